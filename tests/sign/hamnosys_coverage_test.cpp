// Parses every real sign we have: 4,070 lexicon entries (DGS, PJM) and 100 ISL SiGML files.
// Prints the parse rate per source and fails when it falls below the ratchet (the rate reached
// when this test was written; raise it when the parser improves, never lower it).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "gestura/core/error.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/sigml.hpp"
#include "support/shared_data.hpp"

namespace {

using namespace gestura::sign;

constexpr double kMinLexiconRate = 1.0;   // DGS and PJM, lenient parse
constexpr double kMinSigmlRate = 1.0;     // ISL SiGML files
constexpr double kMinStrictRate = 0.998;  // all lexicon signs, strict parse

struct Tally {
  int total = 0, parsed = 0;
  double rate() const { return total ? double(parsed) / total : 0.0; }
};

TEST(HamnosysCoverage, AllLexiconSignsParse) {
  std::ifstream in(gestura::test::shared_data() + "/hamnosys/signs.jsonl");
  ASSERT_TRUE(in) << "missing signs.jsonl";
  std::map<std::string, Tally> lenient, strict;
  int names_checked = 0, names_agree = 0;
  std::string line;
  int failures_shown = 0;
  while (std::getline(in, line)) {
    const auto j = nlohmann::json::parse(line);
    const std::string source = j.at("source");
    const std::string text = j.at("hamnosys");
    ++lenient[source].total;
    ++strict[source].total;
    try {
      parse_hamnosys_unicode(text);
      ++lenient[source].parsed;
    } catch (const gestura::Error& e) {
      if (failures_shown++ < 20) std::printf("  %s %s: %s\n", source.c_str(), j.value("gloss", "").c_str(), e.what());
    }
    try {
      parse_hamnosys_unicode(text, ParseOptions{.strict = true});
      ++strict[source].parsed;
    } catch (const gestura::Error&) {
    }
    // The `names` field spells the same notation; both front doors must give the same symbols.
    const std::string names = j.value("names", "");
    if (!names.empty() && names != "None") {
      ++names_checked;
      if (symbols_from_names(names) == symbols_from_unicode(text)) ++names_agree;
    }
  }
  Tally all, all_strict;
  for (const auto& [source, t] : lenient) {
    std::printf("HamNoSys coverage %s: %d/%d parsed (%.2f%%), strict %d (%.2f%%)\n", source.c_str(), t.parsed,
                t.total, 100 * t.rate(), strict[source].parsed, 100 * strict[source].rate());
    all.total += t.total;
    all.parsed += t.parsed;
    all_strict.total += strict[source].total;
    all_strict.parsed += strict[source].parsed;
    EXPECT_GE(t.rate(), kMinLexiconRate) << source;
  }
  EXPECT_EQ(all.total, 4070);
  EXPECT_GE(all_strict.rate(), kMinStrictRate);
  std::printf("names field agrees with Unicode for %d/%d DGS signs\n", names_agree, names_checked);
  EXPECT_EQ(names_agree, names_checked);
  EXPECT_GT(names_checked, 1700);
}

TEST(HamnosysCoverage, AllSigmlFilesParse) {
  const std::filesystem::path dir = gestura::test::shared_data() + "/sigml-isl";
  Tally files, signs;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".sigml") continue;
    ++files.total;
    bool ok = true;
    try {
      const std::string text = read_text_file(entry.path().string());
      for (const SigmlEntry& e : read_sigml_entries(text, entry.path().filename().string())) {
        ++signs.total;
        if (e.sign) ++signs.parsed;
        else {
          ok = false;
          std::printf("  %s\n", e.error->what());
        }
      }
    } catch (const gestura::Error& e) {
      ok = false;
      std::printf("  %s\n", e.what());
    }
    files.parsed += ok ? 1 : 0;
  }
  std::printf("HamNoSys coverage ISL-SiGML: %d/%d files, %d/%d signs parsed (%.2f%%)\n", files.parsed, files.total,
              signs.parsed, signs.total, 100 * signs.rate());
  EXPECT_EQ(files.total, 100);
  EXPECT_GE(files.rate(), kMinSigmlRate);
  EXPECT_GE(signs.rate(), kMinSigmlRate);
}

}  // namespace
