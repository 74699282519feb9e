// gestura studio: the window. The model (gestura/studio) holds the draft, the lexicons and the undo
// history; this file draws panels over it, renders the preview with the shared renderer into an
// offscreen texture shown as an ImGui image, replays --script steps one per frame, autosaves the
// draft and measures itself (--frame-log).
#include "studio_window.hpp"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <atomic>
#include <stop_token>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "gestura/app/error.hpp"
#include "gestura/app/lexicon.hpp"
#include "gestura/app/say.hpp"
#include "gestura/app/sign.hpp"
#include "gestura/app/workspace.hpp"
#include "gestura/core/error.hpp"
#include "gestura/render/camera.hpp"
#include "gestura/render/gl_context.hpp"
#include "gestura/render/occluders.hpp"
#include "gestura/render/png_writer.hpp"
#include "gestura/render/renderer.hpp"
#include "gestura/core/staged_file.hpp"
#include "gestura/render/subject.hpp"
#include "gestura/render/viewer_controls.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/studio/learning.hpp"
#include "gestura/studio/palette.hpp"
#include "gestura/studio/pose_editor.hpp"
#include "gestura/studio/recovery.hpp"
#include "gestura/studio/script.hpp"
#include "gestura/studio/sign_preview.hpp"
#include "gestura/studio/studio_model.hpp"
#include "environment_panel.hpp"

namespace gestura::studio_ui {
namespace {

using namespace gestura::studio;
using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size() - 1) + 0.5))];
}

const char* const kPanels[] = {"Signs", "Sign", "Notation", "Palette", "Preview", "Problems"};

class Studio {
 public:
  Studio(const app::StudioRequest& request, app::StudioSetup setup, const app::RunContext& context)
      : request_(request),
        setup_(std::move(setup)),
        model_(setup_.builtin_files, setup_.user_db),
        recovery_file_(recovery_path(setup_.user_db)),
        window_(request.size.width, request.size.height, "gestura studio"),
        renderer_() {
    if (!request.frame_log.empty()) glfwSwapInterval(0);  // measure the work, not the wait for the display
    workspace_ = context.workspace;
    if (!workspace_) own_workspace_ = std::make_unique<app::Workspace>(), workspace_ = own_workspace_.get();
    const Avatar& avatar = workspace_->avatar(request.avatar);
    rig_ = &workspace_->rig(request.avatar);
    subject_.skeleton = avatar.skeleton;
    subject_.mesh = avatar.mesh;
    animator_.emplace(subject_);
    renderer_.upload(subject_.mesh);
    renderer_.set_occluders(find_occluders(subject_.skeleton, subject_.mesh));
    controls_.emplace(framing_box(subject_.mesh, subject_.skeleton), CameraPreset::Front, 1.0f);
    std::vector<std::string> morph_names;
    for (const MorphTarget& m : subject_.mesh.morphs) morph_names.push_back(m.name);
    pose_editor_.emplace(subject_.skeleton, morph_names);
    pose_model_.resize(subject_.skeleton.size());
    pose_skinning_.resize(subject_.skeleton.size());
    inverse_bind_.resize(subject_.skeleton.size());
    local_to_model(subject_.skeleton, rest_pose(subject_.skeleton), inverse_bind_);
    for (mat4& m : inverse_bind_) m = glm::inverse(m);
    controls_->loop = true;

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // the layout is fixed; nothing to remember in the working directory
    ImGui::StyleColorsDark();
    ImGui::GetStyle().WindowRounding = 0.0f;
    ImGui_ImplGlfw_InitForOpenGL(window_.window(), true);
    ImGui_ImplOpenGL3_Init("#version 330 core");

    try {
      recovered_ = read_recovery(recovery_file_);
      if (recovered_) show_recovery_ = true;
    } catch (const Error& e) {
      message_ = std::string(e.what()) + ": not offered; remove or fix it";
    }
    if (!model_.user_error().empty()) message_ = model_.status();
    try {
      topics_ = load_topics(setup_.builtin_files, default_sentences_file(setup_.builtin_files));
    } catch (const Error& e) {
      message_ = std::string("learning mode has no material: ") + e.what();
    }
    refresh_browse();
    if (!setup_.script.empty()) script_ = setup_.script;
  }

  ~Studio() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }

  int run();

 private:
  // ---- actions (UI and script) ----
  void refresh_browse() { rows_ = model_.browse(filter_); }
  void execute(const ScriptStep& step);
  void import_file(const std::string& path);
  void export_file(const std::string& path);
  void accept_recovery(bool restore);
  void palette_click(sign::Symbol symbol);
  void set_field(const std::string& field, const std::string& value);
  void set_learning(bool on);
  void set_posing(bool on);
  void set_environment(bool on);  // the environment and colour editors (environment_panel.hpp)
  void pose_hand(char side, sign::Symbol handshape);
  void draw_skeleton(const ImVec2& pos, const ImVec2& size);
  void draw_joint(const ImVec2& pos, const ImVec2& size);
  void draw_skeleton_node(int joint, const std::vector<std::vector<int>>& children);
  void select_topic(const std::string& name);
  void play_word(const LessonWord& word, bool reveal);
  void play_sentence(const std::string& text);
  void show_clip(const Clip& clip);
  void draw_learn(const ImVec2& pos, const ImVec2& size);
  void draw_word(const ImVec2& pos, const ImVec2& size);

  // ---- per frame ----
  void update_preview(Clock::time_point now);
  void apply_preview(SignPreview result);
  // A synthesis is running or due (script steps wait for it, so a dump sees the edit's preview).
  void start_export(const std::string& path);
  void finish_export();
  bool preview_busy() const { return (env_ && env_->busy()) || pending_.valid() || export_.valid() || (!learning_ && model_.revision() != requested_revision_); }
  void render_preview();
  void draw_ui();
  void draw_menu();
  void draw_signs(const ImVec2& pos, const ImVec2& size);
  void draw_metadata(const ImVec2& pos, const ImVec2& size);
  void draw_notation(const ImVec2& pos, const ImVec2& size);
  void draw_palette(const ImVec2& pos, const ImVec2& size);
  void draw_preview(const ImVec2& pos, const ImVec2& size);
  void draw_problems(const ImVec2& pos, const ImVec2& size);
  void draw_status(const ImVec2& pos, const ImVec2& size);
  void draw_popups();
  void shortcuts();
  void autosave();
  void write_dump(const std::string& path);
  void screenshot(const std::string& path);
  bool begin_panel(const char* name, const ImVec2& pos, const ImVec2& size);
  float flexion_at(float t, char side);
  const std::string& status() const { return !message_.empty() ? message_ : environment_ ? env_->status() : model_.status(); }
  void say(const std::string& text) { message_ = text; }

  const app::StudioRequest& request_;
  app::StudioSetup setup_;
  StudioModel model_;
  std::string recovery_file_;
  WindowGlContext window_;
  Renderer renderer_;
  app::Workspace* workspace_ = nullptr;
  std::unique_ptr<app::Workspace> own_workspace_;
  const SigningRig* rig_ = nullptr;
  RenderSubject subject_;
  std::optional<Animator> animator_;
  std::optional<ViewerControls> controls_;
  bool framed_for_sign_ = false;

  // browsing
  BrowseFilter filter_;
  std::vector<BrowseRow> rows_;
  // notation editing
  int selected_symbol_ = -1;
  // preview
  SignPreview preview_;
  std::uint64_t requested_revision_ = ~0ull;  // the draft revision last sent to synthesis
  std::uint64_t shown_clip_ = 0;               // counts the clips the preview has shown
  std::future<SignPreview> pending_;
  // export of the performed sign (BVH, glTF, JSON, pictures, video) beside the window
  std::future<std::string> export_;
  std::stop_source export_stop_;
  std::shared_ptr<std::atomic<int>> export_done_ = std::make_shared<std::atomic<int>>(0), export_total_ = std::make_shared<std::atomic<int>>(0);
  bool show_export_sign_ = false;
  int preview_width_ = 0, preview_height_ = 0;  // pixels the preview renders at
  ImVec2 preview_panel_{640, 480};
  bool rendered_ = false;  // what the preview texture shows
  std::uint64_t rendered_clip_ = 0;
  float rendered_time_ = 0.0f;
  mat4 rendered_view_{1.0f}, rendered_projection_{1.0f};
  glm::ivec2 rendered_size_{0, 0};
  int rendered_layout_ = 0;  // 0: one view; 1 + preset: two views, the second from that preset
  std::optional<Clock::time_point> edit_time_;  // an edit not yet shown in the preview
  std::vector<double> latencies_ms_, synthesis_ms_;
  // recovery
  std::optional<SignDraft> recovered_;
  bool show_recovery_ = false;
  std::uint64_t autosaved_revision_ = ~0ull;
  bool wrote_recovery_ = false;
  // popups
  bool show_import_ = false, show_export_ = false, show_help_ = false;
  std::string io_path_;
  // panels
  std::string focus_panel_;
  bool visible_[6] = {true, true, true, true, true, true};
  // script
  std::vector<ScriptStep> script_;
  std::size_t script_next_ = 0;
  int wait_frames_ = 0;
  std::string pending_screenshot_;
  bool quit_ = false;
  bool screenshot_then_quit_ = false;  // --screenshot with a script: taken after the script's last step
  int exit_status_ = 0;
  std::string message_;  // overrides the model's status until the next model action
  // learning mode
  bool learning_ = false;
  std::vector<Topic> topics_;
  int topic_ = 0;
  std::string learn_title_;          // what the preview performs: a word or a sentence
  const LessonWord* learn_word_ = nullptr;
  std::vector<PerformedGloss> learn_glosses_;  // a sentence's signs, as bars on the timeline
  std::optional<Quiz> quiz_;
  bool two_views_ = true;
  // pose mode
  bool posing_ = false;
  std::optional<PoseEditor> pose_editor_;
  int pose_joint_ = -1;
  std::vector<mat4> pose_model_, pose_skinning_, inverse_bind_;
  bool orbited_ = false;  // the learner moved the left view's camera
  CameraPreset second_view_ = CameraPreset::Side;
  std::uint64_t frame_ = 0;
  // environment mode
  bool environment_ = false;
  std::unique_ptr<EnvironmentPanel> env_;
};

