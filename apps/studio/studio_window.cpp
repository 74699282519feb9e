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
#include <cstring>
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
#include "gestura/app/motion_output.hpp"
#include "gestura/compress/compress.hpp"
#include "gestura/sentence/signer.hpp"
#include "gestura/studio/figure_model.hpp"
#include "gestura/studio/learning.hpp"
#include "gestura/studio/limb_drag.hpp"
#include "gestura/studio/palette.hpp"
#include "gestura/studio/pose_editor.hpp"
#include "gestura/studio/recovery.hpp"
#include "gestura/studio/script.hpp"
#include "gestura/studio/sign_preview.hpp"
#include "gestura/studio/studio_model.hpp"
#include "gestura/studio/timeline_clip_sign.hpp"
#include "gestura/studio/timeline_model.hpp"
#include "figure_panel.hpp"
#include "timeline_panel.hpp"
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

// Input events seen by GLFW (counted by callbacks installed before ImGui's, which chains to them):
// a frame is drawn after input, and not while nothing moves and nothing is touched.
std::atomic<unsigned> g_input_events{0};
// Frames drawn after the last input, so ImGui settles (hover, a popup opening, a release).
constexpr int kSettleFrames = 3;

void count_input_events(GLFWwindow* window) {
  glfwSetCursorPosCallback(window, [](GLFWwindow*, double, double) { ++g_input_events; });
  glfwSetMouseButtonCallback(window, [](GLFWwindow*, int, int, int) { ++g_input_events; });
  glfwSetScrollCallback(window, [](GLFWwindow*, double, double) { ++g_input_events; });
  glfwSetKeyCallback(window, [](GLFWwindow*, int, int, int, int) { ++g_input_events; });
  glfwSetCharCallback(window, [](GLFWwindow*, unsigned) { ++g_input_events; });
  glfwSetWindowFocusCallback(window, [](GLFWwindow*, int) { ++g_input_events; });
  glfwSetCursorEnterCallback(window, [](GLFWwindow*, int) { ++g_input_events; });
  glfwSetFramebufferSizeCallback(window, [](GLFWwindow*, int, int) { ++g_input_events; });
  glfwSetWindowRefreshCallback(window, [](GLFWwindow*) { ++g_input_events; });
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
    // While the preview plays it is drawn with one sample per pixel (on a CPU renderer a 4-sample
    // frame costs about twice as much); a still picture is drawn again with 4 samples.
    moving_renderer_.emplace(Look{}, Antialiasing::None);
    moving_renderer_->upload(subject_.mesh);
    moving_renderer_->set_occluders(find_occluders(subject_.skeleton, subject_.mesh));
    controls_.emplace(framing_box(subject_.mesh, subject_.skeleton), CameraPreset::Front, 1.0f);
    std::vector<std::string> morph_names;
    for (const MorphTarget& m : subject_.mesh.morphs) morph_names.push_back(m.name);
    pose_editor_.emplace(subject_.skeleton, morph_names);
    timeline_.emplace(subject_.skeleton, morph_names);
    figure_.emplace(subject_.skeleton);
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
    count_input_events(window_.window());  // before ImGui's callbacks, which call these after their own
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
    if (ui_fbo_) glDeleteFramebuffers(1, &ui_fbo_);
    if (preview_read_fbo_) glDeleteFramebuffers(1, &preview_read_fbo_);
    if (ui_texture_) glDeleteTextures(1, &ui_texture_);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }

  int run();

 private:
  // Whether this frame must be drawn: input came, something plays or is computed, a script runs.
  bool needs_frame();
  std::optional<Clock::time_point> wait_file_since_;  // the script's wait-file began
  unsigned seen_events_ = 0;
  int settle_frames_ = kSettleFrames;
  std::uint64_t idle_waits_ = 0;  // waits for input instead of a frame (the frame log counts them)
  // The drawn UI kept in a texture: while only the preview plays (no input, no script step, no new
  // synthesis) a frame copies it and the new preview picture into the window instead of building and
  // drawing the whole UI again (Dear ImGui's draw of the window costs llvmpipe more than the preview).
  // The UI itself (playhead, time) is drawn again at least every kUiRefresh.
  static constexpr std::chrono::milliseconds kUiRefresh{250};
  // `refreshing`: the same conditions, but the kUiRefresh is due (only the strip under the preview
  // picture is drawn again then: draw_ui_strip).
  bool reuse_ui(Clock::time_point now, bool stepped, int width, int height, bool refreshing = false) const;
  void compose_cached_ui(int width, int height, bool with_preview);
  // The periodic refresh while only the preview plays: the UI is built as usual, but only the strip
  // under the preview picture (playhead, time, the transport) is drawn again into the kept UI, as
  // nothing else can have changed without input, a script step or a synthesis landing. On llvmpipe
  // a draw of the whole 1280x800 window costs as much as the preview itself.
  // Returns when the UI was built (before its draw).
  Clock::time_point draw_ui_strip(int width, int height);
  std::uint64_t strip_ui_frames_ = 0;
  bool full_ui_due_ = false;  // the strip found the layout moved: the next frame draws the whole UI
  ImVec2 preview_panel_min_{}, preview_panel_max_{};  // the preview panel's window, from the last full UI
  unsigned ui_fbo_ = 0, ui_texture_ = 0, preview_read_fbo_ = 0;
  glm::ivec2 ui_size_{0, 0};
  bool preview_in_ui_ = false;  // the last full UI showed the preview picture at preview_rect_
  ImVec2 preview_rect_min_{}, preview_rect_max_{};
  Clock::time_point last_full_ui_{};
  std::uint64_t reused_ui_frames_ = 0;

  // ---- actions (UI and script) ----
  void refresh_browse() { rows_ = model_.browse(filter_); }
  void execute(const ScriptStep& step);
  void import_file(const std::string& path);
  void export_file(const std::string& path);
  void accept_recovery(bool restore);
  void palette_click(sign::Symbol symbol);
  void draw_nonmanuals();  // the non-manual tiers of the draft (a palette group)
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
  // A clip sign from the dictionary or the learning mode: its recorded motion played in the preview.
  bool play_clip_sign(const SignEntry& entry, bool reveal);
  // Opens a row of the dictionary: a notated sign as the draft, a clip sign played.
  void open_row(const EntryKey& key);
  // The learning mode's topic of the user's own signs, read again from the lexicon.
  void refresh_user_topic();
  void draw_learn(const ImVec2& pos, const ImVec2& size);
  void draw_word(const ImVec2& pos, const ImVec2& size);
  // timeline and figure modes, IK drag (the part of the file after "timeline and figure")
  void set_timeline_mode(bool on);
  void set_figure_mode(bool on);
  bool execute_timeline_or_figure(const ScriptStep& step);
  void timeline_source_from_say(const std::string& text);
  void timeline_source_from_sign();
  void key_pose_now(float time);
  void sync_timeline_pose();
  void start_timeline_export(const std::string& path);
  void save_clip_sign(const std::string& gloss, const std::string& language);
  void figure_skinning(std::vector<mat4>& model, std::vector<mat4>& skinning) const;
  bool ik_drag_to(int joint, const vec3& target, const std::string& merge_key);
  void pick_limb(float fx, float fy, const vec2& size);
  void draw_preview_overlay(const ImVec2& origin, const ImVec2& size);
  void draw_timeline_ui(float top, float w, float h, float status_h);
  void draw_figure_ui(float top, float w, float h, float status_h);
  nlohmann::json dump_timeline_and_figure();
  bool figure_or_timeline() const { return timeline_mode_ || figure_mode_; }

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
  Renderer renderer_;                       // still pictures (4x MSAA)
  std::optional<Renderer> moving_renderer_;  // while playing (one sample)
  Renderer* shown_renderer_ = &renderer_;    // the one whose picture the preview shows
  bool rendered_moving_ = false;
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
  bool open_nonmanuals_ = false;  // the palette's non-manual group is opened (by the script's nonmanual)
  int scroll_to_nonmanuals_ = 0;
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
  std::optional<Signer> learn_signer_;
  std::string shown_clip_sign_;  // the dictionary plays this clip sign (not the draft)  // sentences from the studio's lexicons (the user's clip signs too)
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
  // IK drag of a hand or foot in the view
  bool ik_tool_ = false;
  std::optional<DragLimb> ik_limb_;
  vec3 ik_target_{0.0f};
  float ik_residual_ = -1.0f;
  bool ik_dragging_ = false;
  vec3 ik_plane_point_{0.0f};
  // timeline mode
  bool timeline_mode_ = false;
  std::optional<Timeline> timeline_;
  TimelineView tl_view_;
  float tl_synced_time_ = -1.0f;
  std::uint64_t tl_synced_revision_ = ~0ull, pose_synced_revision_ = 0;
  bool show_export_timeline_ = false, show_clip_sign_ = false;
  // figure mode
  bool figure_mode_ = false;
  std::optional<FigureEditor> figure_;
  FigureView fig_view_;
  FramingBox sign_box_;
  std::uint64_t render_stamp_ = ~0ull;  // what the pose/timeline/figure preview last showed
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
  else if (field == "agreement") {
    try {
      d.agreement = agreement_from_string(value);
    } catch (const std::exception& e) {
      say(e.what());
      return;
    }
  } else if (field == "variant") {
    try {
      const int v = std::stoi(value);
      if (v < 1 || v > 1000000) throw std::out_of_range("variant");
      d.variant = v;
    } catch (const std::exception&) {
      say("variant '" + value + "' is not a whole number from 1 to 1000000");
      return;
    }
  } else {
    say("no field '" + field + "' (gloss lang variant names keywords meaning source licence agreement)");
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
  // SiGML does not name its sign language: its signs are taken to be in the draft's.
  request.lang = model_.draft().language.empty() ? "ase" : model_.draft().language;
  // Signs that cannot be stored (notation that does not parse, a missing field) are skipped and
  // reported with their line; the good ones are stored in one transaction.
  request.skip_bad = true;
  try {
    const app::LexiconChangeResult r = app::run(request);
    std::string text = "imported " + std::to_string(r.count) + " signs from " + path + " into " + r.path;
    if (!r.bad_lines.empty()) {
      text += "; skipped " + std::to_string(r.bad_lines.size()) + ":";
      for (std::size_t i = 0; i < r.bad_lines.size() && i < 3; ++i)
        text += " " + r.bad_lines[i].where.to_string() + ": " + r.bad_lines[i].message + (i + 1 < r.bad_lines.size() ? ";" : "");
      if (r.bad_lines.size() > 3) text += " ...";
      for (const app::Notice& n : r.bad_lines) std::fprintf(stderr, "gestura studio: import: %s\n", n.text().c_str());
    }
    say(text);
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
  if (on) set_timeline_mode(false), set_figure_mode(false);
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
    refresh_user_topic();
    say(topics_.empty() ? "learning mode: no topics (no built-in lexicon)" : "learning mode: pick a topic, a word or a sentence");
  }
}

