// gestura say: English text → ASL performed by the default avatar (sentence/signer.hpp).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/io/gltf_animation.hpp"
#include "gestura/io/joint_positions_json.hpp"
#include "gestura/lexicon/default_lexicon.hpp"
#include "gestura/render/render_job.hpp"
#include "gestura/render/subject.hpp"
#include "gestura/sentence/signer.hpp"

namespace {

using namespace gestura;

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

float parse_speed(const std::string& v) {
  char* end = nullptr;
  const float speed = std::strtof(v.c_str(), &end);
  if (end == v.c_str() || *end) throw Error("--speed needs a number, got '" + v + "'");
  return speed;
}

void print_timeline(const SentencePerformance& p) {
  for (const PerformedGloss& g : p.glosses)
    std::printf("%6.2f–%6.2f s  %-14s %s\n", g.start, g.end, g.gloss.c_str(), g.source.c_str());
  std::printf("duration %.2f s (including the approach from and return to rest)\n", p.duration);
  std::printf("%d transitions: %d bent around the body, %d solved by IK every frame\n", p.motion.transitions,
              p.motion.via, p.motion.escaped);
}

int run_say(const std::vector<std::string>& args) {
  std::optional<std::string> text;
  std::string output, camera = "front", size = "1280x720";
  SayOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-o" || a == "--output") output = cli::flag_value(args, i);
    else if (a == "--speed") options.speed = parse_speed(cli::flag_value(args, i));
    else if (a == "--camera") camera = cli::flag_value(args, i);
    else if (a == "--size") size = cli::flag_value(args, i);
    else if (a == "--lang") options.lang = cli::flag_value(args, i);
    else if (a == "--fps") options.fps = static_cast<float>(parse_fps(cli::flag_value(args, i)));
    else if (a == "--no-mouthing") options.mouthing = false;
    else if (a == "--no-nonmanuals") options.nonmanuals = false;
    else if (a.size() > 1 && a[0] == '-') throw Error("unknown flag '" + a + "' (see gestura say --help)");
    else if (text) throw Error("give the text as one argument (quote it)");
    else text = a;
  }
  if (!text) throw Error("missing TEXT (see gestura say --help)");
  if (!output.empty() && !ends_with(output, ".mp4") && !ends_with(output, ".webm") && !ends_with(output, ".gif") &&
      !ends_with(output, ".png") && !ends_with(output, ".glb") && !ends_with(output, ".gltf") &&
      !ends_with(output, ".bvh") && !ends_with(output, ".json"))
    throw Error("-o " + output + ": unknown output type (use .mp4 .webm .gif .png .glb .bvh .json)");

  DefaultLexicon lexicon;
  const Avatar avatar = build_avatar();
  const Signer signer(avatar, lexicon.layers());
  const SentencePerformance p = signer.say(*text, options);
  for (const std::string& note : p.notes) std::fprintf(stderr, "note: %s\n", note.c_str());
  if (output.empty()) {
    print_timeline(p);
    return 0;
  }

  if (ends_with(output, ".json")) write_joint_positions_json(output, avatar.skeleton, p.clip, options.fps);
  else if (ends_with(output, ".bvh")) save_bvh(output, make_bvh(avatar.skeleton, p.clip, 1.0f / options.fps));
  else if (ends_with(output, ".glb") || ends_with(output, ".gltf")) save_gltf(output, avatar.skeleton, p.clip, &avatar.mesh);
  else {
    RenderJob job;
    job.output = output;
    job.size = parse_image_size(size);
    job.fps = static_cast<int>(options.fps);
    job.cameras = parse_camera_list(camera);
    job.sheet = ends_with(output, ".png");
    validate(job);
    RenderSubject subject{avatar.skeleton, avatar.mesh, p.clip};
    render_to_file(subject, job);
  }
  print_timeline(p);
  std::printf("wrote %s\n", std::filesystem::absolute(output).c_str());
  return 0;
}

const cli::Registration reg{{
    "say",
    "sign English text in ASL on the default avatar",
    "usage: gestura say TEXT [-o OUT] [--speed S] [--lang ase] [--fps N] [--camera LIST] [--size WxH]\n"
    "                   [--no-mouthing] [--no-nonmanuals]\n\n"
    "TEXT is translated to ASL glosses (gestura gloss shows how), each gloss is signed from the lexicon\n"
    "(built-in data/lexicon plus the user lexicon) or fingerspelled, the signs are joined without\n"
    "returning to rest, and the face adds mouthing, question brows, negation headshake and blinks.\n"
    "Without -o the gloss timeline is printed. OUT by extension: .mp4 .webm .gif video, .png contact\n"
    "sheet, .glb/.gltf (skeleton, mesh, animation with face morph weights), .bvh, .json joint positions.\n"
    "--speed 0.25–2 scales the tempo. Only 'ase' (ASL) has a lexicon. At most 16 KiB of text and 300\n"
    "glosses per call: split longer text.",
    run_say,
}};

}  // namespace
