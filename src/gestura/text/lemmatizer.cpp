#include "gestura/text/lemmatizer.hpp"

#include <algorithm>
#include <array>
#include <unordered_map>

namespace gestura {

namespace {

struct Irregular {
  std::string_view lemma;
  std::string_view rule;
};

const std::unordered_map<std::string_view, Irregular>& irregular_forms() {
  static const std::unordered_map<std::string_view, Irregular> kTable = [] {
    std::unordered_map<std::string_view, Irregular> t;
    // Verbs: past and participle forms.
    constexpr std::array<std::array<std::string_view, 3>, 60> kVerbs{{
        {"go", "went", "gone"},       {"eat", "ate", "eaten"},        {"see", "saw", "seen"},
        {"do", "did", "done"},        {"have", "had", "had"},         {"buy", "bought", "bought"},
        {"bring", "brought", "brought"}, {"come", "came", "come"},    {"make", "made", "made"},
        {"take", "took", "taken"},    {"give", "gave", "given"},      {"get", "got", "gotten"},
        {"know", "knew", "known"},    {"think", "thought", "thought"}, {"tell", "told", "told"},
        {"say", "said", "said"},      {"find", "found", "found"},     {"feel", "felt", "felt"},
        {"leave", "left", "left"},    {"meet", "met", "met"},         {"run", "ran", "run"},
        {"sit", "sat", "sat"},        {"stand", "stood", "stood"},    {"write", "wrote", "written"},
        {"speak", "spoke", "spoken"}, {"drive", "drove", "driven"},   {"fly", "flew", "flown"},
        {"swim", "swam", "swum"},     {"begin", "began", "begun"},    {"drink", "drank", "drunk"},
        {"forget", "forgot", "forgotten"}, {"understand", "understood", "understood"},
        {"teach", "taught", "taught"}, {"catch", "caught", "caught"}, {"fight", "fought", "fought"},
        {"sell", "sold", "sold"},     {"send", "sent", "sent"},       {"spend", "spent", "spent"},
        {"build", "built", "built"},  {"lose", "lost", "lost"},       {"pay", "paid", "paid"},
        {"hear", "heard", "heard"},   {"sleep", "slept", "slept"},    {"wake", "woke", "woken"},
        {"wear", "wore", "worn"},     {"choose", "chose", "chosen"},  {"break", "broke", "broken"},
        {"fall", "fell", "fallen"},   {"hold", "held", "held"},       {"keep", "kept", "kept"},
        {"mean", "meant", "meant"},   {"become", "became", "become"}, {"sing", "sang", "sung"},
        {"ride", "rode", "ridden"},   {"win", "won", "won"},          {"grow", "grew", "grown"},
        {"throw", "threw", "thrown"}, {"draw", "drew", "drawn"},      {"steal", "stole", "stolen"},
        {"hide", "hid", "hidden"},
    }};
    for (const auto& v : kVerbs) {
      t.emplace(v[1], Irregular{v[0], "irregular past"});
      if (v[2] != v[0]) t.emplace(v[2], Irregular{v[0], "irregular participle"});
    }
    t.emplace("goes", Irregular{"go", "3rd person -es"});
    t.emplace("does", Irregular{"do", "3rd person -es"});
    t.emplace("has", Irregular{"have", "3rd person"});
    // Nouns with irregular plurals.
    constexpr std::array<std::array<std::string_view, 2>, 12> kNouns{{
        {"child", "children"}, {"man", "men"}, {"woman", "women"}, {"foot", "feet"}, {"tooth", "teeth"},
        {"mouse", "mice"}, {"goose", "geese"}, {"knife", "knives"}, {"wife", "wives"}, {"life", "lives"},
        {"leaf", "leaves"}, {"person", "persons"},
    }};
    for (const auto& n : kNouns) t.emplace(n[1], Irregular{n[0], "irregular plural"});
    return t;
  }();
  return kTable;
}

// Words ending in -s, -ed or -ing that are already base forms.
bool is_base_form(std::string_view w) {
  static constexpr std::array kWords{
      "bus",     "this",     "his",     "is",       "was",    "yes",    "has",      "gas",     "plus",
      "us",      "thus",     "always",  "perhaps",  "news",   "series", "species",  "minus",   "bonus",
      "virus",   "status",   "campus",  "chaos",    "across", "its",    "yours",    "ours",    "theirs",
      "lens",    "christmas", "morning", "evening", "nothing", "something", "anything", "everything",
      "building", "ceiling", "during",  "wedding",  "bed",    "red",    "need",     "feed",    "speed",
      "seed",    "weed",     "hundred", "sled",     "shed",   "wed",    "bled",     "fled",    "sacred",
      "naked",   "wicked",   "ragged",  "kindred",  "tired",  "bored",  "ago",      "less",    "dress",
  };
  return std::find(kWords.begin(), kWords.end(), w) != kWords.end();
}

bool is_vowel(char c) { return c == 'a' || c == 'e' || c == 'i' || c == 'o' || c == 'u'; }

int vowel_groups(std::string_view w) {
  int groups = 0;
  bool in_vowel = false;
  for (std::size_t i = 0; i < w.size(); ++i) {
    const bool v = is_vowel(w[i]) || (w[i] == 'y' && i > 0 && !in_vowel);
    if (v && !in_vowel) ++groups;
    in_vowel = v;
  }
  return groups;
}

bool has_vowel(std::string_view w) {
  return std::any_of(w.begin(), w.end(), [](char c) { return is_vowel(c) || c == 'y'; });
}

// A stem left by removing -ed/-ing: which spellings of the base are plausible, best first.
void stem_candidates(std::string_view stem, std::string_view rule, std::vector<LemmaCandidate>& out) {
  if (stem.size() < 2 || !has_vowel(stem)) return;
  const std::size_t n = stem.size();
  const char last = stem[n - 1];
  const char before = stem[n - 2];
  // stopped → stop, running → run (but not kiss-ing, call-ed, …).
  if (last == before && !is_vowel(last) && last != 'l' && last != 's' && last != 'z' && last != 'f') {
    out.push_back({std::string(stem.substr(0, n - 1)), rule});
    out.push_back({std::string(stem), rule});
    return;
  }
  // liked → like, making → make, moved → move: a silent e after one vowel and one consonant in a
  // one-syllable stem, or after v / c / u / z, which English words rarely end in.
  const bool silent_e = last == 'v' || last == 'c' || last == 'u' || last == 'z' ||
                        (!is_vowel(last) && last != 'w' && last != 'x' && last != 'y' && is_vowel(before) &&
                         (n < 3 || !is_vowel(stem[n - 3])) && vowel_groups(stem) == 1);
  std::string with_e = std::string(stem) + "e";
  if (silent_e) {
    out.push_back({with_e, rule});
    out.push_back({std::string(stem), rule});
  } else {
    out.push_back({std::string(stem), rule});
    out.push_back({with_e, rule});
  }
}

bool ends_with(std::string_view s, std::string_view suffix) {
  return s.size() > suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}

}  // namespace

std::vector<LemmaCandidate> lemma_candidates(std::string_view w) {
  std::vector<LemmaCandidate> out;
  if (const auto it = irregular_forms().find(w); it != irregular_forms().end()) {
    out.push_back({std::string(it->second.lemma), it->second.rule});
  } else if (!is_base_form(w) && w.size() > 3) {
    if (ends_with(w, "ies")) {
      out.push_back({std::string(w.substr(0, w.size() - 3)) + "y", "plural -ies"});
    } else if (ends_with(w, "ied")) {
      out.push_back({std::string(w.substr(0, w.size() - 3)) + "y", "past -ied"});
    } else if (ends_with(w, "ing")) {
      stem_candidates(w.substr(0, w.size() - 3), "-ing", out);
    } else if (ends_with(w, "ed")) {
      stem_candidates(w.substr(0, w.size() - 2), "past -ed", out);
    } else if (ends_with(w, "es") && (ends_with(w, "ches") || ends_with(w, "shes") || ends_with(w, "xes") ||
                                      ends_with(w, "zes") || ends_with(w, "sses") || ends_with(w, "oes"))) {
      out.push_back({std::string(w.substr(0, w.size() - 2)), "plural -es"});
      out.push_back({std::string(w.substr(0, w.size() - 1)), "plural -s"});
    } else if (ends_with(w, "s") && !ends_with(w, "ss") && !ends_with(w, "us") && !ends_with(w, "is")) {
      out.push_back({std::string(w.substr(0, w.size() - 1)), "plural -s"});
    }
  }
  out.push_back({std::string(w), ""});
  return out;
}

}  // namespace gestura