void Studio::refresh_user_topic() {
  // Words are pointed at by the shown word and the self-test: both let go before the topics change.
  learn_word_ = nullptr;
  quiz_.reset();
  const std::string current = topics_.empty() ? std::string() : topics_[static_cast<std::size_t>(topic_)].name;
  std::erase_if(topics_, [](const Topic& t) { return t.name == kUserTopic; });
  const std::vector<SignEntry> mine = model_.user_signs();
  if (Topic t = user_topic(mine); !t.words.empty()) topics_.push_back(std::move(t));
  topic_ = 0;
  for (std::size_t i = 0; i < topics_.size(); ++i)
    if (topics_[i].name == current) topic_ = static_cast<int>(i);
}

bool Studio::play_clip_sign(const SignEntry& entry, bool reveal) {
  try {
    Clip clip = clip_of(entry);
    validate(clip, subject_.skeleton);
    const float duration = clip.duration;
    show_clip(clip);
    learn_glosses_ = {PerformedGloss{entry.gloss, entry.keywords.empty() ? std::string() : entry.keywords.front().word, 0.0f, duration}};
    learn_title_ = reveal ? entry.gloss : "which sign is this?";
    char text[160];
    std::snprintf(text, sizeof text, "clip sign %s: its keyframed motion (%.2f s)", entry.gloss.c_str(), static_cast<double>(duration));
    if (reveal) say(text);
    return true;
  } catch (const std::exception& e) {
    say("cannot play " + entry.gloss + ": " + e.what());
    return false;
  }
}

void Studio::open_row(const EntryKey& key) {
  const std::optional<BrowseRow> row = model_.find(key);
  if (row && row->entry.notation_kind == NotationKind::clip) {
    // Not editable as notation: the dictionary shows it playing, and it is opened in the timeline
    // editor (its editor: F8), as the source motion of one bar, saved back under its gloss.
    if (play_clip_sign(row->entry, true)) {
      learn_word_ = nullptr;
      shown_clip_sign_ = row->entry.gloss;
      rendered_ = false;
      const Clip& clip = *subject_.clip;
      const std::vector<SourceSign> signs{{row->entry.gloss, 0.0f, clip.duration}};
      timeline_->set_source(clip, signs, row->entry.gloss);
      tl_view_.clip_gloss = row->entry.gloss;
      tl_view_.time = 0.0f, tl_synced_time_ = -1.0f;
      say(status() + "; opened in the timeline editor (F8)");
    }
    return;
  }
  shown_clip_sign_.clear();
  model_.open(key);
}

void Studio::set_posing(bool on) {
  if (on) set_timeline_mode(false), set_figure_mode(false);
  if (on == posing_) return;
  if (on) set_learning(false);
  posing_ = on;
  rendered_ = false;
  say(on ? "pose editor: pick a joint in the tree or click it in the view" : "sign editor");
}

void Studio::set_environment(bool on) {
  if (on) set_learning(false), set_posing(false), set_timeline_mode(false), set_figure_mode(false);
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
  if (word.clip_sign) {
    const std::optional<BrowseRow> row = model_.find(EntryKey{word.gloss, word.language, word.variant});
    if (!row) return say("no sign " + word.gloss + " in your lexicon any more");
    if (play_clip_sign(row->entry, reveal)) learn_word_ = reveal ? &word : nullptr;
    return;
  }
  SignDraft d;
  d.gloss = word.gloss;
  d.language = word.language;
  d.names = word.names;
  d.nonmanuals = word.nonmanuals;
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
  try {
    // Signed from the studio's own lexicons, so the user's signs (clip signs too) are used.
    if (!learn_signer_) learn_signer_.emplace(workspace_->avatar(request_.avatar), model_.lexicon());
    const SentencePerformance performance = learn_signer_->say(text);
    show_clip(performance.clip);
    learn_glosses_ = performance.glosses;
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
  static const char* const keeps_message[] = {"screenshot", "dump", "wait", "wait-file", "time", "play", "pause", "speed", "camera", "views", "panel"};
  if (std::none_of(std::begin(keeps_message), std::end(keeps_message), [&](const char* k) { return a == k; })) message_.clear();
  if (a == "wait-file") {
    // The script waits (frames go on) until the file exists: another program — a test moving the
    // real mouse — says it is done by creating it. At most two minutes.
    if (!wait_file_since_) wait_file_since_ = Clock::now();
    if (!std::filesystem::exists(arg(0)) && Clock::now() - *wait_file_since_ < std::chrono::seconds(120)) {
      --script_next_;
      return;
    }
    if (!std::filesystem::exists(arg(0))) say("waited two minutes for " + arg(0) + " in vain");
    wait_file_since_.reset();
    return;
  }
  if (execute_timeline_or_figure(step)) return;
  if (a.rfind("env-", 0) == 0) set_environment(true);
  if (environment_ && env_->execute(step)) return;
  if (a == "open") {
    EntryKey key{arg(0), step.args.size() > 1 ? arg(1) : "ase", step.args.size() > 2 ? number(2) : 1};
    open_row(key);
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
  } else if (a == "nonmanual") {
    const auto tier = tier_from_key(arg(0));
    if (!tier) {
      say("no non-manual tier '" + arg(0) + "' (shoulder body head gaze eyebrows eyelids nose cheeks mouth-gesture mouth-picture extra)");
    } else {
      message_.clear();
      open_nonmanuals_ = true;
      model_.set_nonmanual(*tier, step.args.size() < 2 || arg(1) == "-" ? std::string() : arg(1));
    }
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
    else if (arg(0) == "edit") set_learning(false), set_posing(false), set_timeline_mode(false), set_figure_mode(false);
    else if (arg(0) == "pose") set_posing(true);
    else say("no mode '" + arg(0) + "' (learn, edit, pose, timeline, figure, env)");
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
    shown_clip_sign_.clear();
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
  const bool moving = timeline_mode_ ? tl_view_.playing : controls_->playing && !posing_ && !figure_mode_;
  // A playing preview renders fewer pixels (--playing-scale): the eye follows the motion, not the
  // edges; once it stops, the still picture is drawn again at full size with antialiasing.
  const float scale = request_.preview_scale * (moving ? request_.playing_scale : 1.0f);
  const int width = std::max(16, static_cast<int>(preview_panel_.x * scale));
  const int height = std::max(16, static_cast<int>(preview_panel_.y * scale));
  Renderer& renderer = moving ? *moving_renderer_ : renderer_;
  if (width != renderer.width() || height != renderer.height()) renderer.resize(width, height);
  const bool two = learning_ && two_views_;
  if (posing_ || figure_or_timeline()) {
    // The pose (sliders, IK drag), the timeline's pose at the playhead or the figure: drawn again
    // when one of them changed.
    std::uint32_t time_bits = 0;
    std::memcpy(&time_bits, &tl_synced_time_, sizeof time_bits);
    std::uint64_t stamp = pose_editor_->revision();
    stamp = stamp * 1000003ull + (figure_mode_ ? figure_->revision() + 1 : 0);
    stamp = stamp * 1000003ull + (timeline_mode_ ? tl_synced_revision_ + 1 : 0);
    stamp = stamp * 1000003ull + time_bits;
    stamp = stamp * 31ull + (figure_mode_ ? 2u : timeline_mode_ ? 1u : 0u) + (fig_view_.show_body ? 4u : 0u);
    if (stamp != render_stamp_) rendered_ = false, render_stamp_ = stamp;
  }
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
                    rendered_size_ == glm::ivec2(width, height) && rendered_layout_ == (two ? 1 + static_cast<int>(second_view_) : 0) &&
                    rendered_moving_ == moving;
  if (same) return;
  rendered_moving_ = moving;
  shown_renderer_ = &renderer;
  preview_width_ = width, preview_height_ = height;
  rendered_layout_ = two ? 1 + static_cast<int>(second_view_) : 0;
  rendered_ = true, rendered_clip_ = shown_clip_, rendered_time_ = controls_->time;
  rendered_view_ = view.camera.view, rendered_projection_ = view.camera.projection, rendered_size_ = glm::ivec2(width, height);
  if (figure_mode_) {
    figure_skinning(pose_model_, pose_skinning_);
    const std::vector<float> no_morphs(subject_.mesh.morphs.size(), 0.0f);
    renderer.render(views, pose_skinning_, no_morphs);
    return;
  }
  if (posing_ || timeline_mode_) {
    pose_editor_->model(pose_model_);
    for (std::size_t j = 0; j < pose_model_.size(); ++j) pose_skinning_[j] = pose_model_[j] * inverse_bind_[j];
    renderer.render(views, pose_skinning_, pose_editor_->morph_weights());
    return;
  }
  animator_->pose_at(controls_->time);
  renderer.render(views, animator_->skinning(), animator_->morph_weights());
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
    if (ImGui::MenuItem("Export the timeline (BVH, glTF, .gcl, MP4, WebM)...", nullptr, false, !export_.valid())) show_export_timeline_ = true;
    if (ImGui::MenuItem("Save the timeline as a clip sign...", nullptr, false, model_.writable())) show_clip_sign_ = true;
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
    if (ImGui::MenuItem("Sign editor", "F9", !learning_ && !posing_ && !figure_or_timeline() && !environment_))
      set_environment(false), set_learning(false), set_posing(false), set_timeline_mode(false), set_figure_mode(false);
    if (ImGui::MenuItem("Learning", "F10", learning_)) set_environment(false), set_learning(true);
    if (ImGui::MenuItem("Pose editor", "F11", posing_)) set_environment(false), set_posing(true);
    if (ImGui::MenuItem("Timeline editor", "F8", timeline_mode_)) set_timeline_mode(true);
    if (ImGui::MenuItem("Figure editor", "F7", figure_mode_)) set_figure_mode(true);
    if (ImGui::MenuItem("Environment editor", "F6", environment_)) set_environment(true);
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
      const bool shown = r.entry.notation_kind == NotationKind::clip ? shown_clip_sign_ == r.entry.gloss : origin && *origin == key;
      if (ImGui::Selectable(label, shown)) message_.clear(), open_row(key), selected_symbol_ = -1;
      if (r.entry.notation_kind == NotationKind::clip) ImGui::SameLine(), ImGui::TextDisabled("clip");
      if (r.builtin) ImGui::PopStyleColor();
    }
    ImGui::EndChild();
  }
  ImGui::End();
}

