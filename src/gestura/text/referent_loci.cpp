#include "gestura/text/referent_loci.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <unordered_map>
#include <vector>

#include "gestura/core/utf8.hpp"
#include "gestura/text/wordnet.hpp"

namespace gestura {

namespace {

enum class Gender { unknown, male, female, neuter };

struct Referent {
  std::string key;        // the noun's or name's gloss ("BOY", "FS-JOHN"); "" when a pronoun introduced it
  Gender gender = Gender::unknown;
  bool plural = false;
  bool human = true;
  int locus = -1;         // third-person place, -1 while it has none
  std::vector<int> members;  // a group "they" sweeps over: its members' referent indices
  std::size_t introduced = std::string::npos;  // the gloss of its first noun or name mention
  bool needs_index = false;  // a later sign uses its place: set it up after the first mention
  std::size_t last_sentence = 0, last_gloss = 0;
  bool last_subject = false;
};

struct Mention {
  int referent = -1;       // -1: the signer or the addressee (locus person 1 or 2), or nothing
  Locus locus;
  bool possessive = false;
  english::Role role = english::Role::none;
};

// The word a gloss came from: the first source word of its span.
const SourceWord* word_of(std::span<const SourceWord> words, const GlossToken& g) {
  const auto it = std::lower_bound(words.begin(), words.end(), g.begin,
                                   [](const SourceWord& w, std::size_t at) { return w.begin < at; });
  return it != words.end() && it->begin < g.end ? &*it : nullptr;
}

bool ends_with(std::string_view s, std::string_view tail) {
  return s.size() >= tail.size() && s.substr(s.size() - tail.size()) == tail;
}

// Gender from link-grammar's tags (names "John.m", "Sarah.f"; nouns "father.n-m", "mother.n-f")
// and, for the nouns the dictionary leaves unmarked, the English words that name one sex.
Gender gender_of(const SourceWord& w, std::string_view lemma) {
  const std::string& t = w.tag;
  if (ends_with(t, ".m") || ends_with(t, "-m")) return Gender::male;
  if (ends_with(t, ".f") || ends_with(t, "-f")) return Gender::female;
  static const std::unordered_map<std::string_view, Gender> kNouns{
      {"man", Gender::male},       {"boy", Gender::male},        {"father", Gender::male},
      {"dad", Gender::male},       {"son", Gender::male},        {"brother", Gender::male},
      {"husband", Gender::male},   {"uncle", Gender::male},      {"nephew", Gender::male},
      {"grandfather", Gender::male}, {"grandpa", Gender::male},  {"grandson", Gender::male},
      {"boyfriend", Gender::male}, {"king", Gender::male},       {"gentleman", Gender::male},
      {"guy", Gender::male},       {"prince", Gender::male},     {"woman", Gender::female},
      {"girl", Gender::female},    {"mother", Gender::female},   {"mom", Gender::female},
      {"daughter", Gender::female}, {"sister", Gender::female},  {"wife", Gender::female},
      {"aunt", Gender::female},    {"niece", Gender::female},    {"grandmother", Gender::female},
      {"grandma", Gender::female}, {"granddaughter", Gender::female}, {"girlfriend", Gender::female},
      {"queen", Gender::female},   {"lady", Gender::female},     {"princess", Gender::female},
  };
  const auto it = kNouns.find(lemma);
  return it == kNouns.end() ? Gender::unknown : it->second;
}

// The number and gender a third-person pronoun asks of its antecedent; nullopt for other words
// ("this", "those" are pointing of their own, not anaphora).
struct PronounFeatures {
  Gender gender = Gender::unknown;
  bool plural = false;
  bool accusative = false;  // him, her (not possessive), them, it as an object
};
std::optional<PronounFeatures> pronoun_features(std::string_view w, bool possessive) {
  if (w == "he" || w == "his" || w == "himself") return PronounFeatures{Gender::male, false, false};
  if (w == "him") return PronounFeatures{Gender::male, false, true};
  if (w == "she" || w == "hers" || w == "herself") return PronounFeatures{Gender::female, false, false};
  if (w == "her") return PronounFeatures{Gender::female, false, !possessive};
  if (w == "it" || w == "its" || w == "itself") return PronounFeatures{Gender::neuter, false, false};
  if (w == "they" || w == "their" || w == "theirs" || w == "themselves") return PronounFeatures{Gender::unknown, true, false};
  if (w == "them") return PronounFeatures{Gender::unknown, true, true};
  return std::nullopt;
}

bool agrees(const Referent& r, const PronounFeatures& p) {
  if (r.plural != p.plural) return false;
  if (p.plural) return true;
  if (p.gender == Gender::neuter) return !r.human;
  if (!r.human) return false;
  return r.gender == Gender::unknown || r.gender == p.gender;
}

std::string third(const std::string& base_person, int locus, std::string_view tail) {
  // "IX-3" + 'a' + "-PL"
  return base_person + static_cast<char>('a' + locus % 26) + std::string(tail);
}

class Placer {
 public:
  Placer(Translation& t, std::string_view text, std::span<const SourceWord> words, SignInventory& inventory)
      : t_(t), text_(text), words_(words), inventory_(inventory), mentions_(t.glosses.size()) {}

