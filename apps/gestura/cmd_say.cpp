// gestura say: English text → ASL performed by the avatar (app/say.hpp).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "command.hpp"
#include "gestura/app/input_file.hpp"
#include "gestura/app/say.hpp"

namespace gestura::cli {
namespace {

void print_timeline(const SentencePerformance& p) {
  for (const PerformedGloss& g : p.glosses)
    std::printf("%6.2f–%6.2f s  %-14s %s\n", g.start, g.end, g.gloss.c_str(), g.source.c_str());
  std::printf("duration %.2f s (including the approach from and return to rest)\n", p.duration);
  std::printf("%d transitions: %d bent around the body, %d solved by IK every frame\n", p.motion.transitions,
              p.motion.via, p.motion.escaped);
}

Invocation prepare() {
  struct State {
    app::SayRequest request;
    std::string file;
    bool json = false;
  };
  auto state = std::make_shared<State>();
  Invocation invocation;
  invocation.fields = bind_fields(state->request);
  invocation.fields.push_back(option({.name = "file", .help = "read TEXT from this file ('-': standard input)", .value = "FILE", .short_flag = 'f'}, state->file));
  invocation.fields.push_back(flag({.name = "json", .help = "print the result as JSON"}, state->json));
  invocation.run = [state](const app::RunContext& context) {
    app::SayRequest& request = state->request;
    request.text = text_argument(request.text, state->file, app::kMaxTextInputBytes);
    const app::SayResult result = app::run(request, context);
    for (const app::Notice& n : result.notices) std::fprintf(stderr, "%s\n", n.text().c_str());
    if (state->json) {
      std::printf("%s\n", app::to_json(result).dump(2).c_str());
      return 0;
    }
    print_timeline(result.performance);
    if (result.written) std::printf("wrote %s\n", std::filesystem::absolute(result.written->path).c_str());
    return 0;
  };
  return invocation;
}

const Registration reg{{
    "say",
    "sign English text in ASL on the default avatar",
    "TEXT is translated to ASL glosses (gestura gloss shows how), each gloss is signed from the lexicon\n"
    "(built-in data/lexicon plus the user lexicon) or fingerspelled, the signs are joined without\n"
    "returning to rest, and the face adds mouthing, question brows, negation headshake and blinks.\n"
    "TEXT '-' (or --file -) reads standard input. Without -o the gloss timeline is printed.\n" +
        std::string(app::kMotionOutputHelp) +
        "\nHere a .png is always a 4x4 contact sheet of the sentence; .glb/.gltf carry the face morph weights.\n"
        "Only 'ase' (ASL) has a lexicon. At most 16 KiB of text and 300 glosses per call: split longer text.\n"
        "Each sign's joint motion, once solved, is kept in the user lexicon database for later runs\n"
        "(GESTURA_CITATION_CACHE=off: solve every sign afresh).",
    prepare,
}};

}  // namespace
}  // namespace gestura::cli
