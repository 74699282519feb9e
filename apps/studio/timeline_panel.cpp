#include "timeline_panel.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace gestura::studio_ui {
namespace {

using studio::KeyInterpolation;
using studio::Timeline;

constexpr float kLabelWidth = 110.0f;
constexpr ImU32 kKey = IM_COL32(230, 200, 80, 255), kKeySelected = IM_COL32(255, 120, 60, 255);

// Seconds ↔ pixels over the visible window of the tracks.
struct TimeAxis {
  float x0 = 0, width = 1, first = 0, seconds = 1;
  float x(float t) const { return x0 + (t - first) / seconds * width; }
  float t(float px) const { return first + (px - x0) / width * seconds; }
};

TimeAxis axis_for(const TimelineView& view, float duration, float x0, float width) {
  const float seconds = std::max(0.1f, duration * 1.05f / std::max(1.0f, view.zoom));
  return TimeAxis{x0, std::max(1.0f, width), std::clamp(view.scroll, 0.0f, std::max(0.0f, duration * 1.05f - seconds)), seconds};
}

void diamond(ImDrawList* d, ImVec2 c, float r, ImU32 col) {
  d->AddQuadFilled(ImVec2(c.x, c.y - r), ImVec2(c.x + r, c.y), ImVec2(c.x, c.y + r), ImVec2(c.x - r, c.y), col);
}

void ruler(ImDrawList* d, const TimeAxis& ax, ImVec2 p, float h, float duration) {
  d->AddRectFilled(p, ImVec2(ax.x0 + ax.width, p.y + h), IM_COL32(38, 38, 44, 255));
  const float step = ax.seconds > 12 ? 2.0f : ax.seconds > 5 ? 1.0f : ax.seconds > 2 ? 0.5f : 0.1f;
  for (float t = std::ceil(ax.first / step) * step; t <= ax.first + ax.seconds; t += step) {
    const float x = ax.x(t);
    d->AddLine(ImVec2(x, p.y + h * 0.55f), ImVec2(x, p.y + h), IM_COL32(140, 140, 150, 255));
    char label[16];
    std::snprintf(label, sizeof label, "%.1f", t);
    d->AddText(ImVec2(x + 2, p.y), IM_COL32(170, 170, 180, 255), label);
  }
  d->AddLine(ImVec2(ax.x(duration), p.y), ImVec2(ax.x(duration), p.y + h), IM_COL32(200, 80, 80, 255));
}

// A stick figure of the pose at time t in a box, seen from the front (x right, y up).
void thumbnail(ImDrawList* d, const Timeline& timeline, float t, ImVec2 p, float size, bool current) {
  const Skeleton& s = timeline.skeleton();
  Pose pose;
  pose.resize(s.size());
  std::vector<float> morphs(timeline.morph_names().size());
  timeline.sample(t, pose, morphs);
  std::vector<mat4> model(s.size());
  local_to_model(s, pose, model);
  d->AddRectFilled(p, ImVec2(p.x + size, p.y + size), current ? IM_COL32(60, 70, 95, 255) : IM_COL32(48, 48, 56, 255));
  // The upper body fills the thumbnail (signs happen there): 1.0 .. 1.85 m high, ±0.45 m wide.
  const auto at = [&](std::size_t j) {
    const vec3 q(model[j][3]);
    return ImVec2(p.x + size * (0.5f + q.x / 0.9f), p.y + size * (1.0f - (q.y - 0.95f) / 0.9f));
  };
  d->PushClipRect(p, ImVec2(p.x + size, p.y + size), true);
  for (std::size_t j = 0; j < s.size(); ++j)
    if (s.parents[j] >= 0) d->AddLine(at(static_cast<std::size_t>(s.parents[j])), at(j), IM_COL32(220, 220, 230, 255), 1.2f);
  d->PopClipRect();
  char label[16];
  std::snprintf(label, sizeof label, "%.2fs", t);
  d->AddText(ImVec2(p.x + 2, p.y + 1), IM_COL32(200, 200, 120, 255), label);
}

}  // namespace

void advance(TimelineView& view, float seconds, float duration) {
  if (!view.playing || duration <= 0.0f) return;
  view.time += seconds * std::clamp(view.speed, 0.25f, 2.0f);
  if (view.time > duration) {
    if (view.loop) view.time = std::fmod(view.time, duration);
    else view.time = duration, view.playing = false;
  }
}

