#include "gestura/text/wordnet.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <unordered_map>

// WordNet's header defines short macros (NOUN, VERB, SYNS, ...): kept to this file.
#include <wn.h>

namespace gestura::wordnet {
namespace {

std::mutex& wordnet_mutex() {
  static std::mutex m;
  return m;
}

// WordNet reads its files on every look-up; the answers are kept (bounded) under the mutex.
using Cache = std::unordered_map<std::string, std::vector<std::string>>;
constexpr std::size_t kCacheSize = 50000;
Cache& cache() {
  static Cache c;
  return c;
}
const std::vector<std::string>* cached(const std::string& key) {
  const auto it = cache().find(key);
  return it == cache().end() ? nullptr : &it->second;
}
void remember(const std::string& key, const std::vector<std::string>& value) {
  if (cache().size() >= kCacheSize) cache().clear();
  cache().emplace(key, value);
}

// Under the mutex: opens the database once.
bool ready_locked() {
  static const bool ok = [] {
    if (const char* off = std::getenv("GESTURA_NO_WORDNET"); off && std::strcmp(off, "1") == 0) return false;
    return wninit() == 0;
  }();
  return ok;
}

int wn_pos(english::PartOfSpeech pos) {
  switch (pos) {
    case english::PartOfSpeech::noun: return NOUN;
    case english::PartOfSpeech::verb: return VERB;
    case english::PartOfSpeech::adjective: return ADJ;
    case english::PartOfSpeech::adverb: return ADV;
    default: return 0;
  }
}

// WordNet writes multi-word lemmas with underscores and takes non-const buffers.
constexpr std::size_t kMaxWord = 80;
bool to_buffer(std::string_view word, char (&buffer)[kMaxWord]) {
  if (word.empty() || word.size() >= kMaxWord) return false;
  for (std::size_t i = 0; i < word.size(); ++i) {
    const char c = word[i];
    if (c == '\0') return false;
    buffer[i] = c == ' ' ? '_' : c;
  }
  buffer[word.size()] = '\0';
  return true;
}

std::string from_wordnet(const char* text) {
  std::string out(text);
  std::replace(out.begin(), out.end(), '_', ' ');
  // Adjective lemmas may carry a syntactic marker: "big(a)".
  if (const auto paren = out.find('('); paren != std::string::npos) out.erase(paren);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

void add_unique(std::vector<std::string>& list, std::string word) {
  if (!word.empty() && std::find(list.begin(), list.end(), word) == list.end()) list.push_back(std::move(word));
}

}  // namespace

bool available() {
  std::lock_guard lock(wordnet_mutex());
  return ready_locked();
}

std::vector<std::string> lemmas(std::string_view word, english::PartOfSpeech pos) {
  std::vector<std::string> out;
  const int p = wn_pos(pos);
  char buffer[kMaxWord];
  if (p == 0 || !to_buffer(word, buffer)) return out;
  std::lock_guard lock(wordnet_mutex());
  if (!ready_locked()) return out;
  const std::string key = "L" + std::to_string(p) + buffer;
  if (const auto* hit = cached(key)) return *hit;
  // A verb form is most often an inflection (saw → see, left → leave), a noun form a word of its own
  // when WordNet lists it (glasses, news, clothes).
  const bool word_is_lemma = is_defined(buffer, p) != 0;
  if (word_is_lemma && p != VERB) add_unique(out, from_wordnet(buffer));
  for (char* base = morphstr(buffer, p); base; base = morphstr(nullptr, p)) add_unique(out, from_wordnet(base));
  if (word_is_lemma) add_unique(out, from_wordnet(buffer));
  remember(key, out);
  return out;
}

std::vector<std::string> synonyms(std::string_view lemma, english::PartOfSpeech pos, int senses) {
  std::vector<std::string> out;
  const int p = wn_pos(pos);
  char buffer[kMaxWord];
  if (p == 0 || !to_buffer(lemma, buffer)) return out;
  std::lock_guard lock(wordnet_mutex());
  if (!ready_locked()) return out;
  const std::string key = "S" + std::to_string(p) + ":" + std::to_string(senses) + ":" + buffer;
  if (const auto* hit = cached(key)) return *hit;
  SynsetPtr list = findtheinfo_ds(buffer, p, SYNS, ALLSENSES);
  const std::string self = from_wordnet(buffer);
  int sense = 0;
  for (SynsetPtr s = list; s && sense < senses; s = s->nextss, ++sense)
    for (int i = 0; i < s->wcount; ++i)
      if (std::string w = from_wordnet(s->words[i]); w != self) add_unique(out, std::move(w));
  if (list) free_syns(list);
  remember(key, out);
  return out;
}

bool names_a_person(std::string_view lemma) {
  char buffer[kMaxWord];
  if (!to_buffer(lemma, buffer)) return false;
  std::lock_guard lock(wordnet_mutex());
  if (!ready_locked()) return false;
  const std::string key = std::string("P") + buffer;
  if (const auto* hit = cached(key)) return !hit->empty();
  constexpr long kPersonOffset = 7846;  // person.n.01 in WordNet 3.0's data.noun
  constexpr int kInstanceHypernym = 38;  // "@i": a named instance's class
  bool person = false;
  SynsetPtr first = findtheinfo_ds(buffer, NOUN, SYNS, 1);
  if (first) {
    // Breadth-first up the hypernyms (a synset may have several), bounded: the noun hierarchy is
    // under twenty levels deep.
    std::vector<long> frontier{first->hereiam};
    std::vector<long> seen;
    free_syns(first);
    for (int depth = 0; depth < 24 && !frontier.empty() && !person; ++depth) {
      std::vector<long> next;
      for (long offset : frontier) {
        if (offset == kPersonOffset) {
          person = true;
          break;
        }
        if (std::find(seen.begin(), seen.end(), offset) != seen.end()) continue;
        seen.push_back(offset);
        char no_word[1] = "";
        SynsetPtr s = read_synset(NOUN, offset, no_word);
        if (!s) continue;
        for (int i = 0; i < s->ptrcount; ++i)
          if ((s->ptrtyp[i] == HYPERPTR || s->ptrtyp[i] == kInstanceHypernym) && s->ppos[i] == NOUN)
            next.push_back(s->ptroff[i]);
        free_synset(s);
      }
      frontier = std::move(next);
    }
  }
  remember(key, person ? std::vector<std::string>{"person"} : std::vector<std::string>{});
  return person;
}

bool first_sense_is_proper(std::string_view word) {
  char buffer[kMaxWord];
  if (!to_buffer(word, buffer)) return false;
  for (char* c = buffer; *c; ++c) *c = static_cast<char>(std::tolower(static_cast<unsigned char>(*c)));
  std::lock_guard lock(wordnet_mutex());
  if (!ready_locked()) return false;
  const std::string key = std::string("C") + buffer;
  if (const auto* hit = cached(key)) return !hit->empty();
  bool proper = false;
  if (IndexPtr index = index_lookup(buffer, NOUN)) {
    // Senses are in frequency order; an untagged first sense (Frank, the Germanic people) is no evidence.
    if (index->tagged_cnt > 0 && index->off_cnt > 0)
      if (SynsetPtr s = read_synset(NOUN, index->offset[0], buffer)) {
        for (int i = 0; i < s->wcount; ++i)
          if (from_wordnet(s->words[i]) == buffer) proper = std::isupper(static_cast<unsigned char>(s->words[i][0])) != 0;
        free_synset(s);
      }
    free_index(index);
  }
  remember(key, proper ? std::vector<std::string>{"proper"} : std::vector<std::string>{});
  return proper;
}

std::string first_noun_sense_class(std::string_view word) {
  char buffer[kMaxWord];
  if (!to_buffer(word, buffer)) return {};
  for (char* c = buffer; *c; ++c) *c = static_cast<char>(std::tolower(static_cast<unsigned char>(*c)));
  std::lock_guard lock(wordnet_mutex());
  if (!ready_locked()) return {};
  const std::string key = std::string("F") + buffer;
  if (const auto* hit = cached(key)) return hit->empty() ? std::string() : hit->front();
  std::string out;
  if (SynsetPtr first = findtheinfo_ds(buffer, NOUN, SYNS, 1)) {
    constexpr int kLexicographerFiles = 45;  // WordNet 3.0's lexnames: adj.all (0) … verb.weather (44)
    if (first->fnum >= 0 && first->fnum < kLexicographerFiles && lexfiles[first->fnum]) out = lexfiles[first->fnum];
    free_syns(first);
  }
  remember(key, out.empty() ? std::vector<std::string>{} : std::vector<std::string>{out});
  return out;
}

}  // namespace gestura::wordnet
