// gestura say: English text → ASL performed by the default avatar (sentence/signer.hpp).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "command.hpp"
#include "gestura/io/avatar_source.hpp"
#include "gestura/core/error.hpp"
#include "gestura/lexicon/default_lexicon.hpp"
#include "gestura/sentence/signer.hpp"
#include "motion_output.hpp"

namespace {

using namespace gestura;

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
  cli::MotionOutput out;
  std::string avatar_spec = "default";
  SayOptions options;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (cli::parse_motion_output_flag(args, i, out)) continue;
    if (a == "--speed") options.speed = parse_speed(cli::flag_value(args, i));
    else if (a == "--avatar") avatar_spec = cli::flag_value(args, i);
    else if (a == "--lang") options.lang = cli::flag_value(args, i);
    else if (a == "--no-mouthing") options.mouthing = false;
    else if (a == "--no-nonmanuals") options.nonmanuals = false;
    else if (a.size() > 1 && a[0] == '-') throw Error("unknown flag '" + a + "' (see gestura say --help)");
    else if (text) throw Error("give the text as one argument (quote it)");
    else text = a;
  }
  if (!text) throw Error("missing TEXT (see gestura say --help)");
  // A sentence is many moments: a .png is a contact sheet unless one moment is all that is wanted.
  if (out.path.ends_with(".png")) out.sheet = true;
  if (!out.path.empty()) cli::check_motion_output(out);
  options.fps = static_cast<float>(out.fps);

  DefaultLexicon lexicon;
  const Avatar avatar = load_avatar(avatar_spec);
  const Signer signer(avatar, lexicon.layers());
  const SentencePerformance p = signer.say(*text, options);
  for (const std::string& note : p.notes) std::fprintf(stderr, "note: %s\n", note.c_str());
  if (!out.path.empty()) cli::write_motion(out, avatar.skeleton, p.clip, &avatar.mesh, 0.5f * p.duration);
  print_timeline(p);
  if (!out.path.empty()) std::printf("wrote %s\n", std::filesystem::absolute(out.path).c_str());
  return 0;
}

const cli::Registration reg{{
    "say",
    "sign English text in ASL on the default avatar",
    "usage: gestura say TEXT [-o OUT] [--speed S] [--lang ase] [--avatar SPEC] [--fps N] [--camera LIST]\n"
    "                   [--size WxH] [--no-mouthing] [--no-nonmanuals]\n\n"
    "TEXT is translated to ASL glosses (gestura gloss shows how), each gloss is signed from the lexicon\n"
    "(built-in data/lexicon plus the user lexicon) or fingerspelled, the signs are joined without\n"
    "returning to rest, and the face adds mouthing, question brows, negation headshake and blinks.\n"
    "Without -o the gloss timeline is printed. " + std::string(cli::kMotionOutputUsage) + "\n"
    "Here a .png is always a 4x4 contact sheet of the sentence; .glb/.gltf carry the face morph weights.\n"
    "--speed 0.25–2 scales the tempo. --avatar is default (the generated avatar) or makehuman:DIR.\n"
    "Only 'ase' (ASL) has a lexicon. At most 16 KiB of text and 300 glosses per call: split longer text.",
    run_say,
}};

}  // namespace
