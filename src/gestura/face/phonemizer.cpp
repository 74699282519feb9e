#include "gestura/face/phonemizer.hpp"

#include <espeak-ng/speak_lib.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>

#include "gestura/core/error.hpp"
#include "gestura/core/utf8.hpp"

namespace gestura::face {
namespace {

std::mutex& engine_mutex() {
  static std::mutex m;
  return m;
}

// Called with the engine mutex held. Returns an empty string on success, else why it failed; the
// outcome is remembered because eSpeak cannot be initialised twice.
const std::string& engine_status() {
  static const std::string status = [] {
    const char* path = std::getenv("GESTURA_ESPEAK_DATA");
    if (path && !*path) path = nullptr;
    // eSpeak reads a missing data directory by crashing later, so look before it does.
    namespace fs = std::filesystem;
    std::error_code ec;
    if (path && !fs::exists(fs::path(path) / "phontab", ec) &&
        !fs::exists(fs::path(path) / "espeak-ng-data" / "phontab", ec))
      return std::string("eSpeak NG data not found in '") + path +
             "' (GESTURA_ESPEAK_DATA must name espeak-ng-data or the directory that contains it)";
    const int rate = espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, path, espeakINITIALIZE_DONT_EXIT);
    if (rate <= 0)
      return std::string("eSpeak NG could not be initialised (data directory ") +
             (path ? std::string("'") + path + "'" : std::string("default")) +
             " missing or unreadable; install espeak-ng-data or set GESTURA_ESPEAK_DATA)";
    if (espeak_SetVoiceByName("en-us") != EE_OK)
      return std::string("eSpeak NG has no 'en-us' voice in its data directory");
    return std::string();
  }();
  return status;
}

void add_phoneme(std::vector<Phoneme>& out, std::string_view token) {
  Stress stress = Stress::none;
  while (!token.empty() && (token.front() == '\'' || token.front() == ',' || token.front() == '%' ||
                            token.front() == '=')) {
    if (token.front() == '\'') stress = Stress::primary;
    else if (token.front() == ',' && stress == Stress::none) stress = Stress::secondary;
    token.remove_prefix(1);
  }
  while (!token.empty() && (token.back() == ';' || token.back() == '-')) token.remove_suffix(1);
  if (token.empty()) return;
  Phoneme p;
  p.symbol = std::string(token);
  if (token.front() == '_') {
    p.cls = PhonemeClass::pause;
  } else {
    const Articulation a = articulation(token);
    p.cls = a.cls;
    if (p.cls != PhonemeClass::vowel) stress = Stress::none;
    p.duration = relative_duration(a, stress);
  }
  p.stress = stress;
  out.push_back(std::move(p));
}

}  // namespace

std::vector<Phoneme> parse_espeak_phonemes(std::string_view mnemonics) {
  std::vector<Phoneme> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= mnemonics.size(); ++i) {
    if (i == mnemonics.size() || mnemonics[i] == '|' || mnemonics[i] == ' ') {
      add_phoneme(out, mnemonics.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

std::vector<Phoneme> phonemize(std::string_view text) {
  if (text.size() > kMaxPhonemizeBytes)
    throw Error("phonemize: text of " + std::to_string(text.size()) + " bytes is longer than the " +
                std::to_string(kMaxPhonemizeBytes) + "-byte limit");
  utf8::validate(text);
  std::vector<Phoneme> out;
  if (text.empty()) return out;
  const std::string input(text);  // eSpeak wants a zero-terminated string

  std::lock_guard lock(engine_mutex());
  if (const std::string& status = engine_status(); !status.empty()) throw Error(status);
  const void* cursor = input.c_str();
  const int mode = '|' << 8;  // ASCII mnemonics, '|' between phonemes
  while (cursor) {
    const char* clause = espeak_TextToPhonemes(&cursor, espeakCHARS_UTF8, mode);
    if (!clause) break;
    std::vector<Phoneme> part = parse_espeak_phonemes(clause);
    if (part.empty()) continue;
    if (!out.empty()) out.push_back(Phoneme{"_", PhonemeClass::pause, Stress::none, 1.0f});
    out.insert(out.end(), part.begin(), part.end());
  }
  return out;
}

}  // namespace gestura::face
