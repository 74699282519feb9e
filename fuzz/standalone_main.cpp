// Runs one fuzz target without libFuzzer, so the test suite (any compiler, no sanitizer needed)
// keeps every target alive between fuzzing campaigns: each seed, then a fixed number of mutations
// of them made by a seeded generator (the same inputs on every run, so a failure repeats).
//
//   fuzz_smoke_<reader> SEED_DIR [MUTATIONS]
//
// Fails (exit 1, the input saved as fuzz-smoke-<reader>-failure in the working directory) when an
// exception other than gestura::Error escapes; a crash or a target's abort() fails the test too.
// Long fuzzing with coverage feedback is `make fuzz` (libFuzzer, build-asan/).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A few byte-level edits, the kinds libFuzzer starts from: flip a bit, set an interesting byte,
// insert or erase a run, repeat a run, cut the end.
std::string mutate(std::string s, std::mt19937_64& rng) {
  static constexpr char kInteresting[] = {'\0', '\xff', '\x7f', '\x80', '0', '9', '-', '.', 'e', '{', '}', '[', ']',
                                          '<', '>', '"', ',', ':', '\n', ' '};
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits; ++e) {
    const std::size_t at = s.empty() ? 0 : rng() % s.size();
    switch (rng() % 6) {
      case 0:
        if (!s.empty()) s[at] = static_cast<char>(s[at] ^ (1 << (rng() % 8)));
        break;
      case 1:
        if (!s.empty()) s[at] = kInteresting[rng() % sizeof kInteresting];
        break;
      case 2: s.insert(at, 1 + rng() % 8, kInteresting[rng() % sizeof kInteresting]); break;
      case 3:
        if (!s.empty()) s.erase(at, 1 + rng() % std::min<std::size_t>(64, s.size() - at));
        break;
      case 4:
        if (!s.empty() && s.size() < (1u << 20)) {
          const std::size_t n = 1 + rng() % std::min<std::size_t>(64, s.size() - at);
          const std::string run = s.substr(at, n);
          for (std::uint64_t k = 1 + rng() % 16; k > 0; --k) s.insert(at, run);
        }
        break;
      case 5: s.resize(at); break;
    }
  }
  return s;
}

bool run_one(const std::string& input, const std::string& name) {
  try {
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
    return true;
  } catch (const std::exception& e) {
    std::cerr << name << ": an exception escaped the reader: " << e.what() << "\n";
  } catch (...) {
    std::cerr << name << ": an unknown exception escaped the reader\n";
  }
  const std::string saved = "fuzz-smoke-" + name + "-failure";
  std::ofstream(saved, std::ios::binary) << input;
  std::cerr << name << ": the input is in " << saved << "\n";
  return false;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::cerr << "usage: " << argv[0] << " SEED_DIR [MUTATIONS]\n";
    return 2;
  }
  const std::string name = fs::path(argv[0]).filename().string();
  const long mutations = argc == 3 ? std::strtol(argv[2], nullptr, 10) : 2000;
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(argv[1], ec))
    if (entry.is_regular_file()) files.push_back(entry.path());
  if (ec || files.empty()) {
    std::cerr << name << ": no seeds in " << argv[1] << "\n";
    return 2;
  }
  std::sort(files.begin(), files.end());
  std::vector<std::string> seeds;
  for (const fs::path& f : files) seeds.push_back(read_bytes(f));
  for (const std::string& s : seeds)
    if (!run_one(s, name)) return 1;
  std::mt19937_64 rng(20261126);
  for (long i = 0; i < mutations; ++i)
    if (!run_one(mutate(seeds[rng() % seeds.size()], rng), name)) return 1;
  std::printf("%s: %zu seeds and %ld mutations, no escape\n", name.c_str(), seeds.size(), mutations);
  return 0;
}