void Studio::draw_metadata(const ImVec2& pos, const ImVec2& size) {
  if (begin_panel("Sign", pos, size)) {
    const SignDraft& d = model_.draft();
    if (!shown_clip_sign_.empty())
      ImGui::TextColored(ImVec4(0.55f, 0.8f, 1.0f, 1.0f), "playing the clip sign %s (keyframed, no notation: the timeline editor, F8, makes them)",
                         shown_clip_sign_.c_str());
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
    // An agreement verb moves from its subject's place to its object's in sentences (docs/grammar.md).
    int agreement = static_cast<int>(d.agreement);
    if (ImGui::Combo("Agreement", &agreement, "none\0forward (subject to object)\0backward (object to subject)\0")) {
      SignDraft next = model_.draft();
      next.agreement = static_cast<Agreement>(agreement);
      message_.clear();
      model_.edit("edit agreement", next);
      model_.seal();
    }
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
    if (!model_.draft().nonmanuals.empty()) {
      std::string line = "non-manual:";
      for (const DraftNonManual& n : model_.draft().nonmanuals) {
        line += "  " + std::string(tier_info(n.tier).key) + " " + n.value;
        if (const auto m = code_meaning(n.tier, n.value); !m.empty()) line += " (" + std::string(m) + ")";
      }
      ImGui::TextColored(ImVec4(0.55f, 0.8f, 1.0f, 1.0f), "%s", line.c_str());
    }
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

void Studio::draw_nonmanuals() {
  if (open_nonmanuals_) ImGui::SetNextItemOpen(true), open_nonmanuals_ = false, scroll_to_nonmanuals_ = 3;
  if (!ImGui::CollapsingHeader("Non-manuals (SiGML tiers)")) return;
  // The group at the top of the palette: for a few frames, as the scroll is bounded by the content
  // size of the frame before (when the group was still closed).
  if (scroll_to_nonmanuals_ > 0) ImGui::SetScrollHereY(0.0f), --scroll_to_nonmanuals_;
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("face, head and body over the whole sign; a sign with any is saved as SiGML");
  ImGui::PopStyleColor();
  const SignDraft& d = model_.draft();
  const float label_w = ImGui::CalcTextSize("Mouth picture (SAMPA)").x + ImGui::GetStyle().ItemSpacing.x;
  for (const NonManualTierInfo& t : nonmanual_tiers()) {
    ImGui::PushID(static_cast<int>(t.tier));
    const std::vector<std::string> values = tier_values(d.nonmanuals, t.tier);
    std::string current;
    for (const std::string& v : values) current += (current.empty() ? "" : " ") + v;
    ImGui::AlignTextToFramePadding();
    if (!values.empty()) ImGui::TextColored(ImVec4(0.55f, 0.8f, 1.0f, 1.0f), "%s", std::string(t.label).c_str());
    else ImGui::TextUnformatted(std::string(t.label).c_str());
    ImGui::SameLine(label_w);
    ImGui::SetNextItemWidth(-1);
    if (!t.codes.empty()) {
      std::string preview = current.empty() ? std::string("-") : current;
      if (values.size() == 1)
        if (const auto m = code_meaning(t.tier, values.front()); !m.empty()) preview += "  " + std::string(m);
      if (ImGui::BeginCombo("##code", preview.c_str())) {
        if (ImGui::Selectable("-  (none)", values.empty())) message_.clear(), model_.set_nonmanual(t.tier, {});
        for (const NonManualCode& c : t.codes) {
          const std::string item = std::string(c.code) + "  " + std::string(c.meaning);
          if (ImGui::Selectable(item.c_str(), values.size() == 1 && values.front() == c.code))
            message_.clear(), model_.set_nonmanual(t.tier, std::string(c.code));
        }
        ImGui::EndCombo();
      }
    } else {
      // Free text (SAMPA for a mouth picture): one undo step per field visit, as the Sign fields.
      std::string text = current;
      if (ImGui::InputText("##text", &text, ImGuiInputTextFlags_CharsNoBlank)) {
        message_.clear();
        model_.set_nonmanual(t.tier, text, std::string("nonmanual:") + std::string(t.key));
      }
      if (ImGui::IsItemDeactivatedAfterEdit()) model_.seal();
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip(t.tier == sign::NonManualTier::mouth_picture ? "the spoken word as SAMPA, e.g. hUs (house)"
                                                                       : "a tier code, as the SiGML producer writes it");
    }
    ImGui::PopID();
  }
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
    draw_nonmanuals();
  }
  ImGui::End();
}

void Studio::draw_preview(const ImVec2& pos, const ImVec2& size) {
  if (begin_panel("Preview", pos, size)) {
    // Room below the picture: the clip's timeline and transport, or one row of camera buttons.
    const float bar = figure_or_timeline() || posing_ ? ImGui::GetFrameHeightWithSpacing() + 4 : ImGui::GetFrameHeightWithSpacing() * 2 + 30;
    ImVec2 avail = ImGui::GetContentRegionAvail();
    avail.y = std::max(32.0f, avail.y - bar);
    preview_panel_ = avail;
    const Renderer& shown = *shown_renderer_;
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(shown.resolved_texture())), avail,
                 ImVec2(0, static_cast<float>(preview_height_) / static_cast<float>(std::max(1, shown.height()))),
                 ImVec2(static_cast<float>(preview_width_) / static_cast<float>(std::max(1, shown.width())), 0));
    preview_in_ui_ = true, preview_rect_min_ = ImGui::GetItemRectMin(), preview_rect_max_ = ImGui::GetItemRectMax();
    preview_panel_min_ = ImGui::GetWindowPos();
    preview_panel_max_ = ImVec2(preview_panel_min_.x + ImGui::GetWindowSize().x, preview_panel_min_.y + ImGui::GetWindowSize().y);
    draw_preview_overlay(ImGui::GetItemRectMin(), avail);
    if ((posing_ || timeline_mode_) && !ik_tool_ && ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
      // Pick the bone under the click (the mouse ray against the bones' capsules), else the joint
      // nearest to the click as the camera projects it.
      const ImVec2 origin = ImGui::GetItemRectMin(), m = ImGui::GetIO().MousePos;
      const int before = pose_joint_;
      pose_joint_ = -1;
      pick_limb((m.x - origin.x) / avail.x, (m.y - origin.y) / avail.y, vec2(avail.x, avail.y));
      if (pose_joint_ < 0) {
        pose_joint_ = before;
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
    }
    if (ImGui::IsItemHovered()) {
      const ImGuiIO& io = ImGui::GetIO();
      if (ImGui::IsMouseDragging(ImGuiMouseButton_Left) && !ik_dragging_) controls_->orbit_drag(io.MouseDelta.x, io.MouseDelta.y), orbited_ = true;
      if (ImGui::IsMouseDragging(ImGuiMouseButton_Right)) controls_->pan_drag(io.MouseDelta.x, io.MouseDelta.y), orbited_ = true;
      if (io.MouseWheel != 0.0f) controls_->zoom(io.MouseWheel), orbited_ = true;
    }
    if (figure_or_timeline() || posing_) {
      // The timeline editor has its own transport; the figure has no motion. Cameras and the IK tool.
      for (const auto& [label, command] : {std::pair{"front", ViewerCommand::Front}, std::pair{"side", ViewerCommand::Side},
                                           std::pair{"3/4", ViewerCommand::ThreeQuarter}, std::pair{"top", ViewerCommand::Top}}) {
        if (ImGui::SmallButton(label)) controls_->apply(command);
        ImGui::SameLine();
      }
      if (!figure_mode_) {
        ImGui::Checkbox("drag hand/foot (IK)", &ik_tool_);
        if (ik_residual_ >= 0.0f) ImGui::SameLine(), ImGui::TextDisabled("IK: %.1f mm from the target", ik_residual_ * 1000.0f);
      }
      ImGui::End();
      return;
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
    if (posing_) {
      // Key the pose into the timeline at its playhead (Mode -> Timeline editor shows it there).
      char label[48];
      std::snprintf(label, sizeof label, "Key pose into the timeline at %.2f s", tl_view_.time);
      if (ImGui::Button(label)) key_pose_now(tl_view_.time);
    }
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
  if (show_export_timeline_) ImGui::OpenPopup("Export timeline"), show_export_timeline_ = false;
  if (ImGui::BeginPopupModal("Export timeline", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("The timeline as motion or video: .bvh, .glb, .gltf, .json, .gcl (compressed clip), .png, .gif, .mp4, .webm");
    ImGui::InputText("file", &io_path_);
    if (ImGui::Button("Export")) start_timeline_export(io_path_), ImGui::CloseCurrentPopup();
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  if (show_clip_sign_) ImGui::OpenPopup("Save clip sign"), show_clip_sign_ = false;
  if (ImGui::BeginPopupModal("Save clip sign", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("The timeline's motion as a clip sign in your lexicon (%s)", setup_.user_db.c_str());
    ImGui::InputText("gloss", &tl_view_.clip_gloss);
    if (ImGui::Button("Save")) save_clip_sign(tl_view_.clip_gloss, "ase"), ImGui::CloseCurrentPopup();
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
  }
  if (show_help_) ImGui::OpenPopup("Keys"), show_help_ = false;
  if (ImGui::BeginPopupModal("Keys", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("Ctrl+N new   Ctrl+S save   Ctrl+Z undo   Ctrl+Y / Ctrl+Shift+Z redo   Ctrl+D duplicate   Ctrl+Q quit");
    ImGui::Text("Del remove the selected symbol   Space play/pause   , . step a frame   F1..F4 front, side, 3/4, top");
    ImGui::Text("Preview: left drag orbit, right drag pan, wheel zoom; click the timeline to scrub");
    ImGui::Text("F6 environment editor   F7 figure editor   F8 timeline editor   F9 sign editor   F10 learning   F11 pose editor   K key the pose (timeline)");
    ImGui::Text("Pose/timeline: tick 'drag hand/foot (IK)' under the view, then drag an arm or leg");
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
    if (pressed(GLFW_KEY_F8)) set_environment(false), set_timeline_mode(true);
    if (pressed(GLFW_KEY_F7)) set_environment(false), set_figure_mode(true);
    return;
  }
  if (io.KeyCtrl) {
    if (figure_mode_) {
      if (pressed(GLFW_KEY_Z) && !io.KeyShift) figure_->undo();
      if (pressed(GLFW_KEY_Y) || (pressed(GLFW_KEY_Z) && io.KeyShift)) figure_->redo();
      return;
    }
    if (timeline_mode_) {
      // An unkeyed pose edit is undone first, then the timeline's edits.
      const bool pose_edited = pose_editor_->revision() != pose_synced_revision_;
      if (pressed(GLFW_KEY_Z) && !io.KeyShift) pose_edited ? (void)pose_editor_->undo() : (void)timeline_->undo();
      if (pressed(GLFW_KEY_Y) || (pressed(GLFW_KEY_Z) && io.KeyShift)) pose_edited ? (void)pose_editor_->redo() : (void)timeline_->redo();
      return;
    }
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
  if (pressed(GLFW_KEY_SPACE) && timeline_mode_) tl_view_.playing = !tl_view_.playing;
  else if (pressed(GLFW_KEY_SPACE)) controls_->apply(ViewerCommand::PlayPause);
  if (pressed(GLFW_KEY_COMMA)) controls_->apply(ViewerCommand::StepBack);
  if (pressed(GLFW_KEY_PERIOD)) controls_->apply(ViewerCommand::StepForward);
  if (pressed(GLFW_KEY_F1)) controls_->apply(ViewerCommand::Front);
  if (pressed(GLFW_KEY_F2)) controls_->apply(ViewerCommand::Side);
  if (pressed(GLFW_KEY_F3)) controls_->apply(ViewerCommand::ThreeQuarter);
  if (pressed(GLFW_KEY_F4)) controls_->apply(ViewerCommand::Top);
  if (pressed(GLFW_KEY_F9)) set_learning(false), set_posing(false);
  if (pressed(GLFW_KEY_F11)) set_posing(true);
  if (pressed(GLFW_KEY_F8)) set_timeline_mode(true);
  if (pressed(GLFW_KEY_F7)) set_figure_mode(true);
  if (pressed(GLFW_KEY_F9)) set_timeline_mode(false), set_figure_mode(false);
  if (timeline_mode_ && pressed(GLFW_KEY_K)) key_pose_now(tl_view_.time);
  if (pressed(GLFW_KEY_F6)) set_environment(true);
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
  if (timeline_mode_) return draw_timeline_ui(top, w, h, status_h);
  if (figure_mode_) return draw_figure_ui(top, w, h, status_h);
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
// timeline and figure (ALIAS Timeline Editor ch. 8, Tree Editor ch. 3), IK drag in the view

void Studio::set_timeline_mode(bool on) {
  if (on == timeline_mode_) return;
  if (on) {
    set_environment(false), set_learning(false), set_figure_mode(false);
    posing_ = false;
    controls_->playing = false;  // the sign editor's clip does not play behind the timeline
    tl_synced_time_ = -1.0f;  // show the timeline's pose at the playhead
  }
  timeline_mode_ = on;
  rendered_ = false;
  if (on) say("timeline editor: pose the avatar (right), Key pose (K) keys it at the playhead; drag keys and bar edges to retime");
}

void Studio::set_figure_mode(bool on) {
  if (on == figure_mode_) return;
  if (on) set_environment(false), set_learning(false), set_timeline_mode(false), posing_ = false, controls_->playing = false;
  // The figure is seen whole (a sign frames the upper body); the sign's framing comes back after.
  if (on) {
    sign_box_ = controls_->box;
    controls_->box = framing_box(subject_.mesh, subject_.skeleton);
    controls_->box.hips_y = controls_->box.min.y;  // the cut at the feet: the whole figure
  }
  else controls_->box = sign_box_;
  controls_->select(CameraPreset::Front);
  figure_mode_ = on;
  rendered_ = false;
  if (on) say("figure editor: the skeleton as a tree; edit a joint on the right, save a skeleton file (BVH)");
}

void Studio::sync_timeline_pose() {
  if (tl_view_.key_requested) tl_view_.key_requested = false, key_pose_now(tl_view_.time);
  if (tl_view_.say_requested && !tl_view_.say_text.empty()) timeline_source_from_say(tl_view_.say_text);
  if (tl_view_.sign_requested) timeline_source_from_sign();
  if (tl_view_.clear_requested) timeline_->set_source(Clip{}, {}, {}), say("timeline: no source motion");
  tl_view_.say_requested = tl_view_.sign_requested = tl_view_.clear_requested = false;
  if (tl_view_.time == tl_synced_time_ && timeline_->revision() == tl_synced_revision_) return;
  // The pose at the playhead replaces an unkeyed edit, as in every key-frame editor.
  Pose pose;
  pose.resize(subject_.skeleton.size());
  std::vector<float> morphs(pose_editor_->morph_names().size());
  timeline_->sample(tl_view_.time, pose, morphs);
  pose_editor_->assign(pose, morphs);
  pose_synced_revision_ = pose_editor_->revision();
  tl_synced_time_ = tl_view_.time;
  tl_synced_revision_ = timeline_->revision();
  ik_residual_ = -1.0f;
}

void Studio::key_pose_now(float time) {
  const int keys = timeline_->key_pose(pose_editor_->pose(), pose_editor_->morph_weights(), time);
  char text[96];
  std::snprintf(text, sizeof text, "keyed the pose at %.2f s (%d channel%s)", time, keys, keys == 1 ? "" : "s");
  say(text);
  tl_synced_time_ = -1.0f;  // show what the timeline now holds there
}

void Studio::timeline_source_from_say(const std::string& text) {
  app::SayRequest request;
  request.text = text;
  app::RunContext context;
  context.workspace = workspace_;
  try {
    const app::SayResult r = app::run(request, context);
    std::vector<SourceSign> signs;
    for (const PerformedGloss& g : r.performance.glosses) signs.push_back({g.gloss, g.start, g.end});
    timeline_->set_source(r.performance.clip, signs, text);
    tl_view_.time = 0.0f, tl_synced_time_ = -1.0f;
    say("timeline: '" + text + "' as " + std::to_string(timeline_->bars().size()) + " bars");
  } catch (const std::exception& e) {
    say(std::string("cannot sign '") + text + "': " + e.what());
  }
}

void Studio::timeline_source_from_sign() {
  if (!preview_.clip) {
    say("the draft has no performed sign to put on the timeline");
    return;
  }
  const std::string gloss = model_.draft().gloss.empty() ? std::string("sign") : model_.draft().gloss;
  const std::vector<SourceSign> signs{{gloss, preview_.sign_start, preview_.sign_end}};
  timeline_->set_source(*preview_.clip, signs, gloss);
  tl_view_.time = 0.0f, tl_synced_time_ = -1.0f;
  say("timeline: the sign " + gloss);
}

void Studio::start_timeline_export(const std::string& path) {
  if (export_.valid()) {
    say("an export is already running");
    return;
  }
  const bool gcl = std::filesystem::path(path).extension() == ".gcl";
  app::MotionOutput out;
  out.output = path;
  if (!gcl) {
    try {
      app::validate(out, true);
    } catch (const std::exception& e) {
      say(std::string("not exported: ") + e.what() + " (or .gcl)");
      return;
    }
  }
  export_stop_ = std::stop_source();
  *export_done_ = 0, *export_total_ = 0;
  app::RunContext context;
  context.workspace = workspace_;
  context.stop = export_stop_.get_token();
  context.progress = [done = export_done_, total = export_total_](const app::ProgressUpdate& p) { *done = p.done, *total = p.total; };
  const Clip clip = timeline_->bake(30.0f);
  const float still = tl_view_.time;
  export_ = std::async(std::launch::async, [out, clip, gcl, still, context, skeleton = &subject_.skeleton, mesh = &subject_.mesh]() -> std::string {
    try {
      if (gcl) {
        const CompressedClip compressed = compress(clip, *skeleton);
        write_file_atomically(out.output, std::string_view(reinterpret_cast<const char*>(compressed.bytes().data()), compressed.bytes().size()));
        return "exported " + out.output + " (" + std::to_string(compressed.bytes().size()) + " bytes)";
      }
      const app::WrittenFile w = app::write_motion(out, *skeleton, clip, mesh, still, context);
      return "exported " + w.path + " (" + std::to_string(w.frames) + " frames)";
    } catch (const std::exception& e) {
      const app::ErrorReport report = app::classify(e);
      return report.category == app::ErrorCategory::cancelled ? std::string("export cancelled, nothing written")
                                                               : "export failed, nothing written: " + std::string(e.what());
    }
  });
  say("exporting the timeline to " + path + " ...");
}

void Studio::save_clip_sign(const std::string& gloss, const std::string& language) {
  if (!model_.writable()) {
    say("not saved: your lexicon is read-only");
    return;
  }
  try {
    const SignEntry entry = clip_sign_entry(gloss, language, timeline_->bake(30.0f), subject_.skeleton);
    store_clip_sign(setup_.user_db, entry);
    refresh_browse();
    say("saved the timeline as the clip sign " + gloss + " (" + std::to_string(entry.clip.size()) + " bytes)");
  } catch (const std::exception& e) {
    say(std::string("not saved: ") + e.what());
  }
}

void Studio::figure_skinning(std::vector<mat4>& model, std::vector<mat4>& skinning) const {
  // The avatar's body bound to the edited figure by joint name: a joint the figure has takes the
  // figure's rest frame; one it lacks follows its parent as it does at rest.
  const Skeleton& f = figure_->skeleton();
  const Skeleton& a = subject_.skeleton;
  std::vector<mat4> fm(f.size());
  local_to_model(f, rest_pose(f), fm);
  for (std::size_t j = 0; j < a.size(); ++j) {
    const int k = f.find(a.names[j]);
    const mat4 rest = glm::inverse(inverse_bind_[j]);
    if (k >= 0) model[j] = fm[static_cast<std::size_t>(k)];
    else if (a.parents[j] >= 0) model[j] = model[static_cast<std::size_t>(a.parents[j])] * inverse_bind_[static_cast<std::size_t>(a.parents[j])] * rest;
    else model[j] = rest;
    skinning[j] = model[j] * inverse_bind_[j];
  }
}

bool Studio::ik_drag_to(int joint, const vec3& target, const std::string& merge_key) {
  const auto limb = limb_of(subject_.skeleton, joint);
  if (!limb) {
    say("not a limb: pick an arm, hand, leg or foot");
    return false;
  }
  ik_limb_ = limb;
  ik_target_ = target;
  Pose pose = pose_editor_->pose();
  ik_residual_ = drag_limb(subject_.skeleton, pose, *limb, target);
  pose_editor_->set_pose(pose, merge_key);
  pose_joint_ = limb->end;
  return true;
}

void Studio::pick_limb(float fx, float fy, const vec2& size) {
  const Camera camera = controls_->camera(size.x / std::max(1.0f, size.y));
  const mat4 inverse = glm::inverse(camera.projection * camera.view);
  const float x = fx * 2.0f - 1.0f, y = 1.0f - fy * 2.0f;
  const vec4 near = inverse * vec4(x, y, -1.0f, 1.0f), far = inverse * vec4(x, y, 1.0f, 1.0f);
  const vec3 origin = vec3(near) / near.w, direction = vec3(far) / far.w - origin;
  std::vector<mat4> model(subject_.skeleton.size());
  pose_editor_->model(model);
  const int joint = pick_bone(subject_.skeleton, model, origin, direction);
  if (joint < 0) return;
  pose_joint_ = joint;
  const auto limb = limb_of(subject_.skeleton, joint);
  say("picked " + subject_.skeleton.names[static_cast<std::size_t>(joint)] +
      (limb ? " (drag moves the " + std::string(limb->arm ? "hand" : "foot") + ")" : std::string()));
  if (limb) ik_limb_ = limb, ik_plane_point_ = vec3(model[static_cast<std::size_t>(limb->end)][3]);
}

void Studio::draw_preview_overlay(const ImVec2& origin, const ImVec2& size) {
  const Camera camera = controls_->camera(controls_->aspect);
  const auto project = [&](const vec3& p, ImVec2& out) {
    const vec4 c = camera.projection * camera.view * vec4(p, 1.0f);
    if (c.w <= 0.0f) return false;
    out = ImVec2(origin.x + (c.x / c.w * 0.5f + 0.5f) * size.x, origin.y + (0.5f - c.y / c.w * 0.5f) * size.y);
    return true;
  };
  ImDrawList* d = ImGui::GetWindowDrawList();
  d->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  struct PopClip {
    ImDrawList* d;
    ~PopClip() { d->PopClipRect(); }
  } pop{d};
  if (figure_mode_) {
    if (!fig_view_.show_body) d->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(40, 42, 48, 255));
    if (!fig_view_.show_sticks) return;
    const Skeleton& f = figure_->skeleton();
    std::vector<mat4> fm(f.size());
    local_to_model(f, rest_pose(f), fm);
    for (std::size_t j = 0; j < f.size(); ++j) {
      ImVec2 a, b;
      if (!project(vec3(fm[j][3]), b)) continue;
      const bool selected = static_cast<int>(j) == fig_view_.joint;
      if (f.parents[j] >= 0 && project(vec3(fm[static_cast<std::size_t>(f.parents[j])][3]), a))
        d->AddLine(a, b, selected ? IM_COL32(255, 140, 60, 255) : IM_COL32(90, 230, 120, 255), selected ? 3.0f : 1.5f);
      d->AddCircleFilled(b, selected ? 5.0f : 2.5f, f.dofs[j].count() ? IM_COL32(250, 250, 120, 255) : IM_COL32(150, 150, 150, 255));
    }
    if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
      const ImVec2 m = ImGui::GetIO().MousePos;
      float best = 400.0f;
      for (std::size_t j = 0; j < f.size(); ++j) {
        ImVec2 p;
        if (!project(vec3(fm[j][3]), p)) continue;
        const float dd = (p.x - m.x) * (p.x - m.x) + (p.y - m.y) * (p.y - m.y);
        if (dd < best) best = dd, fig_view_.joint = static_cast<int>(j);
      }
    }
    return;
  }
  if (!posing_ && !timeline_mode_) return;
  const ImGuiIO& io = ImGui::GetIO();
  // The IK tool: press on a limb, drag its hand or foot in the plane facing the camera.
  if (ik_tool_ && ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
    pick_limb((io.MousePos.x - origin.x) / size.x, (io.MousePos.y - origin.y) / size.y, vec2(size.x, size.y));
    ik_dragging_ = ik_limb_.has_value();
  }
  if (ik_dragging_ && ImGui::IsMouseDown(ImGuiMouseButton_Left) && ik_limb_) {
    const mat4 inverse = glm::inverse(camera.projection * camera.view);
    const float x = (io.MousePos.x - origin.x) / size.x * 2.0f - 1.0f, y = 1.0f - (io.MousePos.y - origin.y) / size.y * 2.0f;
    const vec4 n = inverse * vec4(x, y, -1.0f, 1.0f), f = inverse * vec4(x, y, 1.0f, 1.0f);
    const vec3 o = vec3(n) / n.w, dir = vec3(f) / f.w - o;
    const vec3 normal = glm::normalize(camera.target - camera.eye);
    const float den = glm::dot(dir, normal);
    if (std::abs(den) > 1e-6f && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
      const vec3 target = o + dir * (glm::dot(ik_plane_point_ - o, normal) / den);
      ik_drag_to(ik_limb_->end, target, "ik-drag");
    }
  }
  if (ik_dragging_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) ik_dragging_ = false, pose_editor_->seal();
  if (ik_limb_ && ik_residual_ >= 0.0f) {
    ImVec2 p;
    if (project(ik_target_, p)) d->AddCircle(p, 7.0f, IM_COL32(255, 90, 60, 255), 16, 2.0f);
  }
}

void Studio::draw_timeline_ui(float top, float w, float h, float status_h) {
  const float left = std::round(w * 0.18f), right = std::round(w * 0.27f), centre = w - left - right;
  const float tracks_h = std::round(h * 0.56f);
  if (begin_panel("Channels", {0, top}, {left, h})) draw_timeline_channels(*timeline_, tl_view_);
  ImGui::End();
  draw_preview({left, top}, {centre, h - tracks_h});
  if (begin_panel("Timeline", {left, top + h - tracks_h}, {centre, tracks_h})) draw_timeline_tracks(*timeline_, tl_view_);
  ImGui::End();
  draw_joint({left + centre, top}, {right, h});
  draw_status({0, top + h}, {w, status_h});
  draw_popups();
  shortcuts();
}

void Studio::draw_figure_ui(float top, float w, float h, float status_h) {
  const float left = std::round(w * 0.22f), right = std::round(w * 0.32f), centre = w - left - right;
  if (begin_panel("Figure", {0, top}, {left, h})) draw_figure_tree(*figure_, fig_view_);
  ImGui::End();
  draw_preview({left, top}, {centre, h});
  if (begin_panel("Figure joint", {left + centre, top}, {right, h})) draw_figure_joint(*figure_, fig_view_);
  ImGui::End();
  draw_status({0, top + h}, {w, status_h});
  draw_popups();
  shortcuts();
}

bool Studio::execute_timeline_or_figure(const ScriptStep& step) {
  const std::string& a = step.action;
  const auto arg = [&](std::size_t i) { return i < step.args.size() ? step.args[i] : std::string(); };
  const auto number = [&](std::size_t i) {
    try {
      std::size_t used = 0;
      const float v = std::stof(arg(i), &used);
      if (used != arg(i).size() || !std::isfinite(v)) throw std::invalid_argument("");
      return v;
    } catch (const std::exception&) {
      throw Error(SourceLocation{request_.script, step.line}, "'" + arg(i) + "' is not a number");
    }
  };
  const auto channel = [&](const std::string& name) {
    const int c = timeline_->channel_for(name);
    if (c < 0) say("no channel " + name + " (JOINT.x|y|z of a free axis, or a face channel)");
    return c;
  };
  if (a == "mode" && arg(0) == "timeline") return set_timeline_mode(true), true;
  if (a == "mode" && arg(0) == "figure") return set_figure_mode(true), true;
  // pose editor: picking and IK (in pose and timeline mode)
  if (a == "pose-pick") {
    if (!posing_ && !timeline_mode_) set_posing(true);
    pick_limb(number(0), number(1), vec2(preview_panel_.x, preview_panel_.y));
    return true;
  }
  if (a == "pose-drag" || a == "pose-drag-by") {
    if (!posing_ && !timeline_mode_) set_posing(true);
    const int joint = subject_.skeleton.find(arg(0));
    if (joint < 0) return say("no joint " + arg(0)), true;
    vec3 target(number(1), number(2), number(3));
    if (a == "pose-drag-by") {
      const auto limb = limb_of(subject_.skeleton, joint);
      if (!limb) return say("not a limb: " + arg(0)), true;
      std::vector<mat4> model(subject_.skeleton.size());
      pose_editor_->model(model);
      target += vec3(model[static_cast<std::size_t>(limb->end)][3]);
    }
    if (ik_drag_to(joint, target, {})) {
      char text[96];
      std::snprintf(text, sizeof text, "dragged the %s: %.1f mm from the target", ik_limb_->arm ? "hand" : "foot", ik_residual_ * 1000.0f);
      say(text);
    }
    return true;
  }
  const bool timeline_action = a.rfind("timeline-", 0) == 0 || a == "key-pose" || a == "key" || a == "move-key" || a == "move-keys-at" ||
                               a == "key-interp" || a == "bar-duration" || a == "export-timeline" || a == "save-clip-sign" ||
                               a == "strip-zoom" || a == "loop" || a == "where-key";
  if (timeline_action && !timeline_mode_) set_timeline_mode(true);
  if (timeline_mode_) {
    if (a == "timeline-say") tl_view_.say_text = arg(0), timeline_source_from_say(arg(0));
    else if (a == "timeline-sign") timeline_source_from_sign();
    else if (a == "timeline-clear") timeline_->set_source(Clip{}, {}, {});
    else if (a == "key-pose") key_pose_now(step.args.empty() ? tl_view_.time : number(0));
    else if (a == "key") {
      if (const int c = channel(arg(0)); c >= 0)
        tl_view_.key = timeline_->set_key(c, number(1), number(2)), tl_view_.channel = c, tl_view_.follow_selection = true;
    } else if (a == "move-key") {
      const int c = timeline_->find_channel(arg(0));
      if (c < 0 || !timeline_->move_key(c, static_cast<int>(number(1)), number(2))) say("no key " + arg(1) + " on " + arg(0));
    } else if (a == "where-key") {
      // Writes "X Y": the window pixel where the key was drawn in the last frame (for tests that
      // drive the real mouse), or nothing (the status says why) when it is not on screen.
      const int c = timeline_->find_channel(arg(0)), k = static_cast<int>(number(1));
      const auto drawn = std::find_if(tl_view_.drawn_keys.begin(), tl_view_.drawn_keys.end(),
                                      [&](const TimelineView::DrawnKey& d) { return d.channel == c && d.key == k; });
      if (c < 0 || drawn == tl_view_.drawn_keys.end()) {
        say("key " + arg(1) + " of " + arg(0) + " is not on screen");
      } else {
        std::ofstream out(arg(2));
        out << std::lround(drawn->x) << ' ' << std::lround(drawn->y) << '\n';
        if (!out) say("cannot write " + arg(2));
      }
    } else if (a == "move-keys-at") {
      say("moved " + std::to_string(timeline_->move_keys_at(number(0), number(1))) + " keys");
    } else if (a == "key-interp") {
      KeyInterpolation kind{};
      const int c = timeline_->find_channel(arg(0));
      if (!parse_key_interpolation(arg(2), kind)) say("no interpolation '" + arg(2) + "' (step, linear, catmull-rom, kb)");
      else if (c < 0 || !timeline_->set_interpolation(c, static_cast<int>(number(1)), kind,
                                                        Tcb{step.args.size() > 3 ? number(3) : 0.0f, step.args.size() > 4 ? number(4) : 0.0f,
                                                            step.args.size() > 5 ? number(5) : 0.0f}))
        say("no key " + arg(1) + " on " + arg(0));
      else tl_view_.channel = c, tl_view_.key = static_cast<int>(number(1)), tl_view_.follow_selection = true;
    } else if (a == "bar-duration") {
      if (!timeline_->set_bar_duration(static_cast<int>(number(0)), number(1))) say("no bar " + arg(0));
    } else if (a == "export-timeline") start_timeline_export(arg(0));
    else if (a == "save-clip-sign") save_clip_sign(arg(0), step.args.size() > 1 ? arg(1) : "ase");
    else if (a == "timeline-zoom") tl_view_.zoom = std::clamp(number(0), 1.0f, 16.0f);
    else if (a == "strip-zoom") tl_view_.strip_zoom = std::clamp(number(0), 0.5f, 3.0f);
    else if (a == "loop") tl_view_.loop = arg(0) == "on";
    else if (a == "time") tl_view_.playing = false, tl_view_.time = std::clamp(number(0), 0.0f, timeline_->duration());
    else if (a == "play") tl_view_.playing = true;
    else if (a == "pause") tl_view_.playing = false;
    else if (a == "speed") tl_view_.speed = std::clamp(number(0), 0.25f, 2.0f);
    else if (a == "undo") {
      const bool pose_edited = pose_editor_->revision() != pose_synced_revision_;
      say((pose_edited ? pose_editor_->undo() : timeline_->undo()) ? "undid" : "nothing to undo");
    } else if (a == "redo") {
      say(timeline_->redo() ? "redid" : "nothing to redo");
    } else return false;
    return true;
  }
  const bool figure_action = a.rfind("figure-", 0) == 0;
  if (figure_action && !figure_mode_) set_figure_mode(true);
  if (!figure_mode_) return false;
  FigureEditor& f = *figure_;
  const int j = fig_view_.joint;
  const auto report = [&](bool ok, const std::string& done) { say(ok ? done : f.error()); };
  if (a == "figure-joint") {
    fig_view_.joint = f.skeleton().find(arg(0));
    if (fig_view_.joint < 0) say("no joint " + arg(0));
  } else if (a == "figure-rename") report(f.rename(j, arg(0)), "renamed to " + arg(0));
  else if (a == "figure-add") {
    const int added = f.add_joint(j, arg(0), vec3(number(1), number(2), number(3)));
    report(added >= 0, "added " + arg(0));
    if (added >= 0) fig_view_.joint = added;
  } else if (a == "figure-remove") {
    const int parent = j >= 0 && j < static_cast<int>(f.skeleton().size()) ? f.skeleton().parents[static_cast<std::size_t>(j)] : -1;
    const bool ok = f.remove_joint(j);
    report(ok, "removed the joint");
    if (ok) fig_view_.joint = parent;
  } else if (a == "figure-copy") {
    const int copy = f.copy_branch(j);
    report(copy >= 0, "copied the branch");
    if (copy >= 0) fig_view_.joint = copy;
  } else if (a == "figure-mirror") {
    const int n = f.mirror_branch(j);
    report(n >= 0, "mirrored " + std::to_string(n) + " joints");
  } else if (a == "figure-offset") report(f.set_rest_offset(j, vec3(number(0), number(1), number(2))), "rest offset set");
  else if (a == "figure-limits" || a == "figure-order") {
    if (j < 0 || j >= static_cast<int>(f.skeleton().size())) return say("no joint selected"), true;
    JointDofs d = f.skeleton().dofs[static_cast<std::size_t>(j)];
    if (a == "figure-order") {
      const auto order = parse_rotation_order(arg(0));
      if (!order) return say("no rotation order " + arg(0)), true;
      d.order = *order;
    } else {
      const int axis = arg(0).size() == 1 ? arg(0)[0] - 'x' : -1;
      if (axis < 0 || axis > 2) return say("no axis " + arg(0) + " (x, y, z)"), true;
      d.axes = static_cast<std::uint8_t>(d.axes | (1u << axis));
      d.min_angle[axis] = glm::radians(number(1)), d.max_angle[axis] = glm::radians(number(2));
    }
    report(f.set_dofs(j, d), "degrees of freedom set");
  } else if (a == "figure-dh") report(f.set_dh(j, f.dh_from_rest(j)), "Denavit-Hartenberg description from the rest offset");
  else if (a == "figure-save") {
    try {
      f.save(arg(0));
      say("saved " + arg(0) + " (BVH) and " + figure_sidecar_path(arg(0)));
    } catch (const Error& e) {
      say(std::string("not saved: ") + e.what());
    }
  } else if (a == "figure-load") say(f.load(arg(0)) ? "loaded " + arg(0) : "not loaded: " + f.error());
  else if (a == "figure-view") fig_view_.show_body = arg(0) != "sticks", fig_view_.show_sticks = arg(0) != "body";
  else if (a == "undo") say(f.undo() ? "undid the figure edit" : "nothing to undo");
  else if (a == "redo") say(f.redo() ? "redid the figure edit" : "nothing to redo");
  else return false;
  fig_view_.message = status();
  return true;
}

nlohmann::json Studio::dump_timeline_and_figure() {
  nlohmann::json out;
  nlohmann::json t{{"active", timeline_mode_}, {"duration", timeline_->duration()}, {"time", tl_view_.time},
                   {"title", timeline_->title()}, {"can_undo", timeline_->can_undo()}, {"speed", tl_view_.speed},
                   {"clip_gloss", tl_view_.clip_gloss}};
  auto& bars = t["bars"] = nlohmann::json::array();
  for (const TimelineBar& b : timeline_->bars()) bars.push_back({{"label", b.label}, {"kind", to_string(b.kind)}, {"duration", b.duration}});
  auto& channels = t["channels"] = nlohmann::json::object();
  for (const TimelineChannel& c : timeline_->channels()) {
    auto& keys = channels[c.name] = nlohmann::json::array();
    for (const TimelineKey& k : c.keys) keys.push_back({{"time", k.time}, {"value", k.value}, {"interpolation", to_string(k.interpolation)}});
  }
  out["timeline"] = t;
  const Skeleton& s = figure_->skeleton();
  nlohmann::json f{{"active", figure_mode_}, {"joints", s.size()}, {"file", figure_->file()}, {"can_undo", figure_->can_undo()}};
  if (fig_view_.joint >= 0 && fig_view_.joint < static_cast<int>(s.size())) {
    const std::size_t j = static_cast<std::size_t>(fig_view_.joint);
    const vec3 o = s.rest_translations[j];
    f["joint"] = {{"name", s.names[j]}, {"offset", {o.x, o.y, o.z}}, {"dofs", s.dofs[j].count()},
                  {"parent", s.parents[j] < 0 ? std::string() : s.names[static_cast<std::size_t>(s.parents[j])]}};
  }
  out["figure"] = f;
  // The IK drag: the dragged limb's end where the pose has it now, and the last target.
  nlohmann::json ik{{"joint", pose_joint_ >= 0 ? subject_.skeleton.names[static_cast<std::size_t>(pose_joint_)] : std::string()}};
  {
    std::vector<mat4> model(subject_.skeleton.size());
    pose_editor_->model(model);
    for (const char* name : {"r_wrist", "l_wrist", "r_ankle", "l_ankle"})
      if (const int k = subject_.skeleton.find(name); k >= 0) {
        const vec3 p(model[static_cast<std::size_t>(k)][3]);
        ik[name] = {p.x, p.y, p.z};
      }
  }
  if (ik_limb_) {
    std::vector<mat4> model(subject_.skeleton.size());
    pose_editor_->model(model);
    const vec3 end(model[static_cast<std::size_t>(ik_limb_->end)][3]);
    ik["end_joint"] = subject_.skeleton.names[static_cast<std::size_t>(ik_limb_->end)];
    ik["end"] = {end.x, end.y, end.z};
    ik["target"] = {ik_target_.x, ik_target_.y, ik_target_.z};
    ik["residual"] = ik_residual_;
    ik["can_undo"] = pose_editor_->revision() > 0;
  }
  out["ik"] = ik;
  return out;
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
      j["db_kind"] = to_string(row->entry.notation_kind);
      j["db_notation"] = row->entry.notation;
      try {
        const SignDraft stored = draft_from_entry(row->entry, false);
        j["db_names"] = stored.names;
        j["db_nonmanuals"] = to_json(stored)["nonmanuals"];
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
    // The face and head channels over the sign: each face channel's largest weight, and how far the
    // head joints turned from rest at most (degrees), sampled at 40 moments of the sign.
    const Clip& clip = *preview_.clip;
    nlohmann::json face = nlohmann::json::object(), head = nlohmann::json::object();
    for (std::size_t c = 0; c < clip.channels.size() && c < clip.channel_names.size(); ++c) {
      float peak = 0.0f;
      for (int k = 0; k <= 40; ++k)
        peak = std::max(peak, std::abs(sample_track(clip.channels[c], preview_.sign_start + (preview_.sign_end - preview_.sign_start) * k / 40.0f)));
      if (peak > 0.01f) face[clip.channel_names[c]] = peak;
    }
    for (const char* name : {"skullbase", "vc4", "l_eyeball_joint", "r_eyeball_joint"}) {
      const int joint = subject_.skeleton.find(name);
      if (joint < 0 || static_cast<std::size_t>(joint) >= clip.rotations.size()) continue;
      float peak = 0.0f;
      const quat rest = subject_.skeleton.rest_rotations[static_cast<std::size_t>(joint)];
      if (!clip.rotations[static_cast<std::size_t>(joint)].empty())
        for (int k = 0; k <= 40; ++k) {
          const quat q = sample_track(clip.rotations[static_cast<std::size_t>(joint)],
                                      preview_.sign_start + (preview_.sign_end - preview_.sign_start) * k / 40.0f);
          peak = std::max(peak, glm::degrees(2.0f * std::acos(std::min(1.0f, std::abs(glm::dot(q, rest))))));
        }
      head[name] = peak;
    }
    p["face"] = face;
    p["head_degrees"] = head;
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
  j["clip_sign_shown"] = shown_clip_sign_;
  j.update(dump_timeline_and_figure());
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

bool Studio::needs_frame() {
  if (const unsigned events = g_input_events.load(); events != seen_events_) seen_events_ = events, settle_frames_ = kSettleFrames;
  if (settle_frames_ > 0 || !script_.empty() || request_.frames > 0 || wait_frames_ > 0 || !pending_screenshot_.empty()) return true;
  if (preview_busy() || export_.valid() || environment_ || !rendered_) return true;
  // Playing something that lasts (a new sign without notation has nothing to play).
  if (timeline_mode_ ? tl_view_.playing && timeline_->duration() > 0.0f
                     : controls_->playing && !posing_ && !figure_mode_ && animator_->duration() > 0.0f)
    return true;
  return show_recovery_;
}

bool Studio::reuse_ui(Clock::time_point now, bool stepped, int width, int height, bool refreshing) const {
  return ui_fbo_ != 0 && ui_size_ == glm::ivec2(width, height) && preview_in_ui_ && !stepped && settle_frames_ == 0 &&
         (refreshing || now - last_full_ui_ < kUiRefresh) && pending_screenshot_.empty() && request_.frames == 0 && !environment_ && !posing_ &&
         !figure_or_timeline() && !show_recovery_ && !preview_busy() && !export_.valid() &&
         !ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
}

Clock::time_point Studio::draw_ui_strip(int width, int height) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const ImVec2 picture_min = preview_rect_min_, picture_max = preview_rect_max_;
  preview_in_ui_ = false;
  draw_ui();
  ImGui::Render();
  const Clock::time_point built = Clock::now();
  // The strip: the preview panel below its picture. Should the layout have moved (it cannot without
  // input or a new size, which draw the whole UI), the next full draw puts everything right.
  const ImVec4 strip(preview_panel_min_.x, picture_max.y, preview_panel_max_.x, preview_panel_max_.y);
  if (!preview_in_ui_ || picture_min.x != preview_rect_min_.x || picture_max.y != preview_rect_max_.y ||
      strip.z <= strip.x || strip.w <= strip.y) {
    full_ui_due_ = true;
    compose_cached_ui(width, height, true);
    return built;
  }
  ImDrawData* data = ImGui::GetDrawData();
  for (int l = 0; l < data->CmdListsCount; ++l)
    for (ImDrawCmd& cmd : data->CmdLists[l]->CmdBuffer) {
      ImVec4& c = cmd.ClipRect;
      c = ImVec4(std::max(c.x, strip.x), std::max(c.y, strip.y), std::min(c.z, strip.z), std::min(c.w, strip.w));
      if (c.z <= c.x || c.w <= c.y) c = ImVec4(strip.x, strip.y, strip.x, strip.y);  // nothing of it in the strip
    }
  const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
  const int x0 = static_cast<int>(std::floor(strip.x * scale.x)), x1 = static_cast<int>(std::ceil(strip.z * scale.x));
  const int y0 = height - static_cast<int>(std::ceil(strip.w * scale.y)), y1 = height - static_cast<int>(std::floor(strip.y * scale.y));
  glBindFramebuffer(GL_FRAMEBUFFER, ui_fbo_);
  glViewport(0, 0, width, height);
  glEnable(GL_SCISSOR_TEST);
  glScissor(x0, y0, x1 - x0, y1 - y0);
  glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  ImGui_ImplOpenGL3_RenderDrawData(data);
  compose_cached_ui(width, height, true);
  ++strip_ui_frames_;
  return built;
}

void Studio::compose_cached_ui(int width, int height, bool with_preview) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, ui_fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  if (with_preview && shown_renderer_) {
    // The new preview picture where the UI shows it (GL rows bottom-up; ImGui's y grows downward).
    const Renderer& shown = *shown_renderer_;
    const unsigned texture = shown.resolved_texture();
    if (!preview_read_fbo_) glGenFramebuffers(1, &preview_read_fbo_);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, preview_read_fbo_);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    const int x0 = static_cast<int>(std::lround(preview_rect_min_.x * scale.x)), x1 = static_cast<int>(std::lround(preview_rect_max_.x * scale.x));
    const int y0 = height - static_cast<int>(std::lround(preview_rect_max_.y * scale.y)),
              y1 = height - static_cast<int>(std::lround(preview_rect_min_.y * scale.y));
    glBlitFramebuffer(0, 0, preview_width_, preview_height_, x0, y0, x1, y1, GL_COLOR_BUFFER_BIT,
                      preview_width_ == x1 - x0 ? GL_NEAREST : GL_LINEAR);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

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
    glfwPollEvents();
    if (!needs_frame()) {
      // Nothing moves and nothing was touched: the last frame stays on screen, and the studio waits
      // for input (waking 4 times a second for the autosave and finished work) instead of drawing.
      glfwWaitEventsTimeout(0.25);
      if (!needs_frame()) {
        ++idle_waits_;
        autosave();
        last = Clock::now();
        continue;
      }
    }
    const Clock::time_point start = Clock::now();
    bool stepped = false;  // a script step ran in this frame
    // One script step per frame boundary (after its waits).
    if (wait_frames_ > 0) {
      --wait_frames_;
    } else if (script_next_ < script_.size() && !preview_busy()) {
      const ScriptStep& step = script_[script_next_++];
      // A wait only counts frames: like a user doing nothing, it does not make the UI draw again.
      stepped = step.action != "wait";
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
    if (timeline_mode_) {
      advance(tl_view_, static_cast<float>(std::chrono::duration<double>(start - last).count()), timeline_->duration());
      sync_timeline_pose();
    }
    last = start;

    int width = 0, height = 0;
    window_.framebuffer_size(width, height);
    if (width <= 0 || height <= 0) continue;
    const bool timing = log != nullptr;  // glFinish between the parts only when measuring them
    if (environment_) env_->render();
    else render_preview();
    if (timing) glFinish();
    const Clock::time_point t_preview = Clock::now();

    const std::uint64_t revision_before_ui = model_.revision();
    const bool reuse = synthesis_ms_.size() == syntheses && reuse_ui(start, stepped, width, height);
    const bool strip = !reuse && !full_ui_due_ && synthesis_ms_.size() == syntheses && reuse_ui(start, stepped, width, height, true);
    Clock::time_point t_ui;
    if (strip) {
      t_ui = draw_ui_strip(width, height);
      last_full_ui_ = start;
    } else if (reuse) {
      // Only the preview moved: the UI drawn last time, with the new picture in it.
      t_ui = Clock::now();
      compose_cached_ui(width, height, true);
      ++reused_ui_frames_;
    } else {
      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      ImGui::NewFrame();
      preview_in_ui_ = false;
      draw_ui();
      ImGui::Render();
      t_ui = Clock::now();
      if (ui_size_ != glm::ivec2(width, height)) {
        if (!ui_texture_) glGenTextures(1, &ui_texture_);
        glBindTexture(GL_TEXTURE_2D, ui_texture_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glBindTexture(GL_TEXTURE_2D, 0);
        if (!ui_fbo_) glGenFramebuffers(1, &ui_fbo_);
        glBindFramebuffer(GL_FRAMEBUFFER, ui_fbo_);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, ui_texture_, 0);
        ui_size_ = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE ? glm::ivec2(width, height) : glm::ivec2(0, 0);
      }
      // Drawn into the kept texture (when there is one), then copied into the window.
      glBindFramebuffer(GL_FRAMEBUFFER, ui_size_ == glm::ivec2(width, height) ? ui_fbo_ : 0);
      glViewport(0, 0, width, height);
      glDisable(GL_SCISSOR_TEST);
      glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
      if (ui_size_ == glm::ivec2(width, height)) compose_cached_ui(width, height, false);
      last_full_ui_ = start;
      full_ui_due_ = false;
    }
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
    if (settle_frames_ > 0) --settle_frames_;
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
    if (reused_ui_frames_ > 0)
      std::fprintf(stderr, "gestura studio: %llu frames showed a new preview in the UI kept from the frame before (not drawn again)\n",
                   static_cast<unsigned long long>(reused_ui_frames_));
    if (strip_ui_frames_ > 0)
      std::fprintf(stderr, "gestura studio: %llu frames drew only the strip under the preview again (playhead, time)\n",
                   static_cast<unsigned long long>(strip_ui_frames_));
    if (idle_waits_ > 0)
      std::fprintf(stderr, "gestura studio: %llu waits for input with nothing to draw (no frame drawn)\n",
                   static_cast<unsigned long long>(idle_waits_));
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
