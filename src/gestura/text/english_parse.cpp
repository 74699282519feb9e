#include "gestura/text/english_parse.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include <link-grammar/link-includes.h>

namespace gestura::english {
namespace {

// Longer sentences are left to the rule tables: link-grammar's time grows steeply with length.
constexpr std::size_t kMaxWords = 32;
// Parses kept for sentences seen again (subtitles and dialogue repeat lines).
constexpr std::size_t kCacheSize = 4096;
constexpr int kMaxLinkagesWeighed = 30;

void quiet(lg_errinfo*, void*) {}  // dictionary notes (locale, ...) are not the user's business

struct Parser {
  Dictionary dictionary = nullptr;
  Parse_Options options = nullptr;
  std::mutex mutex;
  std::unordered_map<std::string, ParsedSentence> cache;

  Parser() {
    if (const char* off = std::getenv("GESTURA_NO_PARSER"); off && std::strcmp(off, "1") == 0) return;
    lg_error_set_handler(quiet, nullptr);
    dictionary = dictionary_create_lang("en");
    if (!dictionary) return;
    options = parse_options_create();
    parse_options_set_verbosity(options, 0);
    parse_options_set_max_parse_time(options, 1);
    parse_options_set_linkage_limit(options, 200);
    parse_options_set_min_null_count(options, 0);
    parse_options_set_max_null_count(options, 0);
    parse_options_set_islands_ok(options, false);
    parse_options_set_spell_guess(options, 0);
    parse_options_set_display_morphology(options, false);
  }
  ~Parser() {
    if (options) parse_options_delete(options);
    if (dictionary) dictionary_delete(dictionary);
  }
};

Parser& parser() {
  static Parser p;
  return p;
}

bool is_one_of(std::string_view word, std::initializer_list<std::string_view> list) {
  return std::find(list.begin(), list.end(), word) != list.end();
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// "hurts.v" → ("hurts", "v"); markers of guessed words ("[?]", "[~]", "[!]") are dropped.
std::pair<std::string, std::string> split_tag(std::string_view tagged) {
  std::string text(tagged);
  for (const char* marker : {"[?]", "[~]", "[!]", "[&]"})
    for (std::size_t at; (at = text.find(marker)) != std::string::npos;) text.erase(at, std::strlen(marker));
  const std::size_t dot = text.rfind('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 >= text.size() || !std::isalpha(static_cast<unsigned char>(text[dot + 1])))
    return {text, ""};
  return {text.substr(0, dot), text.substr(dot + 1)};
}

PartOfSpeech pos_of(std::string_view word, std::string_view subscript) {
  const std::string w = lower(word);
  if (is_one_of(w, {"who", "what", "where", "when", "why", "how", "which"})) return PartOfSpeech::wh;
  if (subscript.empty()) {
    if (!w.empty() && std::isdigit(static_cast<unsigned char>(w[0]))) return PartOfSpeech::number;
    return PartOfSpeech::unknown;
  }
  switch (subscript[0]) {
    case 'v': case 'w': case 'q': return PartOfSpeech::verb;
    case 'n': case 's': case 'g': case 'u': return PartOfSpeech::noun;
    case 'a': return PartOfSpeech::adjective;
    case 'e': return PartOfSpeech::adverb;
    case 'r': return PartOfSpeech::preposition;
    case 'd': return PartOfSpeech::determiner;
    case 'p':
      return is_one_of(w, {"i", "me", "you", "he", "him", "she", "her", "it", "we", "us", "they", "them"})
                 ? PartOfSpeech::pronoun
                 : PartOfSpeech::noun;
    default: return PartOfSpeech::unknown;
  }
}

// Link types by their upper-case head: "Ss*s" is an S link, "SIs" an inverted S link.
std::string_view link_type(std::string_view label) {
  std::size_t n = 0;
  while (n < label.size() && std::isupper(static_cast<unsigned char>(label[n]))) ++n;
  return label.substr(0, n);
}

struct Link {
  std::string type;
  int left, right;  // link-grammar word indices
  bool passive = false;  // a Pv link: passive 'be' → its participle
};

// How much a linkage is to be trusted: link-grammar's own cost, plus a penalty for a 'do' that
// neither supports a verb nor has an object ("how much does this coffee cost" read with 'cost' a
// noun), which English almost never has.
double weigh(Linkage linkage, const std::vector<Link>& links) {
  double cost = linkage_disjunct_cost(linkage);
  const int n = static_cast<int>(linkage_get_num_words(linkage));
  for (int w = 0; w < n; ++w) {
    const std::string word = lower(split_tag(linkage_get_word(linkage, static_cast<WordIdx>(w))).first);
    if (!is_one_of(word, {"do", "does", "did", "don't", "doesn't", "didn't"})) continue;
    const bool used = std::any_of(links.begin(), links.end(), [&](const Link& l) {
      return l.left == w && (l.type == "I" || l.type == "O" || l.type == "MV" || l.type == "N");
    });
    if (!used) cost += 3.0;
  }
  return cost;
}

std::vector<Link> links_of(Linkage linkage) {
  std::vector<Link> links;
  const int n = static_cast<int>(linkage_get_num_links(linkage));
  for (int k = 0; k < n; ++k)
    links.push_back(Link{std::string(link_type(linkage_get_link_label(linkage, k))),
                         static_cast<int>(linkage_get_link_lword(linkage, k)),
                         static_cast<int>(linkage_get_link_rword(linkage, k)),
                         std::string_view(linkage_get_link_label(linkage, k)).starts_with("Pv")});
  return links;
}

}  // namespace

std::string_view to_string(PartOfSpeech pos) {
  switch (pos) {
    case PartOfSpeech::noun: return "noun";
    case PartOfSpeech::verb: return "verb";
    case PartOfSpeech::adjective: return "adjective";
    case PartOfSpeech::adverb: return "adverb";
    case PartOfSpeech::pronoun: return "pronoun";
    case PartOfSpeech::preposition: return "preposition";
    case PartOfSpeech::determiner: return "determiner";
    case PartOfSpeech::number: return "number";
    case PartOfSpeech::wh: return "wh-word";
    case PartOfSpeech::unknown: break;
  }
  return "word";
}

bool parser_available() { return parser().dictionary != nullptr; }

bool is_given_name(std::string_view word) {
  // Read once from link-grammar's data directory (the same search path its dictionary uses).
  static const std::unordered_set<std::string> names = [] {
    std::unordered_set<std::string> out;
    for (const char* file : {"en/words/entities.given-male.sing", "en/words/entities.given-female.sing",
                             "en/words/entities.given-bisex.sing"}) {
      FILE* f = linkgrammar_open_data_file(file);
      if (!f) continue;
      char buffer[256];
      while (std::fscanf(f, "%255s", buffer) == 1) {
        std::string_view entry(buffer);
        if (entry.starts_with('%')) {  // a comment runs to the end of its line
          for (int c; (c = std::fgetc(f)) != EOF && c != '\n';) {}
          continue;
        }
        if (const auto dot = entry.rfind('.'); dot != std::string_view::npos && dot > 0) out.emplace(entry.substr(0, dot));
      }
      std::fclose(f);
    }
    return out;
  }();
  return names.contains(std::string(word));
}

namespace {
ParsedSentence parse_locked(Parser& p, const std::string& text, std::span<const std::string> words,
                            const std::vector<std::size_t>& starts);
}  // namespace

ParsedSentence parse_sentence(std::span<const std::string> words) {
  ParsedSentence out;
  out.words.resize(words.size());
  out.parts.resize(words.size());
  Parser& p = parser();
  if (!p.dictionary || words.empty() || words.size() > kMaxWords) return out;

  // The sentence as link-grammar reads it, and where each word starts in it.
  std::string text;
  std::vector<std::size_t> starts;
  for (const std::string& w : words) {
    if (!text.empty()) text.push_back(' ');
    starts.push_back(text.size());
    text += w;
  }

  std::lock_guard lock(p.mutex);
  if (const auto hit = p.cache.find(text); hit != p.cache.end()) return hit->second;
  if (p.cache.size() >= kCacheSize) p.cache.clear();
  out = parse_locked(p, text, words, starts);
  p.cache.emplace(text, out);
  return out;
}

namespace {

ParsedSentence parse_locked(Parser& p, const std::string& text, std::span<const std::string> words,
                            const std::vector<std::size_t>& starts) {
  ParsedSentence out;
  out.words.resize(words.size());
  out.parts.resize(words.size());
  const auto word_at = [&](std::size_t byte) -> int {
    const auto it = std::upper_bound(starts.begin(), starts.end(), byte);
    return it == starts.begin() ? -1 : static_cast<int>(it - starts.begin()) - 1;
  };
  Sentence sentence = sentence_create(text.c_str(), p.dictionary);
  if (!sentence) return out;
  const int found = sentence_parse(sentence, p.options);
  const int valid = found > 0 && sentence_null_count(sentence) == 0 ? sentence_num_valid_linkages(sentence) : 0;
  // The lightest linkage is kept as it is, not created again: link-grammar 5.12 leaks 56 bytes each
  // time a sentence's linkage is created a second time (LeakSanitizer and valgrind both saw it).
  Linkage linkage = nullptr;
  double best_weight = 0;
  for (int k = 0; k < std::min(valid, kMaxLinkagesWeighed); ++k) {
    Linkage candidate = linkage_create(k, sentence, p.options);
    if (!candidate) continue;
    const double weight = weigh(candidate, links_of(candidate));
    if (!linkage || weight < best_weight) {
      if (linkage) linkage_delete(linkage);
      linkage = candidate;
      best_weight = weight;
    } else {
      linkage_delete(candidate);
    }
  }
  if (!linkage) {
    sentence_delete(sentence);
    return out;
  }
  out.parsed = true;
  out.cost = linkage_disjunct_cost(linkage);

  // Link-grammar words → input words (the walls and split-off parts map to none or to their word).
  const int n = static_cast<int>(linkage_get_num_words(linkage));
  std::vector<int> to_input(static_cast<std::size_t>(n), -1);
  std::vector<ParsedWord*> slot(static_cast<std::size_t>(n), nullptr);  // where each word's findings go
  std::vector<std::string> base(static_cast<std::size_t>(n));
  for (int w = 0; w < n; ++w) {
    const auto [word, subscript] = split_tag(linkage_get_word(linkage, static_cast<WordIdx>(w)));
    base[static_cast<std::size_t>(w)] = lower(word);
    if (word == "LEFT-WALL" || word == "RIGHT-WALL") continue;
    const int k = word_at(linkage_get_word_byte_start(linkage, static_cast<WordIdx>(w)));
    if (k < 0) continue;
    to_input[static_cast<std::size_t>(w)] = k;
    ParsedWord part;
    part.tag = linkage_get_word(linkage, static_cast<WordIdx>(w));
    part.pos = pos_of(word, subscript);
    if (out.words[static_cast<std::size_t>(k)].tag.empty()) out.words[static_cast<std::size_t>(k)] = std::move(part);
    else out.parts[static_cast<std::size_t>(k)].push_back(std::move(part));
  }
  // Pointers once the part lists no longer grow.
  {
    std::vector<std::size_t> seen(words.size(), 0);
    for (int w = 0; w < n; ++w) {
      const int k = to_input[static_cast<std::size_t>(w)];
      if (k < 0) continue;
      std::size_t& m = seen[static_cast<std::size_t>(k)];
      slot[static_cast<std::size_t>(w)] = m == 0 ? &out.words[static_cast<std::size_t>(k)]
                                                 : &out.parts[static_cast<std::size_t>(k)][m - 1];
      ++m;
    }
  }

  const auto input = [&](int w) -> ParsedWord* { return w >= 0 && w < n ? slot[static_cast<std::size_t>(w)] : nullptr; };
  // A word as the user wrote it, or the part link-grammar split off ('m, 've) as link-grammar has it.
  const auto quoted_word = [&](int w) {
    const int k = to_input[static_cast<std::size_t>(w)];
    const bool whole = k >= 0 && slot[static_cast<std::size_t>(w)] == &out.words[static_cast<std::size_t>(k)] &&
                       out.parts[static_cast<std::size_t>(k)].empty();
    return "'" + (whole ? words[static_cast<std::size_t>(k)] : split_tag(linkage_get_word(linkage, static_cast<WordIdx>(w))).first) + "'";
  };
  for (const Link& l : links_of(linkage)) {
    ParsedWord* left = input(l.left);
    ParsedWord* right = input(l.right);
    if (!left || !right) continue;
    const std::string& lw = base[static_cast<std::size_t>(l.left)];
    const std::string_view t = l.type;
    // Subjects: S links (subject left of its verb), SI/SXI/SFI inverted (verb first, as in questions).
    if (!t.empty() && t[0] == 'S' && t != "SJ") {
      const bool inverted = t.find('I') != std::string_view::npos;
      ParsedWord* subject = inverted ? right : left;
      ParsedWord* verb = inverted ? left : right;
      subject->role = Role::subject;
      if (verb->role == Role::none) verb->role = Role::verb;
      const int s = inverted ? l.right : l.left, v = inverted ? l.left : l.right;
      out.roles += (out.roles.empty() ? "" : "; ") + std::string("subject ") + quoted_word(s) + " → verb " + quoted_word(v);
    } else if (t == "O") {
      right->role = Role::object;
      if (left->role == Role::none) left->role = Role::verb;
      out.roles += (out.roles.empty() ? "" : "; ") + std::string("verb ") + quoted_word(l.left) + " → object " +
                   quoted_word(l.right);
    } else if (t == "I") {
      if (is_one_of(lw, {"do", "does", "did", "don't", "doesn't", "didn't"})) left->do_support = true;
      else if (is_one_of(lw, {"can", "could", "will", "would", "shall", "should", "may", "might", "must", "can't",
                              "won't", "couldn't", "wouldn't", "shouldn't", "mustn't", "'ll", "'d"}))
        left->modal = true;
    } else if (t == "PP") {
      if (is_one_of(lw, {"have", "has", "had", "having", "'ve", "haven't", "hasn't", "hadn't"})) {
        left->perfect = true;
        left->participle = to_input[static_cast<std::size_t>(l.right)];
      }
    } else if (t == "P") {
      // Pg (is going), Pv (was taken): 'be' is an auxiliary here, not the copula.
      left->auxiliary_be = true;
      if (l.passive) right->passive_participle = true;
    }
  }

  if (char* tree = linkage_print_constituent_tree(linkage, SINGLE_LINE)) {
    out.tree = tree;
    linkage_free_constituent_tree_str(tree);
    while (!out.tree.empty() && std::isspace(static_cast<unsigned char>(out.tree.back()))) out.tree.pop_back();
    for (std::size_t at = 0; (at = out.tree.find("(S", at)) != std::string::npos; ++at)
      if (at + 2 < out.tree.size() && (out.tree[at + 2] == ' ' || out.tree.compare(at + 2, 4, "BAR ") == 0)) ++out.clauses;
  }
  linkage_delete(linkage);
  sentence_delete(sentence);
  return out;
}

}  // namespace
}  // namespace gestura::english