// ---------------------------------------------------------------------------------------------
// actions

void Studio::set_field(const std::string& field, const std::string& value) {
  SignDraft d = model_.draft();
  if (field == "gloss") d.gloss = value;
  else if (field == "lang") d.language = value;
  else if (field == "names") d.names = value;
  else if (field == "keywords") d.keywords = value;
  else if (field == "meaning") d.meaning = value;
  else if (field == "source") d.source = value;
  else if (field == "licence") d.licence = value;
  else if (field == "variant") {
    try {
      const int v = std::stoi(value);
      if (v < 1 || v > 1000000) throw std::out_of_range("variant");
      d.variant = v;
    } catch (const std::exception&) {
      say("variant '" + value + "' is not a whole number from 1 to 1000000");
      return;
    }
  } else {
    say("no field '" + field + "' (gloss lang variant names keywords meaning source licence)");
    return;
  }
  message_.clear();
  model_.edit("edit " + field, d, "field:" + field);
  model_.seal();
}

void Studio::palette_click(sign::Symbol symbol) {
  message_.clear();
  const std::string name(sign::symbol_name(symbol));
  const int count = static_cast<int>(name_tokens(model_.draft().names).size());
  if (selected_symbol_ >= 0 && selected_symbol_ < count) {
    model_.replace_symbol(selected_symbol_, name);
  } else {
    if (model_.insert_symbol(count, name)) selected_symbol_ = -1;
  }
}

void Studio::import_file(const std::string& path) {
  app::LexiconImportRequest request;
  request.file = path;
  request.db = setup_.user_db;
  try {
    const app::LexiconChangeResult r = app::run(request);
    say("imported " + std::to_string(r.count) + " signs from " + path + " into " + r.path);
    refresh_browse();
  } catch (const std::exception& e) {
    say("import failed, nothing imported: " + app::classify(e).message + " " + app::classify(e).place.source.to_string());
  }
}

void Studio::export_file(const std::string& path) {
  app::LexiconExportRequest request;
  request.file = path;
  request.db = setup_.user_db;
  try {
    const app::LexiconChangeResult r = app::run(request);
    std::string text = "exported " + std::to_string(r.count) + " signs of " + setup_.user_db + " to " + path;
    if (r.skipped)
      text += "; skipped " + std::to_string(r.skipped) + " not written in SiGML (export .jsonl to keep HamNoSys and clip signs)";
    say(text);
  } catch (const std::exception& e) {
    say(std::string("export failed: ") + e.what());
  }
}

void Studio::accept_recovery(bool restore) {
  if (!recovered_) {
    say("no draft to recover");
    return;
  }
  if (restore) {
    model_.restore_draft(*recovered_);
    say("recovered the unsaved draft of " + (recovered_->gloss.empty() ? std::string("a new sign") : recovered_->gloss) +
        " (save to keep it)");
  } else {
    discard_recovery(recovery_file_);
    say("discarded the unsaved draft");
  }
  recovered_.reset();
  show_recovery_ = false;
}

void Studio::show_clip(const Clip& clip) {
  subject_.clip = clip;
  ++shown_clip_;
  animator_.emplace(subject_);
  controls_->time = 0.0f;
  controls_->playing = true;
  rendered_ = false;
}

void Studio::set_learning(bool on) {
  if (on && posing_) posing_ = false, rendered_ = false;
  if (on == learning_) return;
  learning_ = on;
  rendered_ = false;
  if (!on) {
    // Back to the editor: its preview again (synthesized anew from the draft).
    quiz_.reset();
    subject_.clip.reset();
    animator_.emplace(subject_);
    requested_revision_ = ~0ull;
    say("sign editor");
  } else {
    say(topics_.empty() ? "learning mode: no topics (no built-in lexicon)" : "learning mode: pick a topic, a word or a sentence");
  }
}

void Studio::set_posing(bool on) {
  if (on == posing_) return;
  if (on) set_learning(false);
  posing_ = on;
  rendered_ = false;
  say(on ? "pose editor: pick a joint in the tree or click it in the view" : "sign editor");
}

void Studio::set_environment(bool on) {
  if (on) set_learning(false), set_posing(false);
  if (on && !env_) env_ = std::make_unique<EnvironmentPanel>(workspace_->avatar(request_.avatar), request_.preview_scale);
  if (on != environment_) say(on ? "" : "sign editor");  // the environment editor's own status line shows
  environment_ = on;
  rendered_ = false;
}

void Studio::pose_hand(char side, sign::Symbol handshape) {
  // The handshape as the sign pipeline forms it: a short sign performed, the hand read at its middle.
  SignDraft d;
  d.names = std::string(sign::symbol_name(handshape)) + ",hamextfingeru,hampalml,hamneutralspace";
  const SignPreview p = preview_sign(d, *rig_);
  if (!p.clip) {
    say("cannot form " + std::string(sign::symbol_name(handshape)));
    return;
  }
  RenderSubject hand{subject_.skeleton, Mesh{}, *p.clip};
  Animator animator(hand);
  animator.pose_at(0.5f * (p.sign_start + p.sign_end));
  const auto model = animator.model();
  Pose source = pose_editor_->pose();
  for (std::size_t j = 0; j < hand.skeleton.size(); ++j) {
    const int parent = hand.skeleton.parents[j];
    const mat4 local = parent < 0 ? model[j] : glm::inverse(model[parent]) * model[j];
    const mat3 r(glm::normalize(vec3(local[0])), glm::normalize(vec3(local[1])), glm::normalize(vec3(local[2])));
    source.rotations[j] = glm::normalize(glm::quat_cast(r));
  }
  // The non-dominant hand of a one-handed sign rests: form the left hand by mirroring the right's.
  if (side == 'l') {
    PoseEditor mirrored(subject_.skeleton, {});
    mirrored.set_hand('r', source);
    mirrored.mirror();
    source = mirrored.pose();
  }
  pose_editor_->set_hand(side, source);
  say(std::string(side == 'r' ? "right" : "left") + " hand: " + std::string(short_name(handshape)));
}

void Studio::select_topic(const std::string& name) {
  for (std::size_t i = 0; i < topics_.size(); ++i)
    if (topics_[i].name == name) {
      topic_ = static_cast<int>(i);
      quiz_.reset();
      say("topic " + name + ": " + std::to_string(topics_[i].words.size()) + " words, " +
          std::to_string(topics_[i].sentences.size()) + " sentences");
      return;
    }
  say("no topic '" + name + "'");
}

void Studio::play_word(const LessonWord& word, bool reveal) {
  SignDraft d;
  d.gloss = word.gloss;
  d.language = word.language;
  d.names = word.names;
  const SignPreview p = preview_sign(d, *rig_);
  if (!p.clip) {
    say("cannot perform " + word.gloss + ": " + (p.error ? p.error->message : std::string("no clip")));
    return;
  }
  show_clip(*p.clip);
  learn_glosses_ = {PerformedGloss{word.gloss, word.keywords.empty() ? std::string() : word.keywords.front(), p.sign_start, p.sign_end}};
  learn_word_ = reveal ? &word : nullptr;
  learn_title_ = reveal ? word.gloss : "which sign is this?";
  if (reveal) say("word " + word.gloss);
}

void Studio::play_sentence(const std::string& text) {
  app::SayRequest request;
  request.text = text;
  app::RunContext context;
  context.workspace = workspace_;
  try {
    const app::SayResult r = app::run(request, context);
    show_clip(r.performance.clip);
    learn_glosses_ = r.performance.glosses;
    learn_word_ = nullptr;
    learn_title_ = text;
    std::string glosses;
    for (const PerformedGloss& g : learn_glosses_) glosses += (glosses.empty() ? "" : " ") + g.gloss;
    say("sentence: " + glosses);
  } catch (const std::exception& e) {
    say(std::string("cannot sign '") + text + "': " + e.what());
  }
}

void Studio::start_export(const std::string& path) {
  if (export_.valid()) {
    say("an export is already running");
    return;
  }
  if (notation_error(model_.draft())) {
    say("not exported: the notation does not parse");
    return;
  }
  app::SignRequest request;
  request.source.names = model_.draft().names;
  request.output.output = path;
  request.avatar = request_.avatar;
  try {
    app::validate(request);
  } catch (const std::exception& e) {
    say(std::string("not exported: ") + e.what());
    return;
  }
  export_stop_ = std::stop_source();
  *export_done_ = 0, *export_total_ = 0;
  app::RunContext context;
  context.workspace = workspace_;
  context.stop = export_stop_.get_token();
  context.progress = [done = export_done_, total = export_total_](const app::ProgressUpdate& p) { *done = p.done, *total = p.total; };
  export_ = std::async(std::launch::async, [request, context]() -> std::string {
    try {
      const app::SignResult r = app::run(request, context);
      return "exported " + r.written.path + " (" + std::to_string(r.written.frames) + " frames)";
    } catch (const std::exception& e) {
      const app::ErrorReport report = app::classify(e);
      return report.category == app::ErrorCategory::cancelled ? std::string("export cancelled, nothing written")
                                                               : "export failed, nothing written: " + std::string(e.what());
    }
  });
  say("exporting " + path + " ...");
}

void Studio::finish_export() {
  using namespace std::chrono_literals;
  if (export_.valid() && export_.wait_for(0ms) == std::future_status::ready) say(export_.get());
}