  void run() {
    for (std::size_t s = 0; s < t_.sentences.size(); ++s) {
      const Sentence& sentence = t_.sentences[s];
      std::optional<int> clause_subject;
      for (std::size_t i = sentence.first; i < sentence.last; ++i) {
        if (t_.glosses[i].kind == GlossKind::pause) {
          clause_subject.reset();
          continue;
        }
        mention(s, i, clause_subject);
      }
    }
    for (const Sentence& sentence : t_.sentences) agree(sentence);
    role_shifts();
    introduce_objects_first();
    insert_indices();
  }

 private:
  // Adds to a gloss's reason, and to the explanation of the words it came from.
  void explain(GlossToken& g, const std::string& more) {
    for (WordNote* n : notes_of(g))
      if (n->reason == g.reason) n->reason += more;
    g.reason += more;
  }

  // Adds to the explanation of the words a gloss came from (an index the pass adds after them).
  void explain_words(const GlossToken& g, const std::string& more) {
    for (WordNote* n : notes_of(g)) n->reason += more;
  }

  // The notes of the words inside a gloss's span (the notes are in text order).
  std::vector<WordNote*> notes_of(const GlossToken& g) {
    std::vector<WordNote*> out;
    auto it = std::lower_bound(t_.notes.begin(), t_.notes.end(), g.begin,
                               [](const WordNote& n, std::size_t at) { return n.begin < at; });
    for (; it != t_.notes.end() && it->begin < g.end; ++it)
      if (it->end <= g.end) out.push_back(&*it);
    return out;
  }

  int new_referent(Referent r) {
    if (r.human || r.plural || r.locus >= 0) r.locus = next_locus_++;
    referents_.push_back(std::move(r));
    return static_cast<int>(referents_.size()) - 1;
  }

  int locus_of(int referent) {
    Referent& r = referents_[static_cast<std::size_t>(referent)];
    if (r.locus < 0 && r.members.empty()) r.locus = next_locus_++;
    return r.locus;
  }

  void touch(int referent, std::size_t sentence, std::size_t gloss, english::Role role) {
    Referent& r = referents_[static_cast<std::size_t>(referent)];
    r.last_sentence = sentence;
    r.last_gloss = gloss;
    r.last_subject = role == english::Role::subject;
  }

