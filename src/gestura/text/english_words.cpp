#include "gestura/text/english_words.hpp"

#include <algorithm>
#include <array>
#include <unordered_map>

namespace gestura::english {

namespace {

template <class V>
std::optional<V> lookup(const std::unordered_map<std::string_view, V>& table, std::string_view key) {
  const auto it = table.find(key);
  if (it == table.end()) return std::nullopt;
  return it->second;
}

bool ends_with(std::string_view s, std::string_view suffix) {
  return s.size() > suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

}  // namespace

std::optional<std::vector<std::string>> expand_contraction(std::string_view w) {
  static const std::unordered_map<std::string_view, std::vector<std::string>> kWhole{
      {"can't", {"can't"}},       {"cannot", {"can't"}},     {"won't", {"will", "not"}},
      {"ain't", {"is", "not"}},   {"let's", {"let", "us"}},  {"y'all", {"you", "all"}},
      {"shan't", {"shall", "not"}}, {"o'clock", {"o'clock"}},
  };
  if (const auto it = kWhole.find(w); it != kWhole.end()) return it->second;
  const auto split = [&](std::size_t cut, std::string second) {
    return std::vector<std::string>{std::string(w.substr(0, cut)), std::move(second)};
  };
  if (ends_with(w, "n't")) return split(w.size() - 3, "not");
  if (ends_with(w, "'m")) return split(w.size() - 2, "am");
  if (ends_with(w, "'re")) return split(w.size() - 3, "are");
  if (ends_with(w, "'ve")) return split(w.size() - 3, "have");
  if (ends_with(w, "'ll")) return split(w.size() - 3, "will");
  if (ends_with(w, "'d")) return split(w.size() - 2, "would");
  if (ends_with(w, "'s")) {
    static constexpr std::array kIsWords{"it", "he", "she", "that", "there", "here", "what", "where", "who",
                                         "how", "when", "why", "this"};
    const std::string_view stem = w.substr(0, w.size() - 2);
    const bool is = std::find(kIsWords.begin(), kIsWords.end(), stem) != kIsWords.end();
    return split(w.size() - 2, is ? "is" : "'s");
  }
  return std::nullopt;
}

DropReason dropped(std::string_view w) {
  static const std::unordered_map<std::string_view, DropReason> kTable{
      {"a", DropReason::article},        {"an", DropReason::article},       {"the", DropReason::article},
      {"am", DropReason::copula},        {"is", DropReason::copula},        {"are", DropReason::copula},
      {"was", DropReason::copula},       {"were", DropReason::copula},      {"be", DropReason::copula},
      {"been", DropReason::copula},      {"being", DropReason::copula},     {"to", DropReason::preposition},
      {"of", DropReason::preposition},   {"at", DropReason::preposition},   {"by", DropReason::preposition},
      {"into", DropReason::preposition}, {"onto", DropReason::preposition}, {"upon", DropReason::preposition},
      {"on", DropReason::preposition},   {"in", DropReason::preposition},   {"'s", DropReason::filler},
      {"o'clock", DropReason::filler},   {"please", DropReason::none},
  };
  return lookup(kTable, w).value_or(DropReason::none);
}

std::string_view describe(DropReason reason) {
  switch (reason) {
    case DropReason::article: return "article";
    case DropReason::copula: return "copula 'be' (ASL has none)";
    case DropReason::preposition: return "preposition (carried by placement and movement in ASL)";
    case DropReason::filler: return "no sign of its own";
    case DropReason::none: break;
  }
  return "";
}

std::optional<std::string_view> pronoun_gloss(std::string_view w) {
  static const std::unordered_map<std::string_view, std::string_view> kTable{
      {"i", "IX-1"},        {"me", "IX-1"},       {"myself", "SELF-1"},      {"you", "IX-2"},
      {"yourself", "SELF-2"}, {"he", "IX-3"},     {"him", "IX-3"},           {"she", "IX-3"},
      {"it", "IX-3"},       {"they", "IX-3-PL"},  {"them", "IX-3-PL"},       {"we", "WE"},
      {"us", "WE"},         {"my", "POSS-1"},     {"mine", "POSS-1"},        {"your", "POSS-2"},
      {"yours", "POSS-2"},  {"his", "POSS-3"},    {"its", "POSS-3"},         {"their", "POSS-3-PL"},
      {"theirs", "POSS-3-PL"}, {"our", "OUR"},    {"ours", "OUR"},
  };
  return lookup(kTable, w);
}

bool is_wh_word(std::string_view w) {
  return w == "who" || w == "what" || w == "where" || w == "when" || w == "why" || w == "how" || w == "which";
}

bool is_auxiliary_do(std::string_view w) { return w == "do" || w == "does" || w == "did"; }

bool is_auxiliary(std::string_view w) {
  static constexpr std::array kAux{"do",   "does",  "did",    "am",     "is",    "are",  "was",
                                   "were", "have",  "has",    "had",    "can",   "could", "will",
                                   "would", "shall", "should", "may",   "might", "must", "can't"};
  return std::find(kAux.begin(), kAux.end(), w) != kAux.end();
}

std::optional<std::string_view> time_gloss(std::string_view w) {
  static const std::unordered_map<std::string_view, std::string_view> kTable{
      {"yesterday", "YESTERDAY"}, {"today", "TODAY"},       {"tomorrow", "TOMORROW"}, {"tonight", "TONIGHT"},
      {"now", "NOW"},             {"later", "LATER"},       {"soon", "SOON"},         {"recently", "RECENT"},
      {"monday", "MONDAY"},       {"tuesday", "TUESDAY"},   {"wednesday", "WEDNESDAY"},
      {"thursday", "THURSDAY"},   {"friday", "FRIDAY"},     {"saturday", "SATURDAY"}, {"sunday", "SUNDAY"},
      {"weekend", "WEEKEND"},
  };
  return lookup(kTable, w);
}

std::optional<Month> month(std::string_view w) {
  static const std::unordered_map<std::string_view, Month> kTable{
      {"january", {1, "JAN"}},   {"february", {2, "FEB"}}, {"march", {3, "MARCH"}},    {"april", {4, "APRIL"}},
      {"may", {5, "MAY"}},       {"june", {6, "JUNE"}},    {"july", {7, "JULY"}},      {"august", {8, "AUG"}},
      {"september", {9, "SEPT"}}, {"october", {10, "OCT"}}, {"november", {11, "NOV"}}, {"december", {12, "DEC"}},
  };
  return lookup(kTable, w);
}

std::optional<Month> month(int number) {
  static constexpr std::array<std::string_view, 12> kLetters{"JAN",  "FEB", "MARCH", "APRIL", "MAY", "JUNE",
                                                             "JULY", "AUG", "SEPT",  "OCT",   "NOV", "DEC"};
  if (number < 1 || number > 12) return std::nullopt;
  return Month{number, kLetters[static_cast<std::size_t>(number - 1)]};
}

std::optional<long long> number_word(std::string_view w) {
  static const std::unordered_map<std::string_view, long long> kTable{
      {"zero", 0},      {"one", 1},        {"two", 2},        {"three", 3},       {"four", 4},
      {"five", 5},      {"six", 6},        {"seven", 7},      {"eight", 8},       {"nine", 9},
      {"ten", 10},      {"eleven", 11},    {"twelve", 12},    {"thirteen", 13},   {"fourteen", 14},
      {"fifteen", 15},  {"sixteen", 16},   {"seventeen", 17}, {"eighteen", 18},   {"nineteen", 19},
      {"twenty", 20},   {"thirty", 30},    {"forty", 40},     {"fifty", 50},      {"sixty", 60},
      {"seventy", 70},  {"eighty", 80},    {"ninety", 90},    {"hundred", 100},   {"thousand", 1000},
      {"million", 1000000},
  };
  return lookup(kTable, w);
}

std::optional<std::string_view> synonym(std::string_view w) {
  static const std::unordered_map<std::string_view, std::string_view> kTable{
      {"mom", "mother"},     {"mum", "mother"},     {"dad", "father"},     {"kid", "child"},
      {"automobile", "car"}, {"purchase", "buy"},   {"hi", "hello"},       {"hey", "hello"},
      {"shop", "store"},     {"film", "movie"},     {"attorney", "lawyer"}, {"physician", "doctor"},
      {"large", "big"},      {"little", "small"},   {"begin", "start"},    {"sofa", "couch"},
      {"okay", "ok"},        {"glad", "happy"},     {"house", "home"},     {"home", "house"},
  };
  return lookup(kTable, w);
}

const std::vector<const Phrase*>& phrases_starting_with(std::string_view first_word) {
  static const std::vector<Phrase> kPhrases{
      {{"thank", "you"}, {"THANK-YOU"}, PhraseRole::plain},
      {{"thanks"}, {"THANK-YOU"}, PhraseRole::plain},
      {{"how", "are", "you"}, {"HOW", "IX-2"}, PhraseRole::wh},
      {{"nice", "to", "meet", "you"}, {"NICE", "MEET", "IX-2"}, PhraseRole::plain},
      {{"excuse", "me"}, {"EXCUSE-ME"}, PhraseRole::plain},
      {{"i", "love", "you"}, {"I-LOVE-YOU"}, PhraseRole::plain},
      {{"see", "you", "later"}, {"SEE-YOU-LATER"}, PhraseRole::plain},
      {{"good", "morning"}, {"GOOD-MORNING"}, PhraseRole::plain},
      {{"good", "afternoon"}, {"GOOD-AFTERNOON"}, PhraseRole::plain},
      {{"good", "night"}, {"GOOD-NIGHT"}, PhraseRole::plain},
      {{"of", "course"}, {"OF-COURSE"}, PhraseRole::plain},
      {{"ice", "cream"}, {"ICE-CREAM"}, PhraseRole::plain},
      {{"high", "school"}, {"HIGH-SCHOOL"}, PhraseRole::plain},
      {{"new", "york"}, {"NEW-YORK"}, PhraseRole::plain},
      {{"a", "lot", "of"}, {"MANY"}, PhraseRole::plain},
      {{"a", "lot"}, {"A-LOT"}, PhraseRole::plain},
      {{"do", "not", "know"}, {"DON'T-KNOW"}, PhraseRole::negation},
      {{"how", "much"}, {"HOW-MUCH"}, PhraseRole::wh},
      {{"how", "many"}, {"HOW-MANY"}, PhraseRole::wh},
      {{"how", "old"}, {"HOW-OLD"}, PhraseRole::wh},
      {{"last", "night"}, {"LAST-NIGHT"}, PhraseRole::time},
      {{"last", "week"}, {"LAST-WEEK"}, PhraseRole::time},
      {{"last", "month"}, {"LAST-MONTH"}, PhraseRole::time},
      {{"last", "year"}, {"LAST-YEAR"}, PhraseRole::time},
      {{"next", "week"}, {"NEXT-WEEK"}, PhraseRole::time},
      {{"next", "month"}, {"NEXT-MONTH"}, PhraseRole::time},
      {{"next", "year"}, {"NEXT-YEAR"}, PhraseRole::time},
      {{"this", "morning"}, {"THIS-MORNING"}, PhraseRole::time},
      {{"this", "week"}, {"THIS-WEEK"}, PhraseRole::time},
      {{"this", "year"}, {"THIS-YEAR"}, PhraseRole::time},
      {{"every", "day"}, {"EVERY-DAY"}, PhraseRole::time},
      {{"in", "the", "morning"}, {"MORNING"}, PhraseRole::time},
      {{"in", "the", "afternoon"}, {"AFTERNOON"}, PhraseRole::time},
      {{"in", "the", "evening"}, {"EVENING"}, PhraseRole::time},
      {{"right", "now"}, {"NOW"}, PhraseRole::time},
  };
  static const auto index = [] {
    std::unordered_map<std::string_view, std::vector<const Phrase*>> by_first;
    for (const Phrase& p : kPhrases) by_first[p.words.front()].push_back(&p);
    for (auto& [word, list] : by_first)
      std::stable_sort(list.begin(), list.end(),
                       [](const Phrase* a, const Phrase* b) { return a->words.size() > b->words.size(); });
    return by_first;
  }();
  static const std::vector<const Phrase*> kNone;
  const auto it = index.find(first_word);
  return it == index.end() ? kNone : it->second;
}

bool is_linking_verb(std::string_view word) {
  static constexpr std::array kLinking{"am",    "is",     "are",    "was",   "were",  "be",    "been",   "being",
                                       "seem",  "seems",  "seemed", "feel",  "feels", "felt",  "look",   "looks",
                                       "looked", "get",   "gets",   "got",   "become", "became", "becomes"};
  return std::any_of(kLinking.begin(), kLinking.end(), [&](const char* v) { return word == v; });
}

}  // namespace gestura::english