void Studio::execute(const ScriptStep& step) {
  const std::string& a = step.action;
  const auto arg = [&](std::size_t i) { return i < step.args.size() ? step.args[i] : std::string(); };
  const auto number = [&](std::size_t i) {
    try {
      return std::stoi(arg(i));
    } catch (const std::exception&) {
      throw Error(SourceLocation{request_.script, step.line}, "'" + arg(i) + "' is not a number");
    }
  };
  static const char* const keeps_message[] = {"screenshot", "dump", "wait", "time", "play", "pause", "speed", "camera", "views", "panel"};
  if (std::none_of(std::begin(keeps_message), std::end(keeps_message), [&](const char* k) { return a == k; })) message_.clear();
  if (a.rfind("env-", 0) == 0) set_environment(true);
  if (environment_ && env_->execute(step)) return;
  if (a == "open") {
    EntryKey key{arg(0), step.args.size() > 1 ? arg(1) : "ase", step.args.size() > 2 ? number(2) : 1};
    model_.open(key);
    selected_symbol_ = -1;
  } else if (a == "new") {
    model_.new_sign();
  } else if (a == "duplicate") {
    model_.duplicate();
  } else if (a == "save") {
    if (model_.save()) refresh_browse();
  } else if (a == "delete") {
    if (model_.remove()) refresh_browse();
  } else if (a == "undo" && posing_) {
    say(pose_editor_->undo() ? "undid the pose edit" : "nothing to undo");
  } else if (a == "redo" && posing_) {
    say(pose_editor_->redo() ? "redid the pose edit" : "nothing to redo");
  } else if (a == "pose-joint") {
    set_posing(true);
    pose_joint_ = subject_.skeleton.find(arg(0));
    if (pose_joint_ < 0) say("no joint " + arg(0));
  } else if (a == "pose-angles") {
    const vec3 d(std::stof(arg(0)), std::stof(arg(1)), std::stof(arg(2)));
    if (!pose_editor_->set_angles_degrees(pose_joint_, d)) say("joint cannot turn (none selected, or no free axis)");
  } else if (a == "pose-hand") {
    const auto symbol = sign::symbol_from_name(arg(1));
    if (!symbol || sign::symbol_class(*symbol) != sign::SymbolClass::handshape) say("'" + arg(1) + "' is not a handshape");
    else pose_hand(arg(0) == "l" ? 'l' : 'r', *symbol);
  } else if (a == "pose-mirror") {
    pose_editor_->mirror();
  } else if (a == "pose-morph") {
    const auto& names = pose_editor_->morph_names();
    const auto it = std::find(names.begin(), names.end(), arg(0));
    if (it == names.end()) say("no face channel " + arg(0));
    else pose_editor_->set_morph(static_cast<std::size_t>(it - names.begin()), std::stof(arg(1)));
  } else if (a == "undo") {
    model_.undo();
    refresh_browse();
  } else if (a == "redo") {
    model_.redo();
    refresh_browse();
  } else if (a == "set") {
    set_field(arg(0), arg(1));
  } else if (a == "select-symbol") {
    selected_symbol_ = number(0);
  } else if (a == "palette") {
    const auto symbol = sign::symbol_from_name(arg(0));
    if (!symbol) say("no symbol '" + arg(0) + "' in the palette");
    else palette_click(*symbol);
  } else if (a == "replace-symbol") {
    model_.replace_symbol(number(0), arg(1));
  } else if (a == "insert-symbol") {
    model_.insert_symbol(number(0), arg(1));
  } else if (a == "remove-symbol") {
    model_.remove_symbol(number(0));
  } else if (a == "search") {
    filter_.text = arg(0);
    refresh_browse();
  } else if (a == "filter") {
    const std::string value = arg(1) == "-" ? std::string() : arg(1);
    if (arg(0) == "lang") filter_.language = value;
    else if (arg(0) == "handshape") filter_.handshape = value;
    else if (arg(0) == "location") filter_.location = value;
    else say("no filter '" + arg(0) + "' (lang, handshape, location)");
    refresh_browse();
  } else if (a == "panel") {
    focus_panel_ = arg(0);
    for (int i = 0; i < 6; ++i)
      if (focus_panel_ == kPanels[i]) visible_[i] = true;
  } else if (a == "camera") {
    const std::string c = arg(0);
    if (c == "front") controls_->apply(ViewerCommand::Front);
    else if (c == "side") controls_->apply(ViewerCommand::Side);
    else if (c == "three-quarter") controls_->apply(ViewerCommand::ThreeQuarter);
    else if (c == "top") controls_->apply(ViewerCommand::Top);
    else say("no camera '" + c + "'");
  } else if (a == "time") {
    controls_->playing = false;
    controls_->time = std::stof(arg(0));
  } else if (a == "play") {
    controls_->playing = true;
  } else if (a == "pause") {
    controls_->playing = false;
  } else if (a == "wait") {
    wait_frames_ = std::max(0, number(0));
  } else if (a == "import") {
    import_file(arg(0));
  } else if (a == "export") {
    export_file(arg(0));
  } else if (a == "recover") {
    accept_recovery(true);
  } else if (a == "discard-recovery") {
    accept_recovery(false);
  } else if (a == "screenshot") {
    pending_screenshot_ = arg(0);
  } else if (a == "dump") {
    write_dump(arg(0));
  } else if (a == "mode") {
    if (arg(0) == "env") set_environment(true);
    else if (set_environment(false); arg(0) == "learn") set_learning(true);
    else if (arg(0) == "edit") set_learning(false), set_posing(false);
    else if (arg(0) == "pose") set_posing(true);
    else say("no mode '" + arg(0) + "' (learn, edit, pose, env)");
  } else if (a == "topic") {
    set_learning(true);
    select_topic(arg(0));
  } else if (a == "word") {
    set_learning(true);
    const LessonWord* found = nullptr;
    for (const Topic& t : topics_)
      for (const LessonWord& w : t.words)
        if (!found && w.gloss == arg(0)) found = &w;
    if (found) play_word(*found, true);
    else say("no word " + arg(0) + " in the learning material");
  } else if (a == "sentence") {
    set_learning(true);
    play_sentence(arg(0));
  } else if (a == "quiz") {
    set_learning(true);
    if (topics_.empty() || topics_[topic_].words.empty()) say("no words to test");
    else quiz_.emplace(topics_[topic_], static_cast<std::uint32_t>(number(0))), play_word(quiz_->word(), false);
  } else if (a == "answer") {
    if (!quiz_) say("no self-test running");
    else say(quiz_->answer(arg(0)) ? "right: " + quiz_->word().gloss : "no: it was " + quiz_->word().gloss);
  } else if (a == "next-question") {
    if (quiz_) quiz_->next(), play_word(quiz_->word(), false);
  } else if (a == "views") {
    const std::string v = arg(0);
    two_views_ = v != "one";
    if (v == "side") second_view_ = CameraPreset::Side;
    else if (v == "three-quarter") second_view_ = CameraPreset::ThreeQuarter;
    else if (v == "top") second_view_ = CameraPreset::Top;
    rendered_ = false;
  } else if (a == "speed") {
    controls_->speed = std::clamp(std::stof(arg(0)), 0.25f, 2.0f);
  } else if (a == "export-sign") {
    start_export(arg(0));
  } else if (a == "kill") {
    std::fflush(nullptr);
    std::raise(SIGKILL);
  } else if (a == "quit") {
    quit_ = true;
  }
}

// ---------------------------------------------------------------------------------------------
// preview

void Studio::apply_preview(SignPreview result) {
  preview_ = std::move(result);
  synthesis_ms_.push_back(preview_.synthesis_ms);
  // Keep the last good clip on screen while the notation does not parse (the error says why).
  if (preview_.clip) {
    subject_.clip = *preview_.clip;
    animator_.emplace(subject_);
    ++shown_clip_;
    if (!framed_for_sign_) {
      controls_->box = framing_box(subject_.mesh, subject_.skeleton, &*subject_.clip);
      controls_->select(CameraPreset::Front);
      framed_for_sign_ = true;
    }
    if (controls_->time > animator_->duration()) controls_->time = 0.0f;
  }
}

void Studio::update_preview(Clock::time_point now) {
  if (learning_) return;
  using namespace std::chrono_literals;
  if (pending_.valid() && pending_.wait_for(0ms) == std::future_status::ready) apply_preview(pending_.get());
  if (pending_.valid() || model_.revision() == requested_revision_) return;
  // Synthesis runs beside the window, so a long or pathological sign never freezes it; the result
  // replaces the preview when it is ready (edits made meanwhile are synthesized next, the latest only).
  if (!edit_time_) edit_time_ = now;
  requested_revision_ = model_.revision();
  pending_ = std::async(std::launch::async, [draft = model_.draft(), rig = rig_] { return preview_sign(draft, *rig); });
  // A usual sign is ready within a few tens of milliseconds: show it in this very frame.
  if (pending_.wait_for(60ms) == std::future_status::ready) apply_preview(pending_.get());
}

float Studio::flexion_at(float t, char side) {
  if (!preview_.clip) return -1.0f;
  rendered_ = false;  // the animator's pose changes here
  animator_->pose_at(t);
  return finger_flexion_degrees(subject_.skeleton, animator_->model(), side);
}