  // The referent (if any) gloss i mentions, with the pronouns' places resolved.
  void mention(std::size_t sentence, std::size_t i, std::optional<int>& clause_subject) {
    GlossToken& g = t_.glosses[i];
    const SourceWord* w = word_of(words_, g);
    Mention& m = mentions_[i];
    m.role = w ? w->role : english::Role::none;
    const std::string& sign = g.sign();
    if (sign == "IX-1" || sign == "POSS-1" || sign == "SELF-1" || sign == "WE" || sign == "OUR") {
      m.locus = Locus{1, 0};
      m.possessive = sign == "POSS-1" || sign == "OUR";
      return;
    }
    if (sign == "IX-2" || sign == "POSS-2" || sign == "SELF-2") {
      m.locus = Locus{2, 0};
      m.possessive = sign == "POSS-2";
      return;
    }
    if (sign == "IX-3" || sign == "POSS-3" || sign == "IX-3-PL" || sign == "POSS-3-PL") {
      m.possessive = sign.rfind("POSS", 0) == 0;
      const auto features = w ? pronoun_features(w->lower, m.possessive) : std::nullopt;
      if (!features) return;
      const int r = resolve(*features, features->accusative ? clause_subject : std::nullopt);
      m.referent = r;
      touch(r, sentence, i, m.role);
      if (m.role == english::Role::subject) clause_subject = r;
      rewrite_pronoun(g, r);
      m.locus = g.at;
      return;
    }
    if (!w) return;
    // A name: a fingerspelled word written with a capital.
    const bool name = g.kind == GlossKind::fingerspell && !w->lower.empty() &&
                      text_.substr(w->begin, 1) != w->lower.substr(0, 1);
    const bool noun = g.kind == GlossKind::sign && w->pos == english::PartOfSpeech::noun;
    if (!name && !noun) return;
    Referent r;
    r.key = g.gloss;
    std::string lemma = w->lower;
    if (noun) {
      const auto lemmas = wordnet::lemmas(w->lower, english::PartOfSpeech::noun);
      if (!lemmas.empty()) lemma = lemmas.front();
      r.plural = lemma != w->lower && !ends_with(w->lower, "'s");
      r.human = wordnet::names_a_person(lemma);
      if (!r.human && !r.plural) r.gender = Gender::neuter;
    }
    if (r.human) r.gender = gender_of(*w, lemma);
    if (!r.human && noun && r.plural) return;  // things in the plural are not placed here
    const std::string key = r.key + (r.plural ? "+" : "");
    int id = -1;
    if (const auto it = by_key_.find(key); it != by_key_.end()) id = it->second;
    if (id < 0) {
      r.introduced = i;
      r.needs_index = r.human && r.plural;  // the arc shows the plural the lexicon's sign lacks
      id = new_referent(std::move(r));
      by_key_.emplace(key, id);
    }
    m.referent = id;
    touch(id, sentence, i, m.role);
    if (m.role == english::Role::subject) clause_subject = id;
    const int locus = referents_[static_cast<std::size_t>(id)].locus;
    if (locus >= 0) m.locus = Locus{3, locus};
  }

  // The antecedent of a pronoun: an earlier referent that agrees, the same gender before an
  // unknown one, then the one mentioned last as a subject in the latest sentence, then the latest;
  // a new referent when none agrees. `not_this` is the clause's subject for an object pronoun.
  int resolve(const PronounFeatures& p, std::optional<int> not_this) {
    int best = -1;
    auto rank = [&](const Referent& r) {
      const bool exact = r.gender == p.gender || p.plural;
      return std::tuple(exact, r.last_sentence, r.last_subject, r.last_gloss);
    };
    // Antecedents are recent: only the last kWindow referents are candidates (this also keeps a
    // long text linear).
    const std::size_t window_start = referents_.size() > kWindow ? referents_.size() - kWindow : 0;
    for (std::size_t k = window_start; k < referents_.size(); ++k) {
      const Referent& r = referents_[k];
      if (!agrees(r, p) || (not_this && *not_this == static_cast<int>(k))) continue;
      if (best < 0 || rank(r) > rank(referents_[static_cast<std::size_t>(best)])) best = static_cast<int>(k);
    }
    if (best >= 0) {
      Referent& r = referents_[static_cast<std::size_t>(best)];
      if (r.gender == Gender::unknown && !p.plural) r.gender = p.gender;
      r.needs_index = true;
      return best;
    }
    Referent r;
    r.gender = p.gender;
    r.plural = p.plural;
    r.human = p.gender != Gender::neuter;
    if (p.plural) {
      // "they" with no plural antecedent: the people already placed, when there are several.
      for (std::size_t k = window_start; k < referents_.size() && r.members.size() < 4; ++k)
        if (referents_[k].human && !referents_[k].plural && referents_[k].locus >= 0 &&
            !(not_this && *not_this == static_cast<int>(k)))
          r.members.push_back(static_cast<int>(k));
      if (r.members.size() < 2) r.members.clear();
      if (!r.members.empty()) {
        for (int k : r.members) referents_[static_cast<std::size_t>(k)].needs_index = true;
        referents_.push_back(std::move(r));
        return static_cast<int>(referents_.size()) - 1;
      }
    }
    r.locus = 0;  // placed now, even a thing ("it" with no antecedent points somewhere)
    return new_referent(std::move(r));
  }

  void rewrite_pronoun(GlossToken& g, int referent) {
    const std::string base = g.sign();
    const bool plural = ends_with(base, "-PL");
    const std::string stem = plural ? base.substr(0, base.size() - 3) : base;  // "IX-3", "POSS-3"
    g.lexeme = base;
    const Referent& r = referents_[static_cast<std::size_t>(referent)];
    if (!r.members.empty()) {
      std::string places;
      for (int k : r.members) {
        const Locus l{3, referents_[static_cast<std::size_t>(k)].locus};
        g.over.push_back(l);
        places += (places.empty() ? "" : "+") + l.name();
      }
      g.gloss = base + ":" + places;
      explain(g, "; an arc over the places of those placed (" + places + ")");
      return;
    }
    const int locus = locus_of(referent);
    g.at = Locus{3, locus};
    g.gloss = third(stem, locus, plural ? "-PL" : "");
    explain(g, "; points at place " + g.at.name() + (r.key.empty() ? "" : " (" + r.key + ")"));
  }

