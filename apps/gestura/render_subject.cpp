#include "render_subject.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>

#include "command.hpp"
#include "gestura/anim/clip_by_name.hpp"
#include "gestura/io/avatar_source.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/lexicon/default_lexicon.hpp"
#include "gestura/render/test_motion.hpp"
#include "gestura/sentence/signer.hpp"
#include "gestura/sign/sign_synthesis.hpp"

namespace gestura::cli {
namespace {

// A motion as read from a file: the skeleton it was made for and its clip.
struct MotionFile {
  Skeleton skeleton;
  Clip clip;
};

using MotionReader = std::function<MotionFile(const std::string& path)>;

// Motion file formats by extension (lower case). A glTF clip reader adds a row here.
const std::map<std::string, MotionReader>& motion_readers() {
  static const std::map<std::string, MotionReader> table{
      {".bvh", [](const std::string& path) {
         BvhFile bvh = load_bvh(path);
         return MotionFile{std::move(bvh.skeleton), std::move(bvh.clip)};
       }}};
  return table;
}

MotionFile read_motion(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const auto it = motion_readers().find(ext);
  if (it != motion_readers().end()) return it->second(path);
  std::string supported;
  for (const auto& [known, reader] : motion_readers()) supported += (supported.empty() ? "" : ", ") + known;
  throw Error(path + ": cannot play '" + (ext.empty() ? "(no extension)" : ext) + "' motion files (supported: " +
              supported + ")");
}

// The clip on the avatar's skeleton. Clips made on the avatar's H-Anim skeleton (any size, or a
// part of it) bind by joint name; anything else needs retargeting, which belongs right here.
Clip bind_to_avatar(const MotionFile& motion, const Skeleton& avatar, const std::string& path) {
  const JointNameMatch match = match_joints_by_name(motion.skeleton, motion.clip, avatar);
  if (!match.unmatched.empty()) {
    std::string names;
    const std::size_t shown = std::min<std::size_t>(5, match.unmatched.size());
    for (std::size_t i = 0; i < shown; ++i) names += (i ? ", " : "") + match.unmatched[i];
    if (shown < match.unmatched.size()) names += ", …";
    throw Error(path + ": " + std::to_string(match.unmatched.size()) + " of the clip's " +
                std::to_string(motion.skeleton.size()) + " joints are not joints of the avatar (" + names +
                "); only clips on the avatar's H-Anim skeleton play here (no retargeting yet)");
  }
  return clip_for_skeleton(motion.skeleton, motion.clip, avatar, match);
}

float parse_number(const std::string& flag, const std::string& text) {
  float value = 0.0f;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) throw Error("flag " + flag + ": '" + text + "' is not a number");
  return value;
}

}  // namespace

bool parse_avatar_flag(const std::vector<std::string>& args, std::size_t& i, AvatarParams& params, std::string& spec) {
  const std::string& a = args[i];
  if (a == "--height") params.height = parse_number(a, flag_value(args, i));
  else if (a == "--build") params.build = parse_number(a, flag_value(args, i));
  else if (a == "--sex") params.sex = parse_sex(flag_value(args, i));
  else if (a == "--avatar") spec = flag_value(args, i);
  else return false;
  return true;
}

RenderSubject load_render_subject(Motion motion, const std::string& clip_path, const AvatarParams& params,
                                  const SignSource& sign_source, const std::string& avatar_spec) {
  params.validate();
  // Read the motion before building the avatar: a bad file or sign fails at once.
  std::optional<MotionFile> file;
  if (motion == Motion::ClipFile) file = read_motion(clip_path);
  std::optional<sign::HamSign> notation;
  std::vector<sign::NonManual> nonmanual;
  if (motion == Motion::Sign && sign_source.text.empty()) {
    notation = load_sign(sign_source);
    nonmanual = load_nonmanuals(sign_source);
  }
  Avatar avatar = load_avatar(avatar_spec, params);
  std::optional<Clip> performed;
  if (motion == Motion::Sign && !sign_source.text.empty()) {
    DefaultLexicon lexicon;
    const Signer signer(avatar, lexicon.layers());
    SentencePerformance said = signer.say(sign_source.text, SayOptions{});
    for (const std::string& note : said.notes) std::fprintf(stderr, "note: %s\n", note.c_str());
    performed = std::move(said.clip);
  }
  if (notation) {
    const SigningRig rig = make_signing_rig(avatar);
    SignSynthesis result = synthesize_sign(*notation, nonmanual, rig);
    for (const NonManualWarning& w : result.warnings)
      std::fprintf(stderr, "warning: %s:%d: %s\n", sign_source.sigml_path.c_str(), w.line, w.message.c_str());
    if (const auto problem = synthesis_problem(result, rig)) std::fprintf(stderr, "warning: %s\n", problem->c_str());
    performed = std::move(result.clip);
  }
  RenderSubject subject{std::move(avatar.skeleton), std::move(avatar.mesh), std::nullopt};
  switch (motion) {
    case Motion::Rest: break;
    case Motion::TestMotion: subject.clip = make_wave_clip(subject.skeleton); break;
    case Motion::ClipFile: subject.clip = bind_to_avatar(*file, subject.skeleton, clip_path); break;
    case Motion::Sign: subject.clip = std::move(performed); break;
  }
  return subject;
}

}  // namespace gestura::cli