void Studio::render_preview() {
  const int width = std::max(16, static_cast<int>(preview_panel_.x * request_.preview_scale));
  const int height = std::max(16, static_cast<int>(preview_panel_.y * request_.preview_scale));
  if (width != preview_width_ || height != preview_height_) {
    renderer_.resize(width, height);
    preview_width_ = width, preview_height_ = height;
  }
  const bool two = learning_ && two_views_;
  if (posing_) rendered_ = false;  // the pose changes under the sliders: draw every frame
  const int left_width = two ? width / 2 : width;
  controls_->aspect = static_cast<float>(left_width) / static_cast<float>(height);
  // Two narrow views: the left one is the front framing fitted to its width until the learner orbits.
  Camera left_camera = two && !orbited_ ? preset_camera(CameraPreset::Front, controls_->box, controls_->aspect)
                                        : controls_->camera(controls_->aspect);
  if (two && !orbited_ && !left_camera.orthographic) {
    // The front framing is made for a landscape picture; a half-width view steps back until the
    // shoulders and elbows fit its width as well.
    const float back = std::max(1.0f, 0.9f / controls_->aspect);
    left_camera.eye = left_camera.target + (left_camera.eye - left_camera.target) * back;
    left_camera.view = glm::lookAt(left_camera.eye, left_camera.target, vec3(0.0f, 1.0f, 0.0f));
  }
  const View view{left_camera, {0, 0, left_width, height}};
  std::vector<View> views{view};
  if (two)
    views.push_back(View{preset_camera(second_view_, controls_->box, static_cast<float>(width - left_width) / static_cast<float>(height)),
                         {left_width, 0, width - left_width, height}});
  // A still picture is not drawn again: paused, same camera, same clip, same size.
  const bool same = rendered_ && rendered_clip_ == shown_clip_ && rendered_time_ == controls_->time &&
                    rendered_view_ == view.camera.view && rendered_projection_ == view.camera.projection &&
                    rendered_size_ == glm::ivec2(width, height) && rendered_layout_ == (two ? 1 + static_cast<int>(second_view_) : 0);
  if (same) return;
  rendered_layout_ = two ? 1 + static_cast<int>(second_view_) : 0;
  rendered_ = true, rendered_clip_ = shown_clip_, rendered_time_ = controls_->time;
  rendered_view_ = view.camera.view, rendered_projection_ = view.camera.projection, rendered_size_ = glm::ivec2(width, height);
  if (posing_) {
    pose_editor_->model(pose_model_);
    for (std::size_t j = 0; j < pose_model_.size(); ++j) pose_skinning_[j] = pose_model_[j] * inverse_bind_[j];
    renderer_.render(views, pose_skinning_, pose_editor_->morph_weights());
    return;
  }
  animator_->pose_at(controls_->time);
  renderer_.render(views, animator_->skinning(), animator_->morph_weights());
}

// ---------------------------------------------------------------------------------------------
// panels

bool Studio::begin_panel(const char* name, const ImVec2& pos, const ImVec2& size) {
  ImGui::SetNextWindowPos(pos, ImGuiCond_Always);
  ImGui::SetNextWindowSize(size, ImGuiCond_Always);
  if (focus_panel_ == name) ImGui::SetNextWindowFocus(), focus_panel_.clear();
  return ImGui::Begin(name, nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
}

void Studio::draw_menu() {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("New sign", "Ctrl+N")) model_.new_sign(), message_.clear();
    if (ImGui::MenuItem("Save", "Ctrl+S", false, model_.writable())) {
      message_.clear();
      if (model_.save()) refresh_browse();
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Import SiGML or JSONL...", nullptr, false, model_.writable())) show_import_ = true;
    if (ImGui::MenuItem("Export SiGML or JSONL...")) show_export_ = true;
    if (ImGui::MenuItem("Export the sign as motion or video...", nullptr, false, !export_.valid())) show_export_sign_ = true;
    ImGui::Separator();
    if (ImGui::MenuItem("Quit", "Ctrl+Q")) quit_ = true;
    ImGui::EndMenu();
  }
  if (environment_ && ImGui::BeginMenu("Edit")) {  // the scene's history in the environment editor
    const std::string undo = "Undo " + env_->undo_label(), redo = "Redo " + env_->redo_label();
    if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, !env_->undo_label().empty())) env_->undo(), message_.clear();
    if (ImGui::MenuItem(redo.c_str(), "Ctrl+Y", false, !env_->redo_label().empty())) env_->redo(), message_.clear();
    ImGui::EndMenu();
  }
  if (!environment_ && ImGui::BeginMenu("Edit")) {
    const std::string undo = "Undo " + model_.history().undo_label(), redo = "Redo " + model_.history().redo_label();
    if (ImGui::MenuItem(undo.c_str(), "Ctrl+Z", false, model_.history().can_undo())) model_.undo(), message_.clear(), refresh_browse();
    if (ImGui::MenuItem(redo.c_str(), "Ctrl+Y", false, model_.history().can_redo())) model_.redo(), message_.clear(), refresh_browse();
    ImGui::Separator();
    if (ImGui::MenuItem("Duplicate sign", "Ctrl+D")) model_.duplicate(), message_.clear();
    if (ImGui::MenuItem("Delete sign", nullptr, false, model_.writable() && model_.draft().origin && !model_.draft().from_builtin)) {
      message_.clear();
      if (model_.remove()) refresh_browse();
    }
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Mode")) {
    if (ImGui::MenuItem("Sign editor", "F9", !learning_ && !posing_ && !environment_)) set_environment(false), set_learning(false), set_posing(false);
    if (ImGui::MenuItem("Learning", "F10", learning_)) set_environment(false), set_learning(true);
    if (ImGui::MenuItem("Pose editor", "F11", posing_)) set_environment(false), set_posing(true);
    if (ImGui::MenuItem("Environment editor", "F8", environment_)) set_environment(true);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    ImGui::MenuItem("Two views (learning)", nullptr, &two_views_);
    for (int i = 0; i < 6; ++i) ImGui::MenuItem(kPanels[i], nullptr, &visible_[i]);
    ImGui::Separator();
    if (ImGui::MenuItem("Front", "F1")) controls_->apply(ViewerCommand::Front);
    if (ImGui::MenuItem("Side", "F2")) controls_->apply(ViewerCommand::Side);
    if (ImGui::MenuItem("Three-quarter", "F3")) controls_->apply(ViewerCommand::ThreeQuarter);
    if (ImGui::MenuItem("Top", "F4")) controls_->apply(ViewerCommand::Top);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Keys and mouse")) show_help_ = true;
    ImGui::EndMenu();
  }
  ImGui::EndMainMenuBar();
}

void Studio::draw_signs(const ImVec2& pos, const ImVec2& size) {
  if (begin_panel("Signs", pos, size)) {
    bool changed = ImGui::InputTextWithHint("##search", "search gloss or keyword", &filter_.text);
    ImGui::SetNextItemWidth(70);
    changed |= ImGui::InputTextWithHint("##lang", "lang", &filter_.language);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    if (ImGui::BeginCombo("##hand", filter_.handshape.empty() ? "any handshape" : filter_.handshape.c_str())) {
      if (ImGui::Selectable("any handshape", filter_.handshape.empty())) filter_.handshape.clear(), changed = true;
      for (const sign::Symbol s : palette_groups()[0].symbols)
        if (ImGui::Selectable(std::string(sign::symbol_name(s)).c_str(), filter_.handshape == sign::symbol_name(s)))
          filter_.handshape = std::string(sign::symbol_name(s)), changed = true;
      ImGui::EndCombo();
    }
    ImGui::SetNextItemWidth(-1);
    if (ImGui::BeginCombo("##loc", filter_.location.empty() ? "any location" : filter_.location.c_str())) {
      if (ImGui::Selectable("any location", filter_.location.empty())) filter_.location.clear(), changed = true;
      for (const sign::SymbolInfo& info : sign::symbol_table())
        if (info.symbol_class == sign::SymbolClass::location_site &&
            ImGui::Selectable(std::string(info.name).c_str(), filter_.location == info.name))
          filter_.location = std::string(info.name), changed = true;
      ImGui::EndCombo();
    }
    if (changed) refresh_browse();
    if (ImGui::Button("New")) model_.new_sign(), message_.clear();
    ImGui::SameLine();
    if (ImGui::Button("Duplicate")) model_.duplicate(), message_.clear();
    ImGui::SameLine();
    ImGui::BeginDisabled(!model_.writable() || !model_.draft().origin || model_.draft().from_builtin);
    if (ImGui::Button("Delete")) {
      message_.clear();
      if (model_.remove()) refresh_browse();
    }
    ImGui::EndDisabled();
    ImGui::TextDisabled("%zu signs (grey: built-in, read-only)", rows_.size());
    ImGui::BeginChild("rows");
    const auto& origin = model_.draft().origin;
    for (const BrowseRow& r : rows_) {
      const EntryKey key = key_of(r.entry);
      char label[256];
      std::snprintf(label, sizeof label, "%s  %s%s##%s/%s/%d", r.entry.gloss.c_str(), r.entry.language.c_str(),
                    r.entry.variant > 1 ? (" v" + std::to_string(r.entry.variant)).c_str() : "", r.entry.gloss.c_str(),
                    r.entry.language.c_str(), r.entry.variant);
      if (r.builtin) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.65f, 0.65f, 0.65f, 1.0f));
      if (ImGui::Selectable(label, origin && *origin == key)) model_.open(key), message_.clear(), selected_symbol_ = -1;
      if (r.builtin) ImGui::PopStyleColor();
    }
    ImGui::EndChild();
  }
  ImGui::End();
}

void Studio::draw_metadata(const ImVec2& pos, const ImVec2& size) {
  if (begin_panel("Sign", pos, size)) {
    const SignDraft& d = model_.draft();
    ImGui::Text("%s%s", d.origin ? (d.from_builtin ? "built-in sign (saving writes your copy)" : "stored sign") : "new sign",
                model_.dirty() ? "  - unsaved changes" : "");
    auto field = [&](const char* label, const char* key, std::string value) {
      if (ImGui::InputText(label, &value)) {
        SignDraft next = model_.draft();
        if (std::string_view(key) == "gloss") next.gloss = value;
        else if (std::string_view(key) == "lang") next.language = value;
        else if (std::string_view(key) == "keywords") next.keywords = value;
        else if (std::string_view(key) == "meaning") next.meaning = value;
        else if (std::string_view(key) == "source") next.source = value;
        else next.licence = value;
        message_.clear();
        model_.edit(std::string("edit ") + key, next, std::string("field:") + key);
      }
      if (ImGui::IsItemDeactivatedAfterEdit()) model_.seal();
    };
    field("Gloss", "gloss", d.gloss);
    field("Language", "lang", d.language);
    int variant = d.variant;
    if (ImGui::InputInt("Variant", &variant) && variant >= 1) {
      SignDraft next = model_.draft();
      next.variant = variant;
      model_.edit("edit variant", next);
      model_.seal();
    }
    field("Keywords", "keywords", d.keywords);
    field("Meaning", "meaning", d.meaning);
    field("Source", "source", d.source);
    field("Licence", "licence", d.licence);
    ImGui::BeginDisabled(!model_.writable());
    if (ImGui::Button("Save  (Ctrl+S)")) {
      message_.clear();
      if (model_.save()) refresh_browse();
    }
    ImGui::EndDisabled();
  }
  ImGui::End();
}

