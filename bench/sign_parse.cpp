// HamNoSys parsing speed: one typical lexicon sign, and the whole 4,070-sign lexicon.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "gestura/sign/hamnosys_parser.hpp"

namespace {

const std::vector<std::string>& lexicon() {
  static const std::vector<std::string> signs = [] {
    const char* env = std::getenv("GESTURA_SHARED_DATA");
    const std::string root = env && *env ? env : GESTURA_SHARED_DATA;
    std::vector<std::string> out;
    std::ifstream in(root + "/hamnosys/signs.jsonl");
    std::string line;
    while (std::getline(in, line)) out.push_back(nlohmann::json::parse(line).at("hamnosys").get<std::string>());
    return out;
  }();
  return signs;
}

// DGS PILL1^ (14 symbols): handshape, orientation, location, a parallel move + replacement, repeat.
void BM_ParseOneSign(benchmark::State& state) {
  const std::string names =
      "hampinch12,hamextfingerul,hampalml,hamlips,hamparbegin,hammovei,hamsmallmod,hamreplace,hamcee12,"
      "hamfingerstraightmod,hamthumbopenmod,hamparend,hamclose,hamrepeatfromstart";
  const std::vector<gestura::sign::Symbol> symbols = gestura::sign::symbols_from_names(names);
  for (auto _ : state) benchmark::DoNotOptimize(gestura::sign::parse_hamnosys(symbols));
  state.SetLabel(std::to_string(symbols.size()) + " symbols");
}
BENCHMARK(BM_ParseOneSign)->Unit(benchmark::kMicrosecond);

// Decode UTF-8 and parse all lexicon signs.
void BM_ParseWholeLexicon(benchmark::State& state) {
  const auto& signs = lexicon();
  if (signs.empty()) {
    state.SkipWithError("signs.jsonl not found (set GESTURA_SHARED_DATA)");
    return;
  }
  for (auto _ : state)
    for (const std::string& s : signs) benchmark::DoNotOptimize(gestura::sign::parse_hamnosys_unicode(s));
  state.SetLabel(std::to_string(signs.size()) + " signs");
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(signs.size()));
}
BENCHMARK(BM_ParseWholeLexicon)->Unit(benchmark::kMillisecond);

}  // namespace