  // Agreement verbs take their subject's and object's places.
  void agree(const Sentence& sentence) {
    std::size_t clause_start = sentence.first;
    for (std::size_t i = sentence.first; i < sentence.last; ++i) {
      GlossToken& g = t_.glosses[i];
      if (g.kind == GlossKind::pause) {
        clause_start = i + 1;
        continue;
      }
      if (g.kind != GlossKind::sign) continue;
      // The lexicon entry says whether the sign agrees (its `agreement` field, docs/grammar.md).
      const Agreement agreement = inventory_.agreement_of(g.sign());
      const bool backward = agreement == Agreement::backward;
      if (agreement == Agreement::none) continue;
      // Subject and object are looked for within kReach glosses of the verb, in its clause.
      std::size_t clause_end = i;
      while (clause_end < sentence.last && clause_end - i <= kReach && t_.glosses[clause_end].kind != GlossKind::pause)
        ++clause_end;
      const std::size_t near_start = std::max(clause_start, i > kReach ? i - kReach : std::size_t{0});
      std::optional<std::size_t> subject, object;
      for (std::size_t k = near_start; k < i; ++k) {
        const Mention& m = mentions_[k];
        if (!is_person(m) || m.possessive) continue;
        if (!subject || m.role == english::Role::subject || mentions_[*subject].role != english::Role::subject) subject = k;
      }
      for (std::size_t k = i + 1; k < clause_end; ++k) {
        const Mention& m = mentions_[k];
        if (!is_person(m) || m.possessive || m.role == english::Role::subject) continue;
        if (!object || (m.role == english::Role::object && mentions_[*object].role != english::Role::object)) object = k;
        if (m.role == english::Role::object) break;
      }
      if (!object) continue;  // no one to move toward: the citation form
      // An imperative (the verb opens its clause, no subject): the addressee does it.
      const bool content_before = std::any_of(t_.glosses.begin() + static_cast<std::ptrdiff_t>(near_start),
                                              t_.glosses.begin() + static_cast<std::ptrdiff_t>(i),
                                              [](const GlossToken& x) { return x.kind != GlossKind::pause; });
      // A subject that is no person ("Art helps children") has no place to start from: citation start.
      const bool thing_subject = !subject && std::any_of(mentions_.begin() + static_cast<std::ptrdiff_t>(near_start),
                                                         mentions_.begin() + static_cast<std::ptrdiff_t>(i),
                                                         [](const Mention& m) { return m.role == english::Role::subject; });
      if (thing_subject) continue;
      Locus from = subject ? place_of(*subject) : content_before ? Locus{1, 0} : Locus{2, 0};
      Locus to = place_of(*object);
      if (!from || !to || from == to) continue;
      if (backward) std::swap(from, to);
      g.lexeme = g.sign();
      g.from = from;
      g.to = to;
      g.gloss = g.lexeme + ":" + from.name() + "→" + to.name();
      explain(g, "; agreement verb, from " + from.name() + " to " + to.name() +
                     (backward ? " (a backwards verb: from the object to the subject)" : ""));
      for (std::size_t k : {subject.value_or(i), *object})
        if (k != i && mentions_[k].referent >= 0) referents_[static_cast<std::size_t>(mentions_[k].referent)].needs_index = true;
      // A person first named after the verb has no place yet when the verb moves there.
      const int named = mentions_[*object].referent;
      if (*object > i && named >= 0 && referents_[static_cast<std::size_t>(named)].introduced == *object)
        late_objects_.push_back(LateObject{i, *object});
    }
  }