void Studio::draw_notation(const ImVec2& pos, const ImVec2& size) {
  if (begin_panel("Notation", pos, size)) {
    const std::vector<std::string> tokens = name_tokens(model_.draft().names);
    const auto error = notation_error(model_.draft());
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    for (int i = 0; i < static_cast<int>(tokens.size()); ++i) {
      std::string label = tokens[i];
      if (label.starts_with("ham")) label.erase(0, 3);
      label += "##sym" + std::to_string(i);
      const bool is_error = error && error->symbol == i;
      bool is_note = false;
      for (const PreviewProblem& p : preview_.problems) is_note |= p.symbol == i;
      if (i > 0) {
        const float w = ImGui::CalcTextSize(label.c_str(), nullptr, true).x + 2 * ImGui::GetStyle().FramePadding.x;
        if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + w < right) ImGui::SameLine();
      }
      int colours = 0;
      if (is_error) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.75f, 0.12f, 0.12f, 1.0f)), ++colours;
      else if (is_note) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.65f, 0.55f, 0.10f, 1.0f)), ++colours;
      else if (i == selected_symbol_) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.20f, 0.45f, 0.80f, 1.0f)), ++colours;
      if (ImGui::Button(label.c_str())) selected_symbol_ = selected_symbol_ == i ? -1 : i;
      if (colours) ImGui::PopStyleColor(colours);
      if (is_error) {
        draw->AddRect(ImGui::GetItemRectMin(), ImGui::GetItemRectMax(), IM_COL32(255, 90, 90, 255), 0.0f, 0, 2.0f);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", error->message.c_str());
      } else if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("symbol %d: %s (click to select; a palette click then replaces it)", i, tokens[i].c_str());
      }
    }
    if (tokens.empty()) ImGui::TextDisabled("no symbols yet: pick a handshape in the palette");
    if (error) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.45f, 1.0f));
      ImGui::TextWrapped("%s%s (a draft: it is not saved until it parses)",
                         error->symbol >= 0 ? ("symbol " + std::to_string(error->symbol) + ": ").c_str() : "",
                         error->message.c_str());
      ImGui::PopStyleColor();
    }
    ImGui::BeginDisabled(selected_symbol_ < 0 || selected_symbol_ >= static_cast<int>(tokens.size()));
    if (ImGui::Button("Remove selected  (Del)")) model_.remove_symbol(selected_symbol_), selected_symbol_ = -1, message_.clear();
    ImGui::EndDisabled();
    ImGui::TextDisabled("symbol names:");
    std::string names = model_.draft().names;
    if (ImGui::InputTextMultiline("##names", &names, ImVec2(-1, ImGui::GetTextLineHeight() * 4))) {
      SignDraft next = model_.draft();
      next.names = names;
      message_.clear();
      model_.edit("edit notation", next, "field:names");
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) model_.seal();
  }
  ImGui::End();
}

void Studio::draw_palette(const ImVec2& pos, const ImVec2& size) {
  if (begin_panel("Palette", pos, size)) {
    const int count = static_cast<int>(name_tokens(model_.draft().names).size());
    ImGui::TextDisabled(selected_symbol_ >= 0 && selected_symbol_ < count ? "click: replace the selected symbol"
                                                                          : "click: append to the notation");
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    for (const PaletteGroup& g : palette_groups()) {
      if (!ImGui::CollapsingHeader(g.title.c_str(), g.title == "Handshape" ? ImGuiTreeNodeFlags_DefaultOpen : 0)) continue;
      ImGui::TextDisabled("%s", g.hint.c_str());
      bool first = true;
      for (const sign::Symbol s : g.symbols) {
        const std::string label(short_name(s));
        const float w = ImGui::CalcTextSize(label.c_str()).x + 2 * ImGui::GetStyle().FramePadding.x;
        if (!first && ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + w < right) ImGui::SameLine();
        first = false;
        if (ImGui::SmallButton(label.c_str())) palette_click(s);
        if (ImGui::IsItemHovered())
          ImGui::SetTooltip("%s  U+%04X", std::string(sign::symbol_name(s)).c_str(),
                            static_cast<unsigned>(sign::symbol_info(s).codepoint));
      }
    }
  }
  ImGui::End();
}

void Studio::draw_preview(const ImVec2& pos, const ImVec2& size) {
  if (begin_panel("Preview", pos, size)) {
    const float bar = ImGui::GetFrameHeightWithSpacing() * 2 + 30;
    ImVec2 avail = ImGui::GetContentRegionAvail();
    avail.y = std::max(32.0f, avail.y - bar);
    preview_panel_ = avail;
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(renderer_.resolved_texture())), avail,
                 ImVec2(0, static_cast<float>(preview_height_) / static_cast<float>(std::max(1, renderer_.height()))),
                 ImVec2(static_cast<float>(preview_width_) / static_cast<float>(std::max(1, renderer_.width())), 0));
    if (posing_ && ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
      // Pick the joint nearest to the click, as the camera projects it.
      const ImVec2 origin = ImGui::GetItemRectMin(), m = ImGui::GetIO().MousePos;
      const Camera camera = controls_->camera(controls_->aspect);
      float best = 400.0f;  // 20 px
      for (std::size_t j = 0; j < pose_model_.size(); ++j) {
        const vec4 clip = camera.projection * camera.view * vec4(vec3(pose_model_[j][3]), 1.0f);
        if (clip.w <= 0.0f) continue;
        const float x = origin.x + (clip.x / clip.w * 0.5f + 0.5f) * avail.x, y = origin.y + (0.5f - clip.y / clip.w * 0.5f) * avail.y;
        const float d = (x - m.x) * (x - m.x) + (y - m.y) * (y - m.y);
        if (d < best) best = d, pose_joint_ = static_cast<int>(j);
      }
    }
    if (ImGui::IsItemHovered()) {
      const ImGuiIO& io = ImGui::GetIO();
      if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) controls_->orbit_drag(io.MouseDelta.x, io.MouseDelta.y), orbited_ = true;
      if (ImGui::IsMouseDragging(ImGuiMouseButton_Right)) controls_->pan_drag(io.MouseDelta.x, io.MouseDelta.y), orbited_ = true;
      if (io.MouseWheel != 0.0f) controls_->zoom(io.MouseWheel), orbited_ = true;
    }
    // The timeline: the clip, the signing part, problem marks and the playhead; click to scrub.
    const float duration = animator_->duration();
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x, height = 22.0f;
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(p0, ImVec2(p0.x + width, p0.y + height), IM_COL32(45, 45, 50, 255));
    if (duration > 0.0f) {
      const auto x_of = [&](float t) { return p0.x + width * std::clamp(t / duration, 0.0f, 1.0f); };
      if (!learning_)
        draw->AddRectFilled(ImVec2(x_of(preview_.sign_start), p0.y + 4), ImVec2(x_of(preview_.sign_end), p0.y + height - 4),
                            IM_COL32(70, 120, 190, 255));
      if (learning_) {
        // One bar per sign of the word or sentence, labelled with its gloss.
        for (const PerformedGloss& g : learn_glosses_) {
          draw->AddRectFilled(ImVec2(x_of(g.start), p0.y + 3), ImVec2(x_of(g.end), p0.y + height - 3), IM_COL32(70, 120, 190, 255));
          if (learn_word_ || learn_glosses_.size() > 1 || !quiz_)
            draw->AddText(ImVec2(x_of(g.start) + 2, p0.y + 4), IM_COL32(255, 255, 255, 255), g.gloss.c_str());
        }
      }
      for (const PreviewProblem& p : preview_.problems)
        if (p.time >= 0.0f && !learning_)
          draw->AddTriangleFilled(ImVec2(x_of(p.time) - 5, p0.y), ImVec2(x_of(p.time) + 5, p0.y), ImVec2(x_of(p.time), p0.y + 9),
                                  IM_COL32(240, 70, 60, 255));
      draw->AddLine(ImVec2(x_of(controls_->time), p0.y), ImVec2(x_of(controls_->time), p0.y + height), IM_COL32(255, 255, 255, 255), 2.0f);
    }
    ImGui::InvisibleButton("timeline", ImVec2(width, height));
    if (ImGui::IsItemActive() && duration > 0.0f) {
      controls_->playing = false;
      controls_->time = std::clamp((ImGui::GetIO().MousePos.x - p0.x) / width, 0.0f, 1.0f) * duration;
    }
    if (ImGui::Button(controls_->playing ? "Pause" : "Play")) controls_->apply(ViewerCommand::PlayPause);
    ImGui::SameLine();
    if (ImGui::Button("<")) controls_->apply(ViewerCommand::StepBack);
    ImGui::SameLine();
    if (ImGui::Button(">")) controls_->apply(ViewerCommand::StepForward);
    ImGui::SameLine();
    for (const auto& [label, speed] : {std::pair{"0.25x", 0.25f}, std::pair{"0.5x", 0.5f}, std::pair{"1x", 1.0f}}) {
      if (ImGui::RadioButton(label, controls_->speed == speed)) controls_->speed = speed;
      ImGui::SameLine();
    }
    ImGui::Checkbox("loop", &controls_->loop);
    ImGui::SameLine();
    ImGui::Text("%.2f / %.2f s", duration > 0.0f ? controls_->time : 0.0f, duration);
    ImGui::SameLine();
    if (ImGui::SmallButton("front")) controls_->apply(ViewerCommand::Front);
    ImGui::SameLine();
    if (ImGui::SmallButton("side")) controls_->apply(ViewerCommand::Side);
    ImGui::SameLine();
    if (ImGui::SmallButton("3/4")) controls_->apply(ViewerCommand::ThreeQuarter);
  }
  ImGui::End();
}