void draw_timeline_channels(Timeline& timeline, TimelineView& view) {
  ImGui::TextDisabled("%s", timeline.has_source() ? timeline.title().c_str() : "no source motion: keys over the rest pose");
  // The motion the keys sit on: English signed as `gestura say` does, or the sign being edited.
  ImGui::SetNextItemWidth(-1);
  if (ImGui::InputTextWithHint("##say", "English to sign, Enter", &view.say_text, ImGuiInputTextFlags_EnterReturnsTrue)) view.say_requested = true;
  if (ImGui::SmallButton("Sign it")) view.say_requested = true;
  ImGui::SameLine();
  if (ImGui::SmallButton("Use the draft")) view.sign_requested = true;
  ImGui::SameLine();
  if (ImGui::SmallButton("No source")) view.clear_requested = true;
  if (ImGui::Button("Key pose")) view.key_requested = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("key the pose editor's pose at the playhead (every joint that differs)");
  ImGui::SameLine();
  if (ImGui::Button("Undo")) timeline.undo();
  ImGui::SameLine();
  if (ImGui::Button("Redo")) timeline.redo();
  ImGui::Separator();
  const auto& channels = timeline.channels();
  ImGui::BeginChild("channels", ImVec2(0, ImGui::GetContentRegionAvail().y * 0.55f), true);
  for (std::size_t c = 0; c < channels.size(); ++c) {
    char label[96];
    std::snprintf(label, sizeof label, "%s  (%zu)", channels[c].name.c_str(), channels[c].keys.size());
    if (ImGui::Selectable(label, view.channel == static_cast<int>(c)))
      view.channel = static_cast<int>(c), view.key = channels[c].keys.empty() ? -1 : 0, view.follow_selection = true;
  }
  if (channels.empty()) ImGui::TextDisabled("no channels yet: pose the avatar and press Key pose");
  ImGui::EndChild();
  if (view.channel < 0 || view.channel >= static_cast<int>(channels.size())) return;
  const auto& keys = channels[static_cast<std::size_t>(view.channel)].keys;
  if (view.key < 0 || view.key >= static_cast<int>(keys.size())) return;
  const studio::TimelineKey k = keys[static_cast<std::size_t>(view.key)];
  ImGui::Text("key %d of %s", view.key + 1, channels[static_cast<std::size_t>(view.channel)].name.c_str());
  const std::string merge = "key:" + std::to_string(view.channel) + ":" + std::to_string(view.key);
  float time = k.time, value = k.value;
  if (ImGui::DragFloat("time", &time, 0.01f, 0.0f, 3600.0f, "%.3f s")) timeline.move_key(view.channel, view.key, time, merge + ":t");
  if (ImGui::IsItemDeactivatedAfterEdit()) timeline.seal();
  if (ImGui::DragFloat("value", &value, 0.1f)) timeline.set_key_value(view.channel, view.key, value, merge + ":v");
  if (ImGui::IsItemDeactivatedAfterEdit()) timeline.seal();
  int kind = static_cast<int>(k.interpolation);
  const char* kinds[] = {"step", "linear", "Catmull-Rom", "Kochanek-Bartels"};
  Tcb tcb = k.tcb;
  bool changed = ImGui::Combo("interpolation", &kind, kinds, 4);
  if (kind == static_cast<int>(KeyInterpolation::KochanekBartels)) {
    changed |= ImGui::SliderFloat("tension", &tcb.tension, -1.0f, 1.0f);
    if (ImGui::IsItemDeactivatedAfterEdit()) timeline.seal();
    changed |= ImGui::SliderFloat("continuity", &tcb.continuity, -1.0f, 1.0f);
    if (ImGui::IsItemDeactivatedAfterEdit()) timeline.seal();
    changed |= ImGui::SliderFloat("bias", &tcb.bias, -1.0f, 1.0f);
    if (ImGui::IsItemDeactivatedAfterEdit()) timeline.seal();
  }
  if (changed) timeline.set_interpolation(view.channel, view.key, static_cast<KeyInterpolation>(kind), tcb, merge + ":i");
  if (ImGui::Button("Delete key")) {
    timeline.remove_key(view.channel, view.key);
    view.key = -1;
  }
}