  // A signer sets a referent up before a verb is directed at its place: the object named after an
  // agreement verb ("The teacher helped the boy.") is signed, with its index, before the verb —
  // TEACHER IX-3a BOY IX-3b HELP:3a→3b. The verb's movement shows who does what to whom, which is
  // why ASL allows the object before an agreement verb (Fischer 1975; Liddell 2003: a verb is directed
  // at a place the discourse has already given). The words between the verb and the object
  // (LITTLE in "helped the little boy", POSS-3a in "helped her son") go with the object. Not done
  // across a pause, a role-shift or marker boundary, or over another person named or pointed at.
  void introduce_objects_first() {
    for (const LateObject& late : late_objects_) {
      const std::size_t verb = late.verb, object = late.object;
      bool movable = object < t_.glosses.size();
      for (std::size_t k = verb + 1; k < object && movable; ++k)
        movable = t_.glosses[k].kind != GlossKind::pause &&
                  (mentions_[k].possessive || !(mentions_[k].referent >= 0 || mentions_[k].locus));
      const auto inside = [&](std::size_t boundary) { return boundary > verb && boundary <= object; };
      for (const Marker& m : t_.markers) movable = movable && !inside(m.first) && !inside(m.last);
      for (const RoleShift& r : t_.role_shifts) movable = movable && !inside(r.first) && !inside(r.last);
      if (!movable) continue;
      // Rotate [verb, object] left by one: the verb goes after the object.
      std::rotate(t_.glosses.begin() + static_cast<std::ptrdiff_t>(verb),
                  t_.glosses.begin() + static_cast<std::ptrdiff_t>(verb) + 1,
                  t_.glosses.begin() + static_cast<std::ptrdiff_t>(object) + 1);
      std::rotate(mentions_.begin() + static_cast<std::ptrdiff_t>(verb),
                  mentions_.begin() + static_cast<std::ptrdiff_t>(verb) + 1,
                  mentions_.begin() + static_cast<std::ptrdiff_t>(object) + 1);
      const auto moved = [&](std::size_t k) { return k == verb ? object : k > verb && k <= object ? k - 1 : k; };
      for (Referent& r : referents_)
        if (r.introduced != std::string::npos) r.introduced = moved(r.introduced);
      for (LateObject& other : late_objects_) {
        if (&other == &late) continue;
        other.verb = moved(other.verb);
        other.object = moved(other.object);
      }
      explain(t_.glosses[object], "; signed after its object, which is set up first");
    }
  }

  // Whether a mention is of someone who can give, be told or be quoted: the signer, the addressee,
  // or a person placed in space (things, like the book given, are not).
  bool is_person(const Mention& m) const {
    if (m.referent >= 0) return referents_[static_cast<std::size_t>(m.referent)].human;
    return static_cast<bool>(m.locus);
  }

  Locus place_of(std::size_t gloss) {
    const Mention& m = mentions_[gloss];
    if (m.locus) return m.locus;
    if (m.referent < 0) return {};
    const int locus = locus_of(m.referent);
    if (locus < 0) return {};
    mentions_[gloss].locus = Locus{3, locus};
    return mentions_[gloss].locus;
  }

  // Quoted speech: the glosses inside a pair of quotation marks, signed as the person quoted —
  // the subject of the sentence around the quote ("She said, '…'", "'…,' he said").
  void role_shifts() {
    std::vector<std::size_t> marks;
    for (std::size_t pos = 0; pos < text_.size();) {
      const std::size_t at = pos;
      const char32_t c = utf8::next(text_, pos);
      if (c == '"' || c == 0x201C || c == 0x201D || c == 0x201E || c == 0xAB || c == 0xBB) marks.push_back(at);
    }
    sentence_index_.assign(t_.glosses.size(), t_.sentences.size());
    for (std::size_t s = 0; s < t_.sentences.size(); ++s)
      for (std::size_t i = t_.sentences[s].first; i < t_.sentences[s].last && i < t_.glosses.size(); ++i) sentence_index_[i] = s;
    for (std::size_t i = 0; i < t_.glosses.size(); ++i)  // a pause between sentences goes with the one before
      if (sentence_index_[i] == t_.sentences.size() && i > 0) sentence_index_[i] = sentence_index_[i - 1];
    std::size_t cursor = 0;  // glosses come in text order: one pass over them for all quotes
    for (std::size_t q = 0; q + 1 < marks.size(); q += 2) {
      const std::size_t open = marks[q], close = marks[q + 1];
      while (cursor < t_.glosses.size() && t_.glosses[cursor].begin <= open) ++cursor;
      std::size_t first = t_.glosses.size(), last = 0;
      for (std::size_t i = cursor; i < t_.glosses.size() && t_.glosses[i].begin < close; ++i)
        if (t_.glosses[i].kind != GlossKind::pause && t_.glosses[i].end <= close) {
          first = std::min(first, i);
          last = i + 1;
        }
      if (first >= last) continue;
      // The speaker: a third-person mention outside the quote in the same sentence or the ones
      // around it, a subject first, the nearest first.
      std::optional<std::size_t> speaker;
      auto consider = [&](std::size_t k) {
        const Mention& m = mentions_[k];
        if (!is_person(m) || m.possessive) return;
        if (!speaker || (m.role == english::Role::subject && mentions_[*speaker].role != english::Role::subject))
          speaker = k;
      };
      const std::size_t sentence_before = sentence_of(first);
      const std::size_t sentence_after = sentence_of(last - 1);
      for (std::size_t k = first; k-- > 0 && first - k <= kReach && sentence_of(k) + 1 >= sentence_before;) consider(k);
      if (!speaker || mentions_[*speaker].role != english::Role::subject)
        for (std::size_t k = last; k < t_.glosses.size() && k - last < kReach && sentence_of(k) <= sentence_after + 1; ++k)
          consider(k);
      if (!speaker) continue;
      const Locus toward = place_of(*speaker);
      if (toward.person != 3) continue;  // the signer quoting themselves needs no shift
      if (mentions_[*speaker].referent >= 0) referents_[static_cast<std::size_t>(mentions_[*speaker].referent)].needs_index = true;
      t_.role_shifts.push_back(RoleShift{first, last, toward});
    }
  }

