// S2: parse + synthesize one sign on the default avatar, and the whole Ham2Pose lexicon (4,070 signs).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sign_synthesis.hpp"

using namespace gestura;

namespace {

struct Rig {
  Avatar avatar = build_avatar();
  SigningRig rig = make_signing_rig(avatar);
};
const Rig& rig() {
  static const Rig r;
  return r;
}

// ASL MOTHER: a handshape, orientation, a contact at the chin and a repeated small movement.
constexpr const char* kMother =
    "hamfinger2345,hamthumboutmod,hamextfingeru,hampalml,hamchin,hamtouch,hammoveo,hamsmallmod,hamrepeatfromstart";

void S2_ParseAndSynthesizeOneSign(benchmark::State& state) {
  const SigningRig& r = rig().rig;
  for (auto _ : state) {
    const SignSynthesis s = synthesize_sign(sign::parse_hamnosys_names(kMother), r);
    benchmark::DoNotOptimize(s.clip.duration);
  }
}
BENCHMARK(S2_ParseAndSynthesizeOneSign)->Unit(benchmark::kMicrosecond);

std::vector<std::string> lexicon_notations() {
  const char* env = std::getenv("GESTURA_SHARED_DATA");
  const std::string dir = env && std::filesystem::exists(env) ? env : GESTURA_SHARED_DATA;
  std::ifstream file(dir + "/hamnosys/signs.jsonl");
  std::vector<std::string> out;
  std::string line;
  while (std::getline(file, line)) {
    const auto key = line.find("\"hamnosys\": \"");
    if (key == std::string::npos) continue;
    const auto start = key + 13, end = line.find('"', start);
    out.push_back(line.substr(start, end - start));
  }
  return out;
}

void S2_SynthesizeWholeLexicon(benchmark::State& state) {
  static const std::vector<std::string> notations = lexicon_notations();
  if (notations.empty()) {
    state.SkipWithError("no ../shared/data/hamnosys/signs.jsonl");
    return;
  }
  const SigningRig& r = rig().rig;
  for (auto _ : state) {
    int done = 0;
    for (const std::string& n : notations) {
      try {
        const SignSynthesis s = synthesize_sign(sign::parse_hamnosys_unicode(n), r);
        done += s.stats.frames > 0;
      } catch (const std::exception&) {
      }
    }
    state.counters["signs"] = done;
  }
}
BENCHMARK(S2_SynthesizeWholeLexicon)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