void Studio::draw_problems(const ImVec2& pos, const ImVec2& size) {
  if (begin_panel("Problems", pos, size)) {
    ImGui::PushTextWrapPos(0.0f);
    if (preview_.error) {
      ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.45f, 1.0f), "error%s: %s",
                         preview_.error->symbol >= 0 ? (" at symbol " + std::to_string(preview_.error->symbol)).c_str() : "",
                         preview_.error->message.c_str());
      if (subject_.clip) ImGui::TextDisabled("the preview shows the last notation that parsed");
    }
    for (const PreviewProblem& p : preview_.problems) {
      std::string where;
      if (p.symbol >= 0) where += "symbol " + std::to_string(p.symbol) + ": ";
      if (p.time >= 0.0f) where += "at " + std::to_string(p.time).substr(0, 4) + " s: ";
      ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1.0f), "%s%s", where.c_str(), p.text.c_str());
      if (p.time >= 0.0f && ImGui::IsItemClicked()) controls_->playing = false, controls_->time = p.time;
    }
    if (!preview_.error && preview_.problems.empty() && preview_.clip) ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1.0f), "check: no problems");
    if (preview_.clip)
      ImGui::TextDisabled("synthesis %.1f ms; edit to preview %.1f ms (last)", preview_.synthesis_ms,
                          latencies_ms_.empty() ? 0.0 : latencies_ms_.back());
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
}

void Studio::draw_learn(const ImVec2& pos, const ImVec2& size) {
  if (begin_panel("Learn", pos, size)) {
    if (topics_.empty()) ImGui::TextDisabled("no learning material");
    if (!topics_.empty()) {
      ImGui::SetNextItemWidth(-1);
      if (ImGui::BeginCombo("##topic", topics_[topic_].name.c_str())) {
        for (const Topic& t : topics_)
          if (ImGui::Selectable(t.name.c_str(), t.name == topics_[topic_].name)) select_topic(t.name);
        ImGui::EndCombo();
      }
      const Topic& t = topics_[topic_];
      ImGui::TextDisabled("words");
      ImGui::BeginChild("words", ImVec2(0, size.y * 0.42f), true);
      for (const LessonWord& w : t.words)
        if (ImGui::Selectable(w.gloss.c_str(), learn_word_ == &w)) quiz_.reset(), play_word(w, true);
      ImGui::EndChild();
      ImGui::TextDisabled("sentences");
      ImGui::BeginChild("sentences", ImVec2(0, size.y * 0.2f), true);
      for (const std::string& sentence : t.sentences)
        if (ImGui::Selectable(sentence.c_str(), learn_title_ == sentence)) quiz_.reset(), play_sentence(sentence);
      ImGui::EndChild();
      ImGui::Separator();
      ImGui::TextDisabled("self-test");
      if (!quiz_) {
        if (ImGui::Button("Test me on this topic") && !t.words.empty()) {
          quiz_.emplace(t, static_cast<std::uint32_t>(Clock::now().time_since_epoch().count()));
          play_word(quiz_->word(), false);
        }
      } else {
        ImGui::Text("Which sign is this?  (%d of %d right)", quiz_->right(), quiz_->asked() - (quiz_->answered() ? 0 : 1));
        for (const std::string& choice : quiz_->choices()) {
          const bool answered = quiz_->answered().has_value();
          const bool right = choice == quiz_->word().gloss;
          int colours = 0;
          if (answered && right) ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.15f, 0.55f, 0.2f, 1.0f)), ++colours;
          if (ImGui::Button(choice.c_str(), ImVec2(-1, 0)) && !answered)
            say(quiz_->answer(choice) ? "right: " + quiz_->word().gloss : "no: it was " + quiz_->word().gloss);
          if (colours) ImGui::PopStyleColor(colours);
        }
        if (ImGui::Button("Play again")) controls_->time = 0.0f, controls_->playing = true;
        ImGui::SameLine();
        if (ImGui::Button("Next")) quiz_->next(), play_word(quiz_->word(), false);
        ImGui::SameLine();
        if (ImGui::Button("Stop test")) quiz_.reset();
      }
    }
  }
  ImGui::End();
}

void Studio::draw_word(const ImVec2& pos, const ImVec2& size) {
  if (begin_panel("Word", pos, size)) {
    ImGui::PushTextWrapPos(0.0f);
    if (quiz_ && !quiz_->answered()) {
      ImGui::TextDisabled("(hidden until you answer)");
    } else if (learn_word_) {
      ImGui::Text("%s", learn_word_->gloss.c_str());
      if (!learn_word_->keywords.empty()) {
        std::string k;
        for (const std::string& w : learn_word_->keywords) k += (k.empty() ? "" : ", ") + w;
        ImGui::TextDisabled("English: %s", k.c_str());
      }
      if (!learn_word_->description.empty()) ImGui::Text("%s", learn_word_->description.c_str());
      ImGui::Separator();
      ImGui::TextDisabled("notation");
      ImGui::Text("%s", learn_word_->names.c_str());
    } else if (quiz_ && quiz_->answered()) {
      ImGui::Text("%s", quiz_->word().gloss.c_str());
      if (!quiz_->word().description.empty()) ImGui::Text("%s", quiz_->word().description.c_str());
      ImGui::TextDisabled("notation");
      ImGui::Text("%s", quiz_->word().names.c_str());
    } else if (!learn_title_.empty()) {
      ImGui::Text("%s", learn_title_.c_str());
      for (const PerformedGloss& g : learn_glosses_)
        ImGui::BulletText("%s  (%s)  %.2f-%.2f s", g.gloss.c_str(), g.source.c_str(), g.start, g.end);
    } else {
      ImGui::TextDisabled("pick a word or a sentence");
    }
    ImGui::PopTextWrapPos();
    ImGui::Separator();
    ImGui::TextDisabled("watch");
    ImGui::Checkbox("two views", &two_views_);
    ImGui::SameLine();
    for (const auto& [label, preset] : {std::pair{"side", CameraPreset::Side}, std::pair{"3/4", CameraPreset::ThreeQuarter},
                                         std::pair{"top", CameraPreset::Top}}) {
      if (ImGui::RadioButton(label, second_view_ == preset)) second_view_ = preset, rendered_ = false;
      ImGui::SameLine();
    }
    ImGui::NewLine();
    ImGui::TextDisabled("slow motion, frame by frame: 0.25x / 0.5x, < >, R repeats; drag the left view to see any side");
  }
  ImGui::End();
}

void Studio::draw_skeleton_node(int joint, const std::vector<std::vector<int>>& children) {
  const auto& kids = children[static_cast<std::size_t>(joint)];
  ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_DefaultOpen;
  if (kids.empty()) flags |= ImGuiTreeNodeFlags_Leaf;
  if (joint == pose_joint_) flags |= ImGuiTreeNodeFlags_Selected;
  const bool open = ImGui::TreeNodeEx(reinterpret_cast<void*>(static_cast<std::intptr_t>(joint)), flags, "%s",
                                      subject_.skeleton.names[joint].c_str());
  if (ImGui::IsItemClicked()) pose_joint_ = joint;
  if (open) {
    for (const int c : kids) draw_skeleton_node(c, children);
    ImGui::TreePop();
  }
}

void Studio::draw_skeleton(const ImVec2& pos, const ImVec2& size) {
  if (begin_panel("Skeleton", pos, size)) {
    const Skeleton& s = subject_.skeleton;
    std::vector<std::vector<int>> children(s.size());
    for (std::size_t j = 0; j < s.size(); ++j)
      if (s.parents[j] >= 0) children[static_cast<std::size_t>(s.parents[j])].push_back(static_cast<int>(j));
    ImGui::PushStyleVar(ImGuiStyleVar_IndentSpacing, 7.0f);  // a deep tree (root to fingertip) stays readable
    for (std::size_t j = 0; j < s.size(); ++j)
      if (s.parents[j] < 0) draw_skeleton_node(static_cast<int>(j), children);
    ImGui::PopStyleVar();
  }
  ImGui::End();
}

void Studio::draw_joint(const ImVec2& pos, const ImVec2& size) {
  if (begin_panel("Joint", pos, size)) {
    const Skeleton& s = subject_.skeleton;
    if (pose_joint_ >= 0 && pose_joint_ < static_cast<int>(s.size())) {
      const JointDofs& dofs = s.dofs[pose_joint_];
      ImGui::Text("%s  (%d degrees of freedom, order %s)", s.names[pose_joint_].c_str(), dofs.count(),
                  std::string(to_string(dofs.order)).c_str());
      vec3 angles = pose_editor_->angles_degrees(pose_joint_);
      const int bend = pose_editor_->bend_axis(pose_joint_), pivot = pose_editor_->pivot_axis(pose_joint_);
      bool changed = false;
      for (int axis = 0; axis < 3; ++axis) {
        if (!dofs.free(axis)) continue;
        char label[48];
        std::snprintf(label, sizeof label, "%s (%c)", axis == bend ? "bend" : axis == pivot ? "pivot" : "turn", "xyz"[axis]);
        changed |= ImGui::SliderFloat(label, &angles[axis], glm::degrees(dofs.min_angle[axis]), glm::degrees(dofs.max_angle[axis]), "%.1f deg");
        if (ImGui::IsItemDeactivatedAfterEdit()) pose_editor_->seal();
      }
      if (changed) pose_editor_->set_angles_degrees(pose_joint_, angles, "joint:" + std::to_string(pose_joint_));
      if (dofs.count() == 0) ImGui::TextDisabled("this joint does not turn (no free axis)");
    } else {
      ImGui::TextDisabled("pick a joint in the tree or click it in the view");
    }
    ImGui::Separator();
    if (ImGui::Button("Mirror left/right")) pose_editor_->mirror();
    ImGui::SameLine();
    if (ImGui::Button("Reset")) pose_editor_->reset();
    ImGui::SameLine();
    if (ImGui::Button("Undo")) pose_editor_->undo();
    ImGui::SameLine();
    if (ImGui::Button("Redo")) pose_editor_->redo();
    if (ImGui::CollapsingHeader("Handshape presets", ImGuiTreeNodeFlags_DefaultOpen)) {
      for (const char side : {'r', 'l'}) {
        ImGui::TextDisabled("%s hand", side == 'r' ? "right" : "left");
        const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
        bool first = true;
        for (const sign::Symbol h : palette_groups()[0].symbols) {
          const std::string label = std::string(short_name(h)) + "##" + side;
          const float w = ImGui::CalcTextSize(label.c_str(), nullptr, true).x + 2 * ImGui::GetStyle().FramePadding.x;
          if (!first && ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + w < right) ImGui::SameLine();
          first = false;
          if (ImGui::SmallButton(label.c_str())) pose_hand(side, h);
        }
      }
    }
    if (ImGui::CollapsingHeader("Face channels")) {
      const auto& names = pose_editor_->morph_names();
      for (std::size_t i = 0; i < names.size(); ++i) {
        float w = pose_editor_->morph_weights()[i];
        if (ImGui::SliderFloat(names[i].c_str(), &w, 0.0f, 1.0f)) pose_editor_->set_morph(i, w, "morph:" + names[i]);
        if (ImGui::IsItemDeactivatedAfterEdit()) pose_editor_->seal();
      }
    }
  }
  ImGui::End();
}