void draw_timeline_tracks(Timeline& timeline, TimelineView& view) {
  const float duration = timeline.duration();
  // Transport.
  if (ImGui::Button(view.playing ? "Pause" : "Play")) view.playing = !view.playing;
  ImGui::SameLine();
  ImGui::Checkbox("loop", &view.loop);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  ImGui::SliderFloat("speed", &view.speed, 0.25f, 2.0f, "%.2fx");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(110);
  ImGui::SliderFloat("zoom", &view.zoom, 1.0f, 16.0f, "%.1fx");
  ImGui::SameLine();
  ImGui::Text("%.2f / %.2f s", view.time, duration);

  ImDrawList* d = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float full = ImGui::GetContentRegionAvail().x;
  const TimeAxis ax = axis_for(view, duration, origin.x + kLabelWidth, full - kLabelWidth);
  const ImGuiIO& io = ImGui::GetIO();
  const float row = 18.0f;
  float y = origin.y;

  // Ruler: click or drag to scrub; the wheel over the tracks pans when zoomed.
  ruler(d, ax, ImVec2(ax.x0, y), row, duration);
  d->AddText(ImVec2(origin.x, y + 2), IM_COL32(170, 170, 180, 255), "time");
  ImGui::SetCursorScreenPos(ImVec2(ax.x0, y));
  ImGui::InvisibleButton("ruler", ImVec2(ax.width, row));
  if (ImGui::IsItemActive()) view.playing = false, view.time = std::clamp(ax.t(io.MousePos.x), 0.0f, duration);
  y += row + 2;

  // Bars of the utterance: drag a bar's right edge to retime it.
  if (timeline.has_source()) {
    d->AddText(ImVec2(origin.x, y + 2), IM_COL32(170, 170, 180, 255), "signs");
    float at = 0.0f;
    for (std::size_t b = 0; b < timeline.bars().size(); ++b) {
      const studio::TimelineBar& bar = timeline.bars()[b];
      const float x0 = ax.x(at), x1 = ax.x(at + bar.duration);
      const ImU32 col = bar.kind == studio::BarKind::Sign    ? IM_COL32(70, 120, 190, 255)
                        : bar.kind == studio::BarKind::Pause ? IM_COL32(110, 90, 60, 255)
                                                             : IM_COL32(70, 75, 85, 255);
      d->AddRectFilled(ImVec2(x0, y), ImVec2(x1 - 1, y + row), col);
      d->PushClipRect(ImVec2(x0, y), ImVec2(x1, y + row), true);
      d->AddText(ImVec2(x0 + 3, y + 2), IM_COL32(255, 255, 255, 255), bar.kind == studio::BarKind::Sign ? bar.label.c_str() : bar.kind == studio::BarKind::Pause ? "pause" : "~");
      d->PopClipRect();
      ImGui::SetCursorScreenPos(ImVec2(x1 - 4, y));
      ImGui::PushID(static_cast<int>(b));
      ImGui::InvisibleButton("edge", ImVec2(8, row));
      if (ImGui::IsItemHovered() || ImGui::IsItemActive()) {
        ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
        ImGui::SetTooltip("%s %s: %.2f s (drag to retime)", studio::to_string(bar.kind), bar.label.c_str(), bar.duration);
      }
      if (ImGui::IsItemActive() && io.MouseDelta.x != 0.0f)
        timeline.set_bar_duration(static_cast<int>(b), bar.duration + io.MouseDelta.x / ax.width * ax.seconds);
      if (ImGui::IsItemDeactivated()) timeline.seal();
      ImGui::PopID();
      at += bar.duration;
    }
    y += row + 2;
  }

  // One row of keys per channel.
  const auto& channels = timeline.channels();
  // At most kRows rows are shown; the wheel over them scrolls (the selected channel is kept in view).
  constexpr int kRows = 5;
  const int count = static_cast<int>(channels.size());
  if (view.channel >= 0 && view.channel < count && (view.channel < view.first_row || view.channel >= view.first_row + kRows) && view.follow_selection)
    view.first_row = view.channel - kRows / 2;
  view.first_row = std::clamp(view.first_row, 0, std::max(0, count - kRows));
  const float rows_top = y;
  view.drawn_keys.clear();
  for (std::size_t c = static_cast<std::size_t>(view.first_row); c < channels.size() && c < static_cast<std::size_t>(view.first_row + kRows); ++c) {
    const bool selected = view.channel == static_cast<int>(c);
    d->AddRectFilled(ImVec2(ax.x0, y), ImVec2(ax.x0 + ax.width, y + row - 1), selected ? IM_COL32(52, 58, 72, 255) : IM_COL32(40, 40, 46, 255));
    d->PushClipRect(ImVec2(origin.x, y), ImVec2(ax.x0 - 4, y + row), true);
    d->AddText(ImVec2(origin.x, y + 2), IM_COL32(200, 200, 210, 255), channels[c].name.c_str());
    d->PopClipRect();
    for (std::size_t k = 0; k < channels[c].keys.size(); ++k) {
      const float x = ax.x(channels[c].keys[k].time);
      if (x < ax.x0 - 6 || x > ax.x0 + ax.width + 6) continue;
      const bool is = selected && view.key == static_cast<int>(k);
      diamond(d, ImVec2(x, y + row * 0.5f), 5.0f, is ? kKeySelected : kKey);
      view.drawn_keys.push_back({static_cast<int>(c), static_cast<int>(k), x, y + row * 0.5f});
      ImGui::SetCursorScreenPos(ImVec2(x - 6, y));
      ImGui::PushID(static_cast<int>(c * 10000 + k));
      ImGui::InvisibleButton("key", ImVec2(12, row));
      if (ImGui::IsItemActivated()) view.channel = static_cast<int>(c), view.key = static_cast<int>(k);
      if (ImGui::IsItemActive() && io.MouseDelta.x != 0.0f)
        timeline.move_key(static_cast<int>(c), static_cast<int>(k), ax.t(io.MousePos.x), "drag:" + std::to_string(c) + ":" + std::to_string(k));
      if (ImGui::IsItemDeactivated()) timeline.seal();
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s at %.3f s: %.3f (%s)", channels[c].name.c_str(), channels[c].keys[k].time, channels[c].keys[k].value,
                          studio::to_string(channels[c].keys[k].interpolation));
      ImGui::PopID();
    }
    y += row;
  }
  if (channels.empty()) {
    d->AddText(ImVec2(ax.x0 + 4, y + 2), IM_COL32(140, 140, 150, 255), "no keys: pose the avatar (right) and press Key pose");
    y += row;
  } else if (count > kRows) {
    char more[48];
    std::snprintf(more, sizeof more, "%d-%d of %d", view.first_row + 1, std::min(count, view.first_row + kRows), count);
    d->AddText(ImVec2(origin.x, y), IM_COL32(140, 140, 150, 255), more);
    y += row;
  }
  view.follow_selection = false;
  if (ImGui::IsMouseHoveringRect(ImVec2(origin.x, rows_top), ImVec2(origin.x + full, y)) && io.MouseWheel != 0.0f)
    view.first_row -= io.MouseWheel > 0 ? 1 : -1;
  y += 4;

  // The curve of the selected channel: drag a key up or down to change its value.
  const float curve_h = 90.0f;
  d->AddRectFilled(ImVec2(ax.x0, y), ImVec2(ax.x0 + ax.width, y + curve_h), IM_COL32(30, 30, 36, 255));
  d->AddText(ImVec2(origin.x, y + 2), IM_COL32(170, 170, 180, 255), "curve");
  if (view.channel >= 0 && view.channel < static_cast<int>(channels.size()) && !channels[static_cast<std::size_t>(view.channel)].keys.empty()) {
    const auto& keys = channels[static_cast<std::size_t>(view.channel)].keys;
    float lo = keys[0].value, hi = keys[0].value;
    for (float px = 0; px <= ax.width; px += 3) {
      const float v = studio::evaluate(keys, ax.t(ax.x0 + px));
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
    const float pad = std::max(0.05f, (hi - lo) * 0.12f);
    lo -= pad, hi += pad;
    const auto vy = [&](float v) { return y + curve_h - (v - lo) / (hi - lo) * curve_h; };
    char range[48];
    std::snprintf(range, sizeof range, "%.1f .. %.1f", lo + pad, hi - pad);
    d->AddText(ImVec2(origin.x, y + 18), IM_COL32(140, 140, 150, 255), range);
    std::vector<ImVec2> points;
    for (float px = 0; px <= ax.width; px += 2) points.push_back(ImVec2(ax.x0 + px, vy(studio::evaluate(keys, ax.t(ax.x0 + px)))));
    d->AddPolyline(points.data(), static_cast<int>(points.size()), IM_COL32(120, 200, 255, 255), 0, 1.5f);
    for (std::size_t k = 0; k < keys.size(); ++k) {
      const ImVec2 c(ax.x(keys[k].time), vy(keys[k].value));
      if (c.x < ax.x0 - 6 || c.x > ax.x0 + ax.width + 6) continue;
      d->AddCircleFilled(c, 4.5f, view.key == static_cast<int>(k) ? kKeySelected : kKey);
      ImGui::SetCursorScreenPos(ImVec2(c.x - 6, c.y - 6));
      ImGui::PushID(static_cast<int>(k) + 500000);
      ImGui::InvisibleButton("point", ImVec2(12, 12));
      if (ImGui::IsItemActivated()) view.key = static_cast<int>(k);
      if (ImGui::IsItemActive() && io.MouseDelta.y != 0.0f)
        timeline.set_key_value(view.channel, static_cast<int>(k), keys[k].value - io.MouseDelta.y / curve_h * (hi - lo),
                               "curve:" + std::to_string(view.channel) + ":" + std::to_string(k));
      if (ImGui::IsItemDeactivated()) timeline.seal();
      ImGui::PopID();
    }
  } else {
    d->AddText(ImVec2(ax.x0 + 4, y + 4), IM_COL32(140, 140, 150, 255), "select a channel to see its curve");
  }
  // Playhead over ruler, bars, rows and curve.
  const float head = ax.x(view.time);
  if (head >= ax.x0 && head <= ax.x0 + ax.width) d->AddLine(ImVec2(head, origin.y), ImVec2(head, y + curve_h), IM_COL32(255, 255, 255, 220), 2.0f);
  y += curve_h + 6;

  // The pan-zoom film strip (ALIAS §4.2): the pose at every key time; click one to go there.
  ImGui::SetCursorScreenPos(ImVec2(origin.x, y));
  ImGui::SetNextItemWidth(110);
  ImGui::SliderFloat("strip zoom", &view.strip_zoom, 0.5f, 3.0f, "%.1fx");
  y = ImGui::GetCursorScreenPos().y;
  const std::vector<float> times = timeline.key_times();
  const float size = std::round(56.0f * view.strip_zoom);
  const float strip_w = full;
  const float total = static_cast<float>(times.size()) * (size + 4);
  view.strip_scroll = std::clamp(view.strip_scroll, 0.0f, std::max(0.0f, total - strip_w));
  d->PushClipRect(ImVec2(origin.x, y), ImVec2(origin.x + strip_w, y + size + 2), true);
  for (std::size_t i = 0; i < times.size(); ++i) {
    const ImVec2 p(origin.x + static_cast<float>(i) * (size + 4) - view.strip_scroll, y);
    if (p.x + size < origin.x || p.x > origin.x + strip_w) continue;
    thumbnail(d, timeline, times[i], p, size, std::abs(times[i] - view.time) < 1e-3f);
  }
  d->PopClipRect();
  if (times.empty()) d->AddText(ImVec2(origin.x + 4, y + 4), IM_COL32(140, 140, 150, 255), "film strip: the poses at the keys appear here");
  ImGui::SetCursorScreenPos(ImVec2(origin.x, y));
  ImGui::InvisibleButton("strip", ImVec2(strip_w, size + 2));
  if (ImGui::IsItemHovered()) {
    if (io.MouseWheel != 0.0f) view.strip_zoom = std::clamp(view.strip_zoom * (io.MouseWheel > 0 ? 1.15f : 1.0f / 1.15f), 0.5f, 3.0f);
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Right)) view.strip_scroll -= io.MouseDelta.x;
  }
  if (ImGui::IsItemClicked()) {
    const int i = static_cast<int>((io.MousePos.x - origin.x + view.strip_scroll) / (size + 4));
    if (i >= 0 && i < static_cast<int>(times.size())) view.time = times[static_cast<std::size_t>(i)], view.playing = false;
  }
}

}  // namespace gestura::studio_ui