  std::size_t sentence_of(std::size_t gloss) const {
    return gloss < sentence_index_.size() ? sentence_index_[gloss] : t_.sentences.size();
  }

  // An index after the first mention of each noun or name whose place is used later.
  void insert_indices() {
    std::vector<std::vector<GlossToken>> after(t_.glosses.size());
    for (const Referent& r : referents_) {
      if (!r.needs_index || r.introduced == std::string::npos || r.locus < 0) continue;
      const GlossToken& noun = t_.glosses[r.introduced];
      GlossToken ix;
      ix.kind = GlossKind::sign;
      ix.begin = noun.begin;
      ix.end = noun.end;
      ix.lexeme = r.plural ? "IX-3-PL" : "IX-3";
      ix.at = Locus{3, r.locus};
      ix.gloss = third("IX-3", r.locus, r.plural ? "-PL" : "");
      ix.reason = "'" + std::string(text_.substr(noun.begin, noun.end - noun.begin)) + "' → " + ix.gloss +
                  (r.plural ? ": a plural referent, set up by an arc over place " : ": a referent, set up at place ") +
                  ix.at.name();
      explain_words(noun, "; then " + ix.gloss + (r.plural ? " (an arc over place " : " (sets up place ") + ix.at.name() + ")");
      after[r.introduced].push_back(std::move(ix));
    }
    if (std::all_of(after.begin(), after.end(), [](const auto& v) { return v.empty(); })) return;
    std::vector<std::size_t> map(t_.glosses.size() + 1);
    std::vector<GlossToken> out;
    for (std::size_t i = 0; i < t_.glosses.size(); ++i) {
      map[i] = out.size();
      out.push_back(std::move(t_.glosses[i]));
      for (GlossToken& g : after[i]) out.push_back(std::move(g));
    }
    map[t_.glosses.size()] = out.size();
    t_.glosses = std::move(out);
    for (Sentence& s : t_.sentences) {
      s.first = map[s.first];
      s.last = map[s.last];
    }
    for (Marker& m : t_.markers) {
      m.first = map[m.first];
      m.last = map[m.last];
    }
    for (RoleShift& r : t_.role_shifts) {
      r.first = map[r.first];
      r.last = map[r.last];
    }
  }

  Translation& t_;
  std::string_view text_;
  std::span<const SourceWord> words_;
  SignInventory& inventory_;
  std::vector<Mention> mentions_;
  std::vector<Referent> referents_;
  std::unordered_map<std::string, int> by_key_;  // a noun's or name's gloss → its referent
  std::vector<std::size_t> sentence_index_;      // each gloss's sentence
  struct LateObject {
    std::size_t verb, object;  // gloss indices: an agreement verb and the person first named after it
  };
  std::vector<LateObject> late_objects_;
  int next_locus_ = 0;
  static constexpr std::size_t kWindow = 32;
  static constexpr std::size_t kReach = 24;
};

}  // namespace

void place_referents(Translation& translation, std::string_view text, std::span<const SourceWord> words,
                     SignInventory& inventory) {
  Placer(translation, text, words, inventory).run();
}

}  // namespace gestura