void Studio::draw_status(const ImVec2& pos, const ImVec2& size) {
  ImGui::SetNextWindowPos(pos, ImGuiCond_Always);
  ImGui::SetNextWindowSize(size, ImGuiCond_Always);
  ImGui::Begin("##status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoBringToFrontOnFocus);
  if (export_.valid()) {
    const int total = *export_total_, done = *export_done_;
    ImGui::ProgressBar(total > 0 ? static_cast<float>(done) / static_cast<float>(total) : 0.0f, ImVec2(160, 0));
    ImGui::SameLine();
    if (ImGui::SmallButton("Cancel export")) export_stop_.request_stop();
    ImGui::SameLine();
  }
  ImGui::Text("%s", status().c_str());
  ImGui::SameLine(std::max(ImGui::GetCursorPosX() + 20.0f, size.x - 330.0f));
  ImGui::TextDisabled("%s%s | %s", model_.writable() ? "" : "READ-ONLY ", std::filesystem::path(setup_.user_db).filename().c_str(),
                      model_.dirty() ? "unsaved (autosaved draft)" : "saved");
  ImGui::End();
}

void Studio::draw_popups() {
  if (show_recovery_) ImGui::OpenPopup("Recover draft?");
  if (ImGui::BeginPopupModal("Recover draft?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("The last session ended without saving this draft:");
    if (recovered_) {
      ImGui::BulletText("gloss: %s (%s)", recovered_->gloss.empty() ? "(none)" : recovered_->gloss.c_str(), recovered_->language.c_str());
      ImGui::BulletText("notation: %s", recovered_->names.c_str());
    }
    if (ImGui::Button("Restore")) accept_recovery(true);
    ImGui::SameLine();
    if (ImGui::Button("Discard")) accept_recovery(false);
    if (!show_recovery_) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  for (auto [flag, title, verb] : {std::tuple{&show_import_, "Import", "Import"}, std::tuple{&show_export_, "Export", "Export"}}) {
    if (*flag) ImGui::OpenPopup(title), *flag = false;
    if (ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
      ImGui::Text("%s a .sigml or .jsonl file %s your lexicon (%s)", verb, verb[0] == 'I' ? "into" : "from", setup_.user_db.c_str());
      ImGui::InputText("file", &io_path_);
      if (ImGui::Button(verb)) {
        verb[0] == 'I' ? import_file(io_path_) : export_file(io_path_);
        ImGui::CloseCurrentPopup();
      }
      ImGui::SameLine();
      if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
      ImGui::EndPopup();
    }
  }
  if (show_export_sign_) ImGui::OpenPopup("Export sign"), show_export_sign_ = false;
  if (ImGui::BeginPopupModal("Export sign", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("The sign as performed: .bvh, .glb, .gltf, .json (joint positions), .png, .gif, .mp4, .webm");
    ImGui::InputText("file", &io_path_);
    if (ImGui::Button("Export")) start_export(io_path_), ImGui::CloseCurrentPopup();
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  if (show_help_) ImGui::OpenPopup("Keys"), show_help_ = false;
  if (ImGui::BeginPopupModal("Keys", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("Ctrl+N new   Ctrl+S save   Ctrl+Z undo   Ctrl+Y / Ctrl+Shift+Z redo   Ctrl+D duplicate   Ctrl+Q quit");
    ImGui::Text("Del remove the selected symbol   Space play/pause   , . step a frame   F1..F4 front, side, 3/4, top");
    ImGui::Text("Preview: left drag orbit, right drag pan, wheel zoom; click the timeline to scrub");
    if (ImGui::Button("Close")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
}

void Studio::shortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  const auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (environment_) {
    env_->shortcuts();
    if (io.KeyCtrl && pressed(GLFW_KEY_Q)) quit_ = true;
    if (pressed(GLFW_KEY_F9)) set_environment(false);
    if (pressed(GLFW_KEY_F10)) set_environment(false), set_learning(true);
    if (pressed(GLFW_KEY_F11)) set_environment(false), set_posing(true);
    return;
  }
  if (io.KeyCtrl) {
    if (posing_) {
      if (pressed(GLFW_KEY_Z) && !io.KeyShift) pose_editor_->undo();
      if (pressed(GLFW_KEY_Y) || (pressed(GLFW_KEY_Z) && io.KeyShift)) pose_editor_->redo();
      return;
    }
    if (pressed(GLFW_KEY_Z) && !io.KeyShift) model_.undo(), message_.clear(), refresh_browse();
    if (pressed(GLFW_KEY_Y) || (pressed(GLFW_KEY_Z) && io.KeyShift)) model_.redo(), message_.clear(), refresh_browse();
    if (pressed(GLFW_KEY_S)) {
      message_.clear();
      if (model_.save()) refresh_browse();
    }
    if (pressed(GLFW_KEY_N)) model_.new_sign(), message_.clear();
    if (pressed(GLFW_KEY_D)) model_.duplicate(), message_.clear();
    if (pressed(GLFW_KEY_Q)) quit_ = true;
    return;
  }
  if (io.WantTextInput) return;
  if (pressed(GLFW_KEY_SPACE)) controls_->apply(ViewerCommand::PlayPause);
  if (pressed(GLFW_KEY_COMMA)) controls_->apply(ViewerCommand::StepBack);
  if (pressed(GLFW_KEY_PERIOD)) controls_->apply(ViewerCommand::StepForward);
  if (pressed(GLFW_KEY_F1)) controls_->apply(ViewerCommand::Front);
  if (pressed(GLFW_KEY_F2)) controls_->apply(ViewerCommand::Side);
  if (pressed(GLFW_KEY_F3)) controls_->apply(ViewerCommand::ThreeQuarter);
  if (pressed(GLFW_KEY_F4)) controls_->apply(ViewerCommand::Top);
  if (pressed(GLFW_KEY_F9)) set_learning(false), set_posing(false);
  if (pressed(GLFW_KEY_F11)) set_posing(true);
  if (pressed(GLFW_KEY_F8)) set_environment(true);
  if (pressed(GLFW_KEY_F10)) set_learning(true);
  if (pressed(GLFW_KEY_R) && learning_) controls_->time = 0.0f, controls_->playing = true;
  if (pressed(GLFW_KEY_DELETE) && selected_symbol_ >= 0) model_.remove_symbol(selected_symbol_), selected_symbol_ = -1;
}

void Studio::draw_ui() {
  draw_menu();
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float top = vp->WorkPos.y, status_h = ImGui::GetFrameHeight() + 8.0f;
  const float w = vp->WorkSize.x, h = vp->WorkSize.y - status_h;
  const float left = std::round(w * 0.2f), right = std::round(w * 0.3f), centre = w - left - right;
  const float problems_h = std::round(h * 0.2f), meta_h = std::round(h * 0.36f), notation_h = std::round(h * 0.26f);
  if (environment_) {
    env_->draw({0, top}, {w, h});
    draw_status({0, top + h}, {w, status_h});
    draw_popups();
    shortcuts();
    return;
  }
  if (posing_) {
    draw_skeleton({0, top}, {left, h});
    draw_preview({left, top}, {centre, h});
    draw_joint({left + centre, top}, {right, h});
    draw_status({0, top + h}, {w, status_h});
    draw_popups();
    shortcuts();
    return;
  }
  if (learning_) {
    draw_learn({0, top}, {left, h});
    draw_preview({left, top}, {centre, h});
    draw_word({left + centre, top}, {right, h});
    draw_status({0, top + h}, {w, status_h});
    draw_popups();
    shortcuts();
    return;
  }
  if (visible_[0]) draw_signs({0, top}, {left, h});
  if (visible_[1]) draw_metadata({left + centre, top}, {right, meta_h});
  if (visible_[2]) draw_notation({left + centre, top + meta_h}, {right, notation_h});
  if (visible_[3]) draw_palette({left + centre, top + meta_h + notation_h}, {right, h - meta_h - notation_h});
  if (visible_[4]) draw_preview({left, top}, {centre, h - problems_h});
  if (visible_[5]) draw_problems({left, top + h - problems_h}, {centre, problems_h});
  draw_status({0, top + h}, {w, status_h});
  draw_popups();
  shortcuts();
}

// ---------------------------------------------------------------------------------------------
// files

void Studio::autosave() {
  if (show_recovery_) return;  // the old draft waits for the user's answer
  if (model_.dirty()) {
    if (model_.revision() == autosaved_revision_) return;
    try {
      write_recovery(recovery_file_, model_.draft());
      autosaved_revision_ = model_.revision();
      wrote_recovery_ = true;
    } catch (const Error& e) {
      say(std::string("autosave failed: ") + e.what());
    }
  } else if (wrote_recovery_) {
    discard_recovery(recovery_file_);
    wrote_recovery_ = false;
    autosaved_revision_ = ~0ull;
  }
}

void Studio::write_dump(const std::string& path) {
  nlohmann::json j;
  j["draft"] = to_json(model_.draft());
  const auto error = notation_error(model_.draft());
  j["notation_error"] = error ? nlohmann::json{{"symbol", error->symbol}, {"message", error->message}} : nlohmann::json();
  j["status"] = status();
  j["dirty"] = model_.dirty();
  j["writable"] = model_.writable();
  j["can_undo"] = model_.history().can_undo();
  j["can_redo"] = model_.history().can_redo();
  j["recovery_offered"] = show_recovery_;
  j["selected_symbol"] = selected_symbol_;
  j["frame"] = frame_;
  if (env_) j["environment"] = env_->dump();
  j["browse_count"] = rows_.size();
  // The user lexicon's row for the draft's key as stored now (names), null when there is none.
  j["db_names"] = nullptr;
  if (const SignDraft& d = model_.draft(); !d.gloss.empty()) {
    if (const auto row = model_.find(EntryKey{d.gloss, d.language, d.variant}); row && !row->builtin) {
      try {
        j["db_names"] = draft_from_entry(row->entry, false).names;
      } catch (const Error&) {
      }
    }
  }
  nlohmann::json p{{"has_clip", preview_.clip.has_value()}, {"synthesis_ms", preview_.synthesis_ms}};
  if (preview_.clip) {
    const float mid = 0.5f * (preview_.sign_start + preview_.sign_end);
    p["duration"] = preview_.clip->duration;
    p["sign_start"] = preview_.sign_start;
    p["sign_end"] = preview_.sign_end;
    p["flexion_right"] = flexion_at(mid, 'r');
    p["flexion_left"] = flexion_at(mid, 'l');
  }
  p["error"] = preview_.error ? nlohmann::json{{"symbol", preview_.error->symbol}, {"message", preview_.error->message}} : nlohmann::json();
  auto& problems = p["problems"] = nlohmann::json::array();
  for (const PreviewProblem& pr : preview_.problems) problems.push_back({{"text", pr.text}, {"symbol", pr.symbol}, {"time", pr.time}});
  j["preview"] = p;
  nlohmann::json learn{{"active", learning_}, {"title", learn_title_}, {"two_views", two_views_}};
  learn["topic"] = topics_.empty() ? std::string() : topics_[topic_].name;
  learn["topics"] = topics_.size();
  learn["duration"] = animator_->duration();
  auto& glosses = learn["glosses"] = nlohmann::json::array();
  for (const PerformedGloss& g : learn_glosses_) glosses.push_back({{"gloss", g.gloss}, {"start", g.start}, {"end", g.end}});
  if (quiz_) {
    learn["quiz"] = {{"asked", quiz_->asked()}, {"right", quiz_->right()}, {"choices", quiz_->choices()},
                     {"answered", quiz_->answered() ? nlohmann::json(*quiz_->answered()) : nlohmann::json()},
                     {"word", quiz_->word().gloss}};
  }
  j["learning"] = learn;
  if (posing_) {
    std::vector<mat4> model(subject_.skeleton.size());
    pose_editor_->model(model);
    nlohmann::json pose{{"joint", pose_joint_ >= 0 ? subject_.skeleton.names[pose_joint_] : std::string()},
                        {"flexion_right", finger_flexion_degrees(subject_.skeleton, model, 'r')},
                        {"flexion_left", finger_flexion_degrees(subject_.skeleton, model, 'l')}};
    if (pose_joint_ >= 0) {
      const vec3 a = pose_editor_->angles_degrees(pose_joint_);
      pose["angles"] = {a.x, a.y, a.z};
    }
    j["pose"] = pose;
  }
  std::ofstream out(path, std::ios::binary);
  out << j.dump(1) << '\n';
  if (!out) say("cannot write " + path);
}

void Studio::screenshot(const std::string& path) {
  int width = 0, height = 0;
  window_.framebuffer_size(width, height);
  Image image;
  renderer_.read_window_pixels(image, width, height);
  try {
    write_png(path, image);
  } catch (const Error& e) {
    say(std::string("screenshot failed: ") + e.what());
  }
}

// ---------------------------------------------------------------------------------------------

int Studio::run() {
  std::vector<double> frame_ms;
  std::FILE* log = nullptr;
  if (!request_.frame_log.empty()) {
    log = std::fopen(request_.frame_log.c_str(), "w");
    if (!log) throw app::AppError(app::ErrorCategory::output, app::Place{"frame_log", {request_.frame_log}}, "cannot write the frame log");
    std::fprintf(log, "frame\tframe_ms\tto_preview_ms\tui_ms\tdraw_ms\tswap_ms\tsynthesis_ms\tedit_to_preview_ms\tpreview_w\tpreview_h\n");
  }
  Clock::time_point last = Clock::now();
  while (!window_.should_close() && !quit_) {
    const Clock::time_point start = Clock::now();
    glfwPollEvents();
    // One script step per frame boundary (after its waits).
    if (wait_frames_ > 0) {
      --wait_frames_;
    } else if (script_next_ < script_.size() && !preview_busy()) {
      const ScriptStep& step = script_[script_next_++];
      try {
        execute(step);
      } catch (const Error& e) {
        say("script line " + std::to_string(step.line) + ": " + e.message());
        std::fprintf(stderr, "gestura studio: %s:%d: %s\n", request_.script.c_str(), step.line, e.message().c_str());
        exit_status_ = 1;
      }
    }
    finish_export();
    const std::size_t syntheses = synthesis_ms_.size();
    update_preview(start);
    controls_->advance(static_cast<float>(std::chrono::duration<double>(start - last).count()), animator_->duration());
    last = start;

    int width = 0, height = 0;
    window_.framebuffer_size(width, height);
    if (width <= 0 || height <= 0) continue;
    const bool timing = log != nullptr;  // glFinish between the parts only when measuring them
    if (environment_) env_->render();
    else render_preview();
    if (timing) glFinish();
    const Clock::time_point t_preview = Clock::now();

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const std::uint64_t revision_before_ui = model_.revision();
    draw_ui();
    ImGui::Render();
    const Clock::time_point t_ui = Clock::now();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    if (timing) glFinish();
    const Clock::time_point t_draw = Clock::now();
    if (!pending_screenshot_.empty()) screenshot(pending_screenshot_), pending_screenshot_.clear();
    const bool last_frame = request_.frames > 0 && static_cast<int>(frame_ + 1) >= request_.frames;
    if (last_frame && !request_.screenshot.empty()) screenshot(request_.screenshot);
    window_.swap_buffers();
    const Clock::time_point end = Clock::now();

    double latency = -1.0;
    if (edit_time_ && synthesis_ms_.size() > syntheses) {  // this frame showed the edit
      latency = ms_between(*edit_time_, end);
      latencies_ms_.push_back(latency);
      edit_time_.reset();
    }
    if (model_.revision() != revision_before_ui && !edit_time_) edit_time_ = end;  // an edit in the UI: shown next frame
    autosave();
    const double ms = ms_between(start, end);
    frame_ms.push_back(ms);
    if (log)
      std::fprintf(log, "%llu\t%.2f\t%.2f\t%.2f\t%.2f\t%.2f\t%.2f\t%.2f\t%d\t%d\n", static_cast<unsigned long long>(frame_), ms,
                   ms_between(start, t_preview), ms_between(t_preview, t_ui), ms_between(t_ui, t_draw), ms_between(t_draw, end),
                   synthesis_ms_.size() > syntheses ? synthesis_ms_.back() : 0.0, latency, preview_width_, preview_height_);
    ++frame_;
    if (last_frame) break;
    if (script_next_ >= script_.size() && !script_.empty() && request_.frames == 0 && wait_frames_ == 0 &&
        pending_screenshot_.empty() && !preview_busy()) {
      // A script without quit ends the run when it is done (with --screenshot: after one more frame, taken then).
      if (request_.screenshot.empty() || screenshot_then_quit_) break;
      pending_screenshot_ = request_.screenshot;
      screenshot_then_quit_ = true;
    }
  }
  if (log) std::fclose(log);
  if (!request_.frame_log.empty() && !frame_ms.empty()) {
    std::vector<double> steady(frame_ms.begin() + std::min<std::size_t>(frame_ms.size() - 1, 5), frame_ms.end());
    std::fprintf(stderr,
                 "gestura studio: %zu frames at %dx%d (preview %dx%d): frame time median %.1f ms, p95 %.1f ms, max %.1f ms\n",
                 frame_ms.size(), request_.size.width, request_.size.height, preview_width_, preview_height_,
                 percentile(steady, 0.5), percentile(steady, 0.95), percentile(steady, 1.0));
    if (!latencies_ms_.empty())
      std::fprintf(stderr, "gestura studio: %zu edits: edit to preview median %.1f ms, max %.1f ms; synthesis median %.1f ms\n",
                   latencies_ms_.size(), percentile(latencies_ms_, 0.5), percentile(latencies_ms_, 1.0),
                   percentile(synthesis_ms_, 0.5));
  }
  // A clean draft leaves no recovery file; an unsaved one keeps it, to be offered next time.
  if (!model_.dirty() && wrote_recovery_) discard_recovery(recovery_file_);
  return exit_status_;
}

}  // namespace

int run_studio(const app::StudioRequest& request, const app::RunContext& context) {
  app::StudioSetup setup = app::run(request, context);
  Studio studio(request, std::move(setup), context);
  return studio.run();
}

}  // namespace gestura::studio_ui
