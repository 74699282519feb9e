#include "gestura/text/translator.hpp"

#include <algorithm>
#include <array>
#include <optional>

#include "gestura/text/english_parse.hpp"
#include "gestura/text/english_words.hpp"
#include "gestura/text/lemmatizer.hpp"
#include "gestura/text/referent_loci.hpp"
#include "gestura/text/tokenizer.hpp"
#include "gestura/text/wordnet.hpp"
#include "gestura/core/utf8.hpp"

namespace gestura {

namespace {

// One source word after contraction expansion ("don't" gives two words sharing one span).
struct Word {
  TokenKind kind;
  std::string text;   // as written (apostrophes folded)
  std::string lower;
  std::size_t begin, end;
  bool capitalized;
};

// passive_verb: the participle of a passive; agent: the signs of its by-phrase, which go before it.
enum class Role { plain, time, wh, negation_moved, negation_in_place, pause, passive_verb, agent };

struct Item {
  GlossToken token;
  Role role;
};

bool is_capitalized(std::string_view text) {
  std::size_t pos = 0;
  const char32_t first = utf8::next(text, pos);
  return utf8::to_lower(first) != first;
}

std::string quoted(std::string_view word) {
  std::string out;
  out.reserve(word.size() + 2);
  out.push_back('\'');
  out.append(word);
  out.push_back('\'');
  return out;
}

GlossToken make(std::string gloss, GlossKind kind, const Word& from, std::string reason) {
  return GlossToken{std::move(gloss), kind, from.begin, from.end, {}, std::move(reason)};
}

std::string digits_only(std::string_view number) {
  std::string out;
  for (char c : number)
    if (c != ',') out.push_back(c);
  return out;
}

std::optional<int> to_int(std::string_view text) {
  if (text.empty() || text.size() > 9) return std::nullopt;
  int v = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + (c - '0');
  }
  return v;
}

std::vector<std::string_view> split(std::string_view text, char by) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i)
    if (i == text.size() || text[i] == by) {
      parts.push_back(text.substr(start, i - start));
      start = i + 1;
    }
  return parts;
}

class SentenceTranslator {
 public:
  // initial_name: the capitalised word opening the sentence is a given name (opens_with_given_name).
  SentenceTranslator(std::vector<Word> words, english::ParsedSentence parse, bool question, bool initial_name,
                     SignInventory& inventory, std::vector<WordNote>& notes)
      : w_(std::move(words)), parse_(std::move(parse)), question_(question), initial_name_(initial_name),
        inventory_(inventory), notes_(notes) {
    while (first_word_ < w_.size() && w_[first_word_].kind != TokenKind::word &&
           w_[first_word_].kind != TokenKind::number)
      ++first_word_;
    all_caps_ = std::none_of(w_.begin(), w_.end(), [](const Word& w) {
      return w.kind == TokenKind::word && w.text != utf8::upper(w.text) && w.lower != w.text;
    });
    // A sentence in capitals and a mixed one both start with a capital; only mixed case tells names apart.
    all_caps_ = all_caps_ && std::any_of(w_.begin(), w_.end(), [](const Word& w) { return w.kind == TokenKind::word && w.text.size() > 1; });
  }

  std::vector<Item> run() {
    for (i_ = 0; i_ < w_.size();) step();
    return std::move(items_);
  }

  bool has_wh() const { return has_wh_; }

 private:
  const Word* at(std::size_t k) const { return k < w_.size() ? &w_[k] : nullptr; }
  bool word_is(std::size_t k, std::string_view lower) const {
    return k < w_.size() && w_[k].kind == TokenKind::word && w_[k].lower == lower;
  }

  // What the parser says of word k, or nullptr when the sentence did not parse.
  const english::ParsedWord* parsed(std::size_t k) const {
    return parse_.parsed && k < parse_.words.size() ? &parse_.words[k] : nullptr;
  }

  void note(const Word& w, std::string reason) { notes_.push_back(WordNote{w.text, w.begin, w.end, std::move(reason)}); }
  void emit(GlossToken token, Role role) {
    if (role == Role::pause) by_agent_ = false;
    if (role == Role::plain && by_agent_) role = Role::agent;
    items_.push_back(Item{std::move(token), role});
  }
  void drop(const Word& w, std::string_view why) { note(w, quoted(w.text) + " dropped: " + std::string(why)); }

  void step() {
    const Word& w = w_[i_];
    switch (w.kind) {
      case TokenKind::pause:
        if (!items_.empty() && items_.back().role != Role::pause)
          emit(make("PAUSE", GlossKind::pause, w, quoted(w.text) + " → pause"), Role::pause);
        ++i_;
        return;
      case TokenKind::symbol:
        if (money()) return;
        note(w, quoted(w.text) + " dropped: symbol without a number");
        ++i_;
        return;
      case TokenKind::number:
        number();
        return;
      case TokenKind::word:
      case TokenKind::sentence_end:
        break;
    }
    if (phrase() || number_words() || month_date() || lexicon_phrase()) return;
    word();
  }

  // Fixed phrases, longest match first.
  bool phrase() {
    for (const english::Phrase* p : english::phrases_starting_with(w_[i_].lower)) {
      bool match = true;
      for (std::size_t k = 0; k < p->words.size() && match; ++k) match = word_is(i_ + k, p->words[k]);
      if (!match) continue;
      const Word& first = w_[i_];
      const Word& last = w_[i_ + p->words.size() - 1];
      std::string phrase_text;
      for (std::size_t k = 0; k < p->words.size(); ++k) phrase_text += (k ? " " : "") + w_[i_ + k].lower;
      std::string glosses;
      for (auto g : p->glosses) {
        if (!glosses.empty()) glosses.push_back(' ');
        glosses.append(g);
      }
      const std::string reason = quoted(phrase_text) + " → " + glosses + ": fixed phrase";
      const Role role = p->role == english::PhraseRole::time  ? Role::time
                        : p->role == english::PhraseRole::wh  ? Role::wh
                        : p->role == english::PhraseRole::negation ? Role::negation_in_place
                                                                   : Role::plain;
      if (role == Role::wh) has_wh_ = true;
      for (auto g : p->glosses) {
        GlossToken t{std::string(g), GlossKind::sign, first.begin, last.end, {}, reason};
        emit(std::move(t), role);
      }
      for (std::size_t k = 0; k < p->words.size(); ++k) note(w_[i_ + k], reason);
      i_ += p->words.size();
      return true;
    }
    return false;
  }

  // A keyword of several words in the lexicon ("train station", "wake up", "next to"), longest first;
  // the first or the last word may be inflected ("woke up", "credit cards").
  bool lexicon_phrase() {
    if (inventory_.open_vocabulary()) return false;  // it would take any run of words as one sign
    constexpr std::size_t kLongest = 4;
    for (std::size_t n = kLongest; n >= 2; --n) {
      if (i_ + n > w_.size()) continue;
      bool words = true;
      for (std::size_t k = 0; k < n && words; ++k) words = w_[i_ + k].kind == TokenKind::word;
      if (!words) continue;
      std::string middle;
      for (std::size_t k = 1; k + 1 < n; ++k) middle += w_[i_ + k].lower + " ";
      for (const LemmaCandidate& first : lemma_candidates(w_[i_].lower))
        for (const LemmaCandidate& last : lemma_candidates(w_[i_ + n - 1].lower)) {
          const std::string text = first.lemma + " " + middle + last.lemma;
          const auto gloss = inventory_.gloss_for(text);
          if (!gloss) continue;
          const Word& from = w_[i_];
          const Word& to = w_[i_ + n - 1];
          const Role role = english::is_wh_word(from.lower) && question_ ? Role::wh : Role::plain;
          if (role == Role::wh) has_wh_ = true;
          std::string said;
          for (std::size_t k = 0; k < n; ++k) said += (k ? " " : "") + w_[i_ + k].text;
          const std::string reason = quoted(said) + " → " + *gloss + ": lexicon phrase " + quoted(text);
          emit(GlossToken{*gloss, GlossKind::sign, from.begin, to.end, {}, reason}, role);
          for (std::size_t k = 0; k < n; ++k) note(w_[i_ + k], reason);
          i_ += n;
          return true;
        }
    }
    return false;
  }

  // "$5" → 5 DOLLAR, "$5.50" → 5 DOLLAR 50 CENT.
  bool money() {
    const Word& sym = w_[i_];
    std::string_view unit = sym.text == "$" ? "DOLLAR" : sym.text == "€" ? "EURO" : sym.text == "£" ? "POUND" : "";
    const Word* amount = at(i_ + 1);
    if (unit.empty() || !amount || amount->kind != TokenKind::number) return false;
    const std::string digits = digits_only(amount->text);
    const auto parts = split(digits, '.');
    const std::string reason = quoted(sym.text + amount->text) + " → money: amount then " + std::string(unit);
    Word span = *amount;
    span.begin = sym.begin;
    emit(make(std::string(parts[0]), GlossKind::number, span, reason), Role::plain);
    emit(make(std::string(unit), GlossKind::sign, span, reason), Role::plain);
    if (parts.size() == 2 && to_int(parts[1]).value_or(0) > 0) {
      emit(make(std::to_string(*to_int(parts[1])), GlossKind::number, span, reason), Role::plain);
      emit(make("CENT", GlossKind::sign, span, reason), Role::plain);
    }
    note(sym, reason);
    note(*amount, reason);
    i_ += 2;
    return true;
  }

  // The time of day a following "am"/"pm" adds, if any; consumes it.
  void day_part(int hour) {
    const Word* next = at(i_);
    if (!next || next->kind != TokenKind::word) return;
    const std::string& l = next->lower;
    const bool am = l == "am" || l == "a.m." || l == "a.m";
    const bool pm = l == "pm" || l == "p.m." || l == "p.m";
    if (!am && !pm) return;
    const char* part = am ? "MORNING" : hour >= 6 && hour != 12 ? "NIGHT" : "AFTERNOON";
    const std::string reason = quoted(next->text) + " → " + part + ": time of day";
    emit(make(part, GlossKind::sign, *next, reason), Role::time);
    note(*next, reason);
    ++i_;
  }

  void emit_date(int month_number, int day, std::optional<int> year, const Word& span, const std::string& reason) {
    const auto m = english::month(month_number);
    GlossToken fs = make("FS-" + std::string(m->letters), GlossKind::fingerspell, span, reason);
    for (char c : m->letters) fs.letters.emplace_back(1, c);
    emit(std::move(fs), Role::time);
    emit(make(std::to_string(day), GlossKind::number, span, reason), Role::time);
    if (year) emit(make(std::to_string(*year), GlossKind::number, span, reason), Role::time);
  }

  void number() {
    const Word& w = w_[i_];
    ++i_;
    const std::string& t = w.text;
    // 3:30 → TIME 3 30
    if (const auto colon = split(t, ':'); colon.size() == 2 && to_int(colon[0]) && to_int(colon[1])) {
      const std::string reason = quoted(t) + " → TIME hour minutes: clock time";
      emit(make("TIME", GlossKind::sign, w, reason), Role::time);
      emit(make(std::to_string(*to_int(colon[0])), GlossKind::number, w, reason), Role::time);
      if (*to_int(colon[1]) != 0) emit(make(std::string(colon[1]), GlossKind::number, w, reason), Role::time);
      note(w, reason);
      day_part(*to_int(colon[0]));
      return;
    }
    // 3/14/2024 (month/day/year, US order) and 2024-03-14 (ISO) → month fingerspelled, day, year
    const auto slash = split(t, '/');
    const auto dash = split(t, '-');
    std::optional<int> m, d, y;
    if (slash.size() >= 2 && slash.size() <= 3) {
      m = to_int(slash[0]);
      d = to_int(slash[1]);
      if (slash.size() == 3) y = to_int(slash[2]);
    } else if (dash.size() == 3 && dash[0].size() == 4) {
      y = to_int(dash[0]);
      m = to_int(dash[1]);
      d = to_int(dash[2]);
    }
    if (m && d && *m >= 1 && *m <= 12 && *d >= 1 && *d <= 31) {
      const std::string reason = quoted(t) + " → month (fingerspelled) day" + (y ? " year" : "") + ": date";
      emit_date(*m, *d, y, w, reason);
      note(w, reason);
      return;
    }
    // 50% → 50 PERCENT
    if (const Word* next = at(i_); next && next->kind == TokenKind::symbol && next->text == "%") {
      const std::string reason = quoted(t + "%") + " → number PERCENT";
      emit(make(digits_only(t), GlossKind::number, w, reason), Role::plain);
      emit(make("PERCENT", GlossKind::sign, *next, reason), Role::plain);
      note(w, reason);
      note(*next, reason);
      ++i_;
      return;
    }
    const std::string plain = digits_only(t);
    const bool ordinal = !plain.empty() && !utf8::is_digit(static_cast<unsigned char>(plain.back()));
    // A bare hour before am/pm ("3pm", "3 p.m.") is a clock time too.
    if (const Word* next = at(i_); !ordinal && next && next->kind == TokenKind::word &&
                                   (next->lower == "am" || next->lower == "pm" || next->lower == "a.m." ||
                                    next->lower == "p.m." || next->lower == "o'clock") &&
                                   to_int(plain) && *to_int(plain) <= 12) {
      const std::string reason = quoted(t) + " → TIME hour: clock time";
      emit(make("TIME", GlossKind::sign, w, reason), Role::time);
      emit(make(plain, GlossKind::number, w, reason), Role::time);
      note(w, reason);
      if (next->lower == "o'clock") {
        drop(*next, "the clock time is already signed");
        ++i_;
      } else {
        day_part(*to_int(plain));
      }
      return;
    }
    // A year after "in"/"since" ("in 2020") is a time expression and opens the sentence.
    const bool year = to_int(plain) && *to_int(plain) >= 1000 && *to_int(plain) <= 2199 && i_ >= 2 &&
                      (word_is(i_ - 2, "in") || word_is(i_ - 2, "since"));
    std::string gloss = plain;
    std::transform(gloss.begin(), gloss.end(), gloss.begin(),
                   [](unsigned char c) { return static_cast<char>(c >= 'a' && c <= 'z' ? c - 32 : c); });
    const std::string reason = quoted(t) + " → " + gloss + (ordinal ? ": ordinal number" : year ? ": year" : ": number");
    emit(make(gloss, GlossKind::number, w, reason), year ? Role::time : Role::plain);
    note(w, reason);
  }

  // "twenty five" → 25, "two hundred" → 200, "twenty-one" → 21.
  bool number_words() {
    long long total = 0, current = 0;
    std::size_t k = i_;
    bool any = false;
    while (k < w_.size() && w_[k].kind == TokenKind::word) {
      bool part_ok = true;
      for (auto part : split(w_[k].lower, '-')) {
        const auto v = english::number_word(part);
        if (!v) {
          part_ok = false;
          break;
        }
        if (*v == 100) current = (current ? current : 1) * 100;
        else if (*v >= 1000) {
          total += (current ? current : 1) * *v;
          current = 0;
        } else current += *v;
      }
      if (!part_ok) break;
      any = true;
      ++k;
      if (word_is(k, "and") && k + 1 < w_.size() && english::number_word(w_[k + 1].lower)) ++k;
    }
    if (!any) return false;
    // "one" alone before a non-number is often a pronoun ("the red one"); still a number sign in ASL.
    Word span = w_[i_];
    span.end = w_[k - 1].end;
    const long long value = total + current;
    std::string phrase_text;
    for (std::size_t j = i_; j < k; ++j) phrase_text += (j > i_ ? " " : "") + w_[j].text;
    const std::string reason = quoted(phrase_text) + " → " + std::to_string(value) + ": number word";
    emit(make(std::to_string(value), GlossKind::number, span, reason), Role::plain);
    for (std::size_t j = i_; j < k; ++j) note(w_[j], reason);
    i_ = k;
    return true;
  }

  // "March 14", "March 14, 2024", "14 March" → month fingerspelled, day (, year).
  bool month_date() {
    const Word& w = w_[i_];
    const auto m = english::month(w.lower);
    if (!m) return false;
    const Word* day = at(i_ + 1);
    const auto day_value = day && day->kind == TokenKind::number ? to_int(digits_only(day->text).substr(
                                                                       0, std::min<std::size_t>(2, day->text.size())))
                                                                 : std::nullopt;
    const bool adjacent_number = day_value && *day_value >= 1 && *day_value <= 31;
    if (!adjacent_number && (w.lower == "may" || w.lower == "march" || !w.capitalized)) return false;
    if (!adjacent_number) {
      const std::string reason = quoted(w.text) + " → FS-" + std::string(m->letters) + ": month, fingerspelled";
      GlossToken fs = make("FS-" + std::string(m->letters), GlossKind::fingerspell, w, reason);
      for (char c : m->letters) fs.letters.emplace_back(1, c);
      emit(std::move(fs), Role::time);
      note(w, reason);
      ++i_;
      return true;
    }
    std::optional<int> year;
    std::size_t k = i_ + 2;
    if (k < w_.size() && w_[k].kind == TokenKind::pause && w_[k].text == ",") ++k;
    if (k < w_.size() && w_[k].kind == TokenKind::number && w_[k].text.size() == 4 && to_int(w_[k].text))
      year = to_int(w_[k].text);
    else
      k = i_ + 2;
    if (year) ++k;
    Word span = w;
    span.end = w_[k - 1].end;
    const std::string reason =
        quoted(w.text + " " + day->text + (year ? " " + std::to_string(*year) : "")) + " → month (fingerspelled) day" +
        (year ? " year" : "") + ": date";
    emit_date(m->number, *day_value, year, span, reason);
    for (std::size_t j = i_; j < k; ++j) note(w_[j], reason);
    i_ = k;
    return true;
  }

  // No word or number before the current one (pauses and symbols may precede it).
  bool sentence_initial() const { return i_ <= first_word_; }

  // Do-support: "do not", and an auxiliary "do" opening a question or following its wh-word.
  bool is_do_support() const {
    if (!english::is_auxiliary_do(w_[i_].lower)) return false;
    if (word_is(i_ + 1, "not")) return true;
    // The parse knows: 'do' linked to a later verb (I link) supports it; 'do' with an object is DO.
    if (const english::ParsedWord* p = parsed(i_)) return p->do_support;
    if (!question_) return false;
    if (sentence_initial()) return true;
    // "where do you live", "how many dogs do you have": do between the wh-phrase and the subject.
    const Word* next = at(i_ + 1);
    return (next && next->kind == TokenKind::word && english::pronoun_gloss(next->lower)) ||
           (i_ > 0 && w_[i_ - 1].kind == TokenKind::word && english::is_wh_word(w_[i_ - 1].lower));
  }

  // A perfect that reports a completed action (have eaten) is FINISH; one of duration or experience
  // (have been waiting, have lived here for years, has never seen, haven't seen) is not.
  bool completed_action() const {
    const english::ParsedWord* p = parsed(i_);
    if (p && p->participle >= 0 && w_[static_cast<std::size_t>(p->participle)].lower == "been") return false;
    return std::none_of(w_.begin(), w_.end(), [](const Word& w) {
      return w.kind == TokenKind::word && (w.lower == "for" || w.lower == "since" || w.lower == "never" ||
                                           w.lower == "not" || w.lower == "long" || w.lower == "ever" ||
                                           w.lower == "yet");
    });
  }

  bool next_is_content_word() const {
    const Word* next = at(i_ + 1);
    if (!next || next->kind != TokenKind::word) return false;
    return english::dropped(next->lower) == english::DropReason::none && !english::pronoun_gloss(next->lower) &&
           !english::time_gloss(next->lower) && !english::is_auxiliary(next->lower) && next->lower != "not";
  }

  // "have eaten", "has gone", "had finished": the next word reads as a past form.
  bool next_is_participle() const {
    const Word* next = at(i_ + 1);
    if (!next || next->kind != TokenKind::word) return false;
    const auto rule = lemma_candidates(next->lower).front().rule;
    return rule == "irregular participle" || rule == "irregular past" || rule == "past -ed" || rule == "past -ied";
  }

  void fingerspell(const Word& w, std::string why) {
    GlossToken t = make("", GlossKind::fingerspell, w, "");
    std::string name;
    bool outside_alphabet = false;
    for (std::size_t pos = 0; pos < w.text.size();) {
      const char32_t cp = utf8::next(w.text, pos);
      if (!utf8::is_letter(cp) || utf8::is_mark(cp)) {  // a mark left over belongs to the letter before it
        if (cp == '-') name.push_back('-');
        continue;
      }
      const char32_t letter = utf8::to_upper(utf8::base_letter(cp));
      std::string spelled;
      utf8::append(spelled, letter);
      outside_alphabet |= letter < 'A' || letter > 'Z';
      name += spelled;
      t.letters.push_back(std::move(spelled));
    }
    t.gloss = "FS-" + name;
    t.reason = quoted(w.text) + " fingerspelled: " + why;
    if (outside_alphabet) t.reason += " (has letters outside the ASL manual alphabet)";
    note(w, t.reason);
    emit(std::move(t), Role::plain);
  }

  void word() {
    const Word& w = w_[i_];
    const std::string& l = w.lower;
    if (is_do_support()) {
      drop(w, parsed(i_) ? "do-support (parse: I link to the verb; ASL has no auxiliary 'do')"
                         : "do-support (ASL has no auxiliary 'do')");
      ++i_;
      return;
    }
    if (l == "not") {
      const std::string reason = "'not' → NOT: negation, moved after the verb phrase";
      note(w, reason);
      emit(make("NOT", GlossKind::sign, w, reason), Role::negation_moved);
      ++i_;
      return;
    }
    if (l == "can't") {
      const std::string reason = quoted(w.text) + " → CAN'T: negative modal, moved after the verb phrase";
      note(w, reason);
      emit(make("CAN'T", GlossKind::sign, w, reason), Role::negation_moved);
      ++i_;
      return;
    }
    if (l == "never") {
      const std::string reason = "'never' → NEVER: negation, in place";
      note(w, reason);
      emit(make("NEVER", GlossKind::sign, w, reason), Role::negation_in_place);
      ++i_;
      return;
    }
    if ((l == "have" || l == "has" || l == "had") && parsed(i_) && parsed(i_)->perfect && !completed_action()) {
      drop(w, "auxiliary 'have' of a perfect that lasts up to now or is an experience (been, for, since, never, "
              "not), no completed action (parse: PP link to the participle)");
      ++i_;
      return;
    }
    if ((l == "have" || l == "has" || l == "had") && (parsed(i_) ? parsed(i_)->perfect : next_is_participle())) {
      const std::string reason = quoted(w.text) + " → FINISH: perfect 'have', a completed action" +
                                 (parsed(i_) ? " (parse: PP link to the participle)" : "");
      note(w, reason);
      emit(make("FINISH", GlossKind::sign, w, reason), Role::plain);
      ++i_;
      return;
    }
    // "by" after a passive participle names the one who acts: "The door was locked by the teacher."
    if (l == "by" && passive_seen_) {
      by_agent_ = true;
      drop(w, "'by' of a passive: its agent is signed before the verb, as the one who acts (parse: Pv link)");
      ++i_;
      return;
    }
    if (const auto why = english::dropped(l); why != english::DropReason::none) {
      drop(w, english::describe(why));
      ++i_;
      return;
    }
    if (english::is_wh_word(l) && (question_ || sentence_initial())) {
      has_wh_ = true;
      const std::string gloss = utf8::upper(l);
      const std::string reason = quoted(w.text) + " → " + gloss + ": wh-word, moved to the end";
      note(w, reason);
      emit(make(gloss, GlossKind::sign, w, reason), Role::wh);
      ++i_;
      return;
    }
    if (l == "her") {
      // The parse knows an object ("tell her something": O link to 'her'); else a content word after
      // it makes it possessive ("her dog").
      // Right after an agreement verb and before a thing it is the recipient ("gave her money"), before
      // a person the possessive ("sent her mother a letter").
      // The noun the possessive would go with: past adjectives ("her little son").
      std::size_t head = i_ + 1;
      while (head + 1 < w_.size() && parsed(head) && parsed(head)->pos == english::PartOfSpeech::adjective) ++head;
      const Word* noun = at(head);
      const bool object = (parsed(i_) && parsed(i_)->role == english::Role::object) ||
                          (!items_.empty() && inventory_.agreement_of(items_.back().token.gloss) != Agreement::none && noun &&
                           !wordnet::names_a_person(noun->lower));
      const bool possessive = !object && next_is_content_word();
      const std::string gloss = possessive ? "POSS-3" : "IX-3";
      const std::string reason = "'her' → " + gloss + (possessive ? ": possessive pronoun" : ": pronoun (pointing)");
      note(w, reason);
      emit(make(gloss, GlossKind::sign, w, reason), Role::plain);
      ++i_;
      return;
    }
    if (const auto pronoun = english::pronoun_gloss(l)) {
      const std::string reason = quoted(w.text) + " → " + std::string(*pronoun) + ": pronoun (pointing)";
      note(w, reason);
      emit(make(std::string(*pronoun), GlossKind::sign, w, reason), Role::plain);
      ++i_;
      return;
    }
    if (const auto time = english::time_gloss(l)) {
      const std::string reason = quoted(w.text) + " → " + std::string(*time) + ": time expression, moved to the front";
      note(w, reason);
      emit(make(std::string(*time), GlossKind::sign, w, reason), Role::time);
      ++i_;
      return;
    }
    ++i_;
    const bool initial = sentence_initial_word(w);
    const bool looks_like_name = w.capitalized && !all_caps_ && l != "i" && (!initial || initial_name_);
    const auto candidates = lemma_candidates(l);
    // A capitalised given name is a person's name, even when the same word as a noun has a sign
    // (bill, rose, mark): see given_name().
    if (looks_like_name)
      if (const auto why = given_name(i_ - 1)) return fingerspell(w, "name (capitalized), " + *why);
    if (looks_like_name) {
      // A capitalised word with a sign of its own (a place, a holiday, "Sundays") is signed.
      if (!inventory_.open_vocabulary())
        for (const LemmaCandidate& c : candidates)
          if (const auto gloss = inventory_.gloss_for(c.lemma))
            return sign(w, *gloss, quoted(w.text) + " → " + *gloss + (c.rule.empty() ? "" : ": " + std::string(c.rule)));
      return fingerspell(w, "name (capitalized)");
    }
    // The parse gives the part of speech, and WordNet the lemmas of that part of speech: "left" as a
    // verb is LEAVE, as an adjective LEFT; "saw" as a verb is SEE.
    const english::ParsedWord* p = parsed(i_ - 1);
    const english::PartOfSpeech pos = p ? p->pos : english::PartOfSpeech::unknown;
    const std::string as = p && pos != english::PartOfSpeech::unknown ? std::string(english::to_string(pos)) + ", " : "";
    // Modals (might, may) keep the lexicon's own sign (MAYBE), not a verb lemma's.
    const std::vector<std::string> wn_lemmas = p && p->modal ? std::vector<std::string>{} : wordnet::lemmas(l, pos);
    const auto by_wordnet = [&]() -> std::optional<std::pair<std::string, std::string>> {
      if (inventory_.open_vocabulary()) return std::nullopt;
      for (const std::string& lemma : wn_lemmas)
        if (const auto gloss = inventory_.gloss_for(lemma))
          return std::pair{*gloss, lemma == l ? std::string("a WordNet lemma") : "WordNet lemma " + quoted(lemma)};
      return std::nullopt;
    };
    // A verb takes its WordNet lemma first (left → LEAVE, leaves → LEAVE, not LEFT or LEAF). A
    // participle that is not its clause's verb ("I am tired", "she looks worried") is used as an
    // adjective: a form the lexicon lists keeps its own sign (TIRED, not WHEEL by the lemma 'tire').
    // Also a participle right after a form of "be" or a linking verb ("she was tired and left", where
    // the parse joins "tired and left" as verbs) when WordNet lists the form itself as an adjective
    // and the lexicon signs that form: a state, not the passive of the verb ('tire' → WHEEL).
    const bool adjectival =
        p && pos == english::PartOfSpeech::verb && p->role != english::Role::verb && p->tag.ends_with(".v-d") &&
        (in_adjective_phrase(parse_.tree, p->tag) || (after_linking_verb(i_ - 1) && adjective_form_with_sign(l)));
    if (pos == english::PartOfSpeech::verb && !adjectival)
      if (const auto found = by_wordnet()) return sign(w, found->first, quoted(w.text) + " → " + found->first + ": " + as + found->second);
    // A form the lexicon lists as written ("glasses", "hearing", "news", "oranges") keeps its own
    // sign; other forms are looked up by their lemma.
    if (!inventory_.open_vocabulary())
      if (const auto gloss = inventory_.gloss_for(l)) return sign(w, *gloss, quoted(w.text) + " → " + *gloss);
    if (const auto found = by_wordnet()) return sign(w, found->first, quoted(w.text) + " → " + found->first + ": " + as + found->second);
    for (const LemmaCandidate& c : candidates)
      if (const auto gloss = inventory_.gloss_for(c.lemma))
        return sign(w, *gloss, quoted(w.text) + " → " + *gloss + (c.rule.empty() ? "" : ": " + std::string(c.rule)));
    for (const LemmaCandidate& c : candidates)
      if (const auto other = english::synonym(c.lemma))
        if (const auto gloss = inventory_.gloss_for(*other))
          return sign(w, *gloss, quoted(w.text) + " → " + *gloss + ": synonym " + quoted(*other));
    // Synonyms from WordNet, in the word's part of speech and its most frequent sense only, so that a
    // noun never takes a verb's sign and "picnic" never becomes a breeze (its third sense).
    if (!inventory_.open_vocabulary() && pos != english::PartOfSpeech::unknown)
      for (const std::string& lemma : wn_lemmas)
        for (const std::string& other : wordnet::synonyms(lemma, pos, 1))
          if (const auto gloss = inventory_.gloss_for(other))
            return sign(w, *gloss, quoted(w.text) + " → " + *gloss + ": " + as + "WordNet synonym " + quoted(other) +
                                       " (its most frequent sense)");
    fingerspell(w, "no sign in the lexicon");
  }

  // Whether the constituent that directly holds the word `tag` in a one-line tree is an ADJP
  // ("(VP am.v (ADJP (ADVP very.e) tired.v-d))"), not a VP ("(VP tired.v-d and.v-fill left.v-d)").
  static bool in_adjective_phrase(std::string_view tree, std::string_view tag) {
    for (std::size_t at = tree.find(tag); at != std::string_view::npos; at = tree.find(tag, at + 1)) {
      int depth = 0;
      for (std::size_t k = at; k-- > 0;) {
        if (tree[k] == ')') ++depth;
        if (tree[k] == '(' && depth-- == 0) {
          if (tree.substr(k + 1, 5) == "ADJP ") return true;
          break;
        }
      }
    }
    return false;
  }

  // Why capitalised word k (not opening its sentence, or opening it with initial_name_ set) is a
  // given name, or nothing. Link-grammar's tag in this parse ("Bill.m", "Rose.f", "Pat.b") or its
  // given-name lists when the parse took another reading ("Ask Mark" parses Mark.c, the currency;
  // a place, Jordan.l, stays a place). Not after an article ("the Park"), and not a word whose
  // most frequent WordNet sense is itself capitalised (God, Easter, German, Sunday): that thing's sign.
  std::optional<std::string> given_name(std::size_t k) const {
    const Word& w = w_[k];
    const english::ParsedWord* p = parsed(k);
    const bool tagged = p && is_given_name_tag(p->tag);
    const bool listed = !tagged && english::is_given_name(w.text) && !(p && p->tag.ends_with(".l"));
    if (!tagged && !listed) return std::nullopt;
    if (k > 0 && w_[k - 1].kind == TokenKind::word &&
        (w_[k - 1].lower == "the" || w_[k - 1].lower == "a" || w_[k - 1].lower == "an"))
      return std::nullopt;
    // A word that is itself a noun for a person (Mom, Dad, Grandma) is signed as that noun: the
    // sign names the same person.
    if (wordnet::first_sense_is_proper(w.lower) || wordnet::names_a_person(w.lower)) return std::nullopt;
    return tagged ? "a given name to link-grammar (" + p->tag + ")"
                  : "in link-grammar's list of given names (the parse read " + (p ? p->tag : std::string("nothing")) + ")";
  }

  // Link-grammar marks the given names of its dictionary by sex: "John.m", "Mary.f", "Pat.b" (both).
  static bool is_given_name_tag(std::string_view tag) {
    const auto dot = tag.rfind('.');
    return dot != std::string_view::npos && dot > 0 &&
           (tag.substr(dot) == ".m" || tag.substr(dot) == ".f" || tag.substr(dot) == ".b");
  }

  // Whether the word before index k is a form of "be" or a linking verb (seem, feel, look, get, become).
  bool after_linking_verb(std::size_t k) const {
    return k > 0 && english::is_linking_verb(w_[k - 1].lower);
  }

  // WordNet has the form itself as an adjective (tired, worried, closed) and the lexicon signs it.
  bool adjective_form_with_sign(const std::string& l) {
    if (inventory_.open_vocabulary()) return false;
    const auto as_adjective = wordnet::lemmas(l, english::PartOfSpeech::adjective);
    return !as_adjective.empty() && as_adjective.front() == l && inventory_.gloss_for(l).has_value();
  }

  bool sentence_initial_word(const Word& w) const { return first_word_ < w_.size() && &w == &w_[first_word_]; }

  void sign(const Word& w, const std::string& gloss, std::string reason) {
    note(w, reason);
    const std::size_t k = static_cast<std::size_t>(&w - w_.data());
    // A form the lexicon signs as written and WordNet lists as an adjective (surprised, scared,
    // tired) is a state; its "by" names a cause, and the order stays.
    const bool passive = !by_agent_ && parsed(k) && parsed(k)->passive_participle && !adjective_form_with_sign(w.lower);
    if (passive) passive_seen_ = true;
    emit(make(gloss, GlossKind::sign, w, std::move(reason)), passive ? Role::passive_verb : Role::plain);
  }

  std::vector<Word> w_;
  english::ParsedSentence parse_;
  std::size_t first_word_ = 0;  // index of the first word or number
  bool question_;
  bool initial_name_;
  SignInventory& inventory_;
  std::vector<WordNote>& notes_;
  std::vector<Item> items_;
  std::size_t i_ = 0;
  bool all_caps_ = false;
  bool has_wh_ = false;
  bool passive_seen_ = false;  // a passive participle has been signed in this sentence
  bool by_agent_ = false;      // inside the by-phrase of a passive, until a pause
};

// Words of one sentence, contractions expanded.
std::vector<Word> words_of(const std::vector<Token>& tokens, std::size_t from, std::size_t to) {
  std::vector<Word> out;
  for (std::size_t k = from; k < to; ++k) {
    const Token& t = tokens[k];
    const bool word = t.kind == TokenKind::word;
    const std::string lower = word ? utf8::lower(t.text) : t.text;
    const bool capital = word && is_capitalized(t.text);
    if (word)
      if (const auto parts = english::expand_contraction(lower)) {
        for (std::size_t p = 0; p < parts->size(); ++p)
          out.push_back(Word{t.kind, p == 0 ? t.text : (*parts)[p], (*parts)[p], t.begin, t.end, capital && p == 0});
        continue;
      }
    out.push_back(Word{t.kind, t.text, lower, t.begin, t.end, capital});
  }
  return out;
}

// Parses one sentence's words with link-grammar: words and numbers as written, pauses as their
// punctuation, then the terminator.
english::ParsedSentence parse_words(const std::vector<Word>& words, std::string_view terminator) {
  std::vector<std::string> text;
  std::vector<std::size_t> index;  // words[index[k]] is text[k]
  for (std::size_t k = 0; k < words.size(); ++k) {
    const Word& w = words[k];
    if (w.kind == TokenKind::word || w.kind == TokenKind::number) {
      // A contraction goes to the parser as written ("didn't", "I'm"): link-grammar knows them, and
      // "why did not you come" would not parse. Its later parts share its span and are left out.
      if (k > 0 && words[k - 1].kind == TokenKind::word && words[k - 1].begin == w.begin) continue;
      text.push_back(w.text);
      index.push_back(k);
    } else if (w.kind == TokenKind::pause && (w.text == "," || w.text == ";" || w.text == ":")) {
      text.push_back(w.text);
      index.push_back(k);
    }
  }
  if (text.empty()) return {};
  if (!terminator.empty()) text.emplace_back(terminator.substr(0, 1));
  english::ParsedSentence parsed = english::parse_sentence(text);
  english::ParsedSentence out;
  out.parsed = parsed.parsed;
  out.tree = std::move(parsed.tree);
  out.roles = std::move(parsed.roles);
  out.clauses = parsed.clauses;
  out.cost = parsed.cost;
  out.words.resize(words.size());
  // The parser's word indices (participle) → this sentence's word indices.
  for (auto& w : parsed.words)
    if (w.participle >= 0) w.participle = static_cast<int>(index[static_cast<std::size_t>(w.participle)]);
  for (auto& parts : parsed.parts)
    for (auto& w : parts)
      if (w.participle >= 0) w.participle = static_cast<int>(index[static_cast<std::size_t>(w.participle)]);
  for (std::size_t k = 0; k < index.size(); ++k) {
    if (k < parsed.words.size()) out.words[index[k]] = parsed.words[k];
    // The later words of an expanded contraction ("I'm" → I am) take the parts link-grammar split off.
    if (k >= parsed.parts.size()) continue;  // not parsed: no parts
    for (std::size_t j = 0; j < parsed.parts[k].size(); ++j) {
      const std::size_t at = index[k] + 1 + j;
      if (at < words.size() && words[at].begin == words[index[k]].begin) out.words[at] = parsed.parts[k][j];
    }
  }
  return out;
}

// Whether the capitalised word opening a sentence is a given name rather than the common word
// written with a capital because it opens the sentence ("Bill paid." vs "Hope is important.").
// Link-grammar reads any capitalised word of its name lists as a name there (Bill.m, Hope.f), so its
// tag alone does not decide. The test is the parse of the same words with that word in lower case:
// a singular count noun cannot be a bare subject in English ("rose bought flowers." has no complete
// linkage, "bill paid." only a costlier one), while a mass or abstract noun can ("hope is important."). A word whose most frequent WordNet sense
// is itself capitalised (Easter, Sunday) is that thing, not a name.
bool opens_with_given_name(const std::vector<Word>& words, const english::ParsedSentence& parse,
                           std::string_view terminator) {
  std::size_t first = 0;
  while (first < words.size() && words[first].kind != TokenKind::word && words[first].kind != TokenKind::number) ++first;
  if (!parse.parsed || first >= words.size() || first >= parse.words.size()) return false;
  const Word& w = words[first];
  if (w.kind != TokenKind::word || !w.capitalized || w.lower == "i" || w.text == utf8::upper(w.text)) return false;
  const std::string& tag = parse.words[first].tag;
  const auto dot = tag.rfind('.');
  const bool name_tag = dot != std::string::npos && dot > 0 && (tag.substr(dot) == ".m" || tag.substr(dot) == ".f" ||
                                                                 tag.substr(dot) == ".b");
  if (!name_tag || wordnet::first_sense_is_proper(w.lower) || wordnet::names_a_person(w.lower)) return false;
  std::vector<Word> lowered = words;
  lowered[first].text = w.lower;
  const english::ParsedSentence common = parse_words(lowered, terminator);
  // The common word must be read as a noun, and as usual English: link-grammar links a bare count
  // noun only at a cost, which the name reading does not pay.
  if (!common.parsed || first >= common.words.size() || common.words[first].pos != english::PartOfSpeech::noun ||
      common.cost > parse.cost)
    return true;
  // Link-grammar's reading as a mass noun (summer.n-u, art.n-u) is the common word.
  if (common.words[first].tag.ends_with("-u")) return false;
  // Link-grammar lets many count nouns go bare ("bill paid." parses). WordNet's first noun sense tells
  // a thing one counts (a document, a plant, an artifact, a place) from a feeling, a time, a
  // substance or an idea, which English leaves bare ("Hope is important.", "Summer is hot."). A bare
  // countable thing that does something ("Bill paid.") is a person's name; one that only is something
  // ("Bill is due today.", "Art is fun.") keeps the noun.
  static constexpr std::array kCounted{"noun.artifact", "noun.communication", "noun.plant", "noun.animal",
                                       "noun.object",   "noun.body",          "noun.location", "noun.possession"};
  const std::string kind = wordnet::first_noun_sense_class(w.lower);
  if (std::none_of(kCounted.begin(), kCounted.end(), [&](const char* c) { return kind == c; })) return false;
  for (std::size_t k = first + 1; k < words.size() && k < parse.words.size(); ++k)
    if (parse.words[k].pos == english::PartOfSpeech::verb)
      return !english::is_linking_verb(words[k].lower);
  return false;
}

// Reorders one clause: time expressions, the rest, moved negation, wh-words. Returns where the
// negated verb phrase starts in the reordered clause (or npos).
std::size_t reorder_clause(std::vector<Item>& clause, bool wh_question) {
  std::size_t negation_start = std::string::npos;
  std::vector<Item> time, rest, negation, wh;
  bool negation_seen = false;
  for (Item& item : clause) {
    if (item.role == Role::time) time.push_back(std::move(item));
    else if (item.role == Role::wh && wh_question) wh.push_back(std::move(item));
    else if (item.role == Role::negation_moved) {
      if (!negation_seen) negation_start = rest.size();
      negation_seen = true;
      negation.push_back(std::move(item));
    } else rest.push_back(std::move(item));
  }
  // In "why don't you like…" the subject follows the negation; the headshake covers the verb phrase.
  const auto is_subject = [](const Item& item) {
    return item.token.gloss.rfind("IX-", 0) == 0 || item.token.gloss == "WE";
  };
  if (negation_seen && negation_start + 1 < rest.size() && is_subject(rest[negation_start])) ++negation_start;
  // A passive's agent ("by the teacher") goes before its verb: ASL has no passive, and DOOR LOCK
  // TEACHER would read as the door locking the teacher; DOOR TEACHER LOCK keeps the door as the
  // topic and the teacher as the one who acts.
  if (const auto verb = std::find_if(rest.begin(), rest.end(), [](const Item& x) { return x.role == Role::passive_verb; });
      verb != rest.end()) {
    const auto agent_first = std::stable_partition(verb + 1, rest.end(), [](const Item& x) { return x.role == Role::agent; });
    if (agent_first != verb + 1) std::rotate(verb, verb + 1, agent_first);
  }
  clause.clear();
  for (auto* part : {&time, &rest, &negation, &wh})
    for (Item& item : *part) clause.push_back(std::move(item));
  return negation_seen ? time.size() + negation_start : std::string::npos;
}

}  // namespace

Translation translate_to_gloss(std::string_view english, SignInventory& inventory) {
  Translation out;
  constexpr std::size_t kMaxParsedSentences = 2000;
  std::size_t parsed_sentences = 0;
  const std::vector<Token> tokens = tokenize(english);
  std::vector<SourceWord> source_words;  // for the spatial grammar pass
  std::size_t start = 0;
  while (start < tokens.size()) {
    std::size_t end = start;
    while (end < tokens.size() && tokens[end].kind != TokenKind::sentence_end) ++end;
    const std::string_view terminator = end < tokens.size() ? std::string_view(tokens[end].text) : "";
    std::vector<Word> words = words_of(tokens, start, end);
    const bool question_mark = terminator.find('?') != std::string_view::npos;
    const bool aux_question = words.size() > 1 && words[0].kind == TokenKind::word &&
                              (english::is_auxiliary(words[0].lower) || english::is_wh_word(words[0].lower)) &&
                              words[1].kind == TokenKind::word &&
                              (english::pronoun_gloss(words[1].lower) || english::is_auxiliary(words[1].lower));
    const bool question = question_mark || aux_question;
    // Parsing is bounded per text so that megabytes of input stay quick; later sentences use the rules.
    english::ParsedSentence parse = ++parsed_sentences <= kMaxParsedSentences ? parse_words(words, terminator)
                                                                              : english::ParsedSentence{};
    for (std::size_t k = 0; k < words.size(); ++k) {
      const Word& w = words[k];
      if (w.kind != TokenKind::word && w.kind != TokenKind::number) continue;
      if (!source_words.empty() && source_words.back().begin == w.begin) continue;  // a contraction's later part
      SourceWord& sw = source_words.emplace_back(SourceWord{w.begin, w.end, w.lower});
      if (parse.parsed && k < parse.words.size()) {
        sw.pos = parse.words[k].pos;
        sw.role = parse.words[k].role;
        sw.tag = parse.words[k].tag;
      }
    }
    std::string parse_text = parse.tree;
    if (!parse.roles.empty()) parse_text += "; " + parse.roles;
    const bool initial_name = opens_with_given_name(words, parse, terminator);
    SentenceTranslator translator(std::move(words), std::move(parse), question, initial_name, inventory, out.notes);
    std::vector<Item> items = translator.run();
    while (!items.empty() && items.back().role == Role::pause) items.pop_back();

    Sentence sentence;
    sentence.type = question ? (translator.has_wh() ? SentenceType::wh_question : SentenceType::yes_no_question)
                    : terminator.find('!') != std::string_view::npos ? SentenceType::exclamation
                                                                    : SentenceType::statement;
    sentence.parse = std::move(parse_text);
    sentence.begin = start < tokens.size() ? tokens[start].begin : english.size();
    sentence.end = end < tokens.size() ? tokens[end].end : tokens[end - 1].end;

    if (!items.empty()) {
      if (!out.glosses.empty()) {
        const std::size_t at = tokens[start - 1].begin;
        out.glosses.push_back(GlossToken{"PAUSE", GlossKind::pause, at, tokens[start - 1].end, {}, "sentence boundary"});
      }
      sentence.first = out.glosses.size();
      std::size_t clause_start = 0;
      for (std::size_t k = 0; k <= items.size(); ++k) {
        if (k < items.size() && items[k].role != Role::pause) continue;
        std::vector<Item> clause(std::make_move_iterator(items.begin() + static_cast<std::ptrdiff_t>(clause_start)),
                                 std::make_move_iterator(items.begin() + static_cast<std::ptrdiff_t>(k)));
        const std::size_t base = out.glosses.size();
        const std::size_t negated_from = reorder_clause(clause, sentence.type == SentenceType::wh_question);
        std::size_t negation_end = base;
        std::optional<std::size_t> in_place;
        for (std::size_t c = 0; c < clause.size(); ++c) {
          if (clause[c].role == Role::negation_moved) negation_end = base + c + 1;
          if (clause[c].role == Role::negation_in_place && !in_place) in_place = base + c;
          out.glosses.push_back(std::move(clause[c].token));
        }
        if (negated_from != std::string::npos) {
          out.markers.push_back(Marker{MarkerKind::negation, base + negated_from, negation_end});
          sentence.negated = true;
        } else if (in_place) {
          // NEVER / DON'T-KNOW: the headshake runs from the negative sign to the end of the clause,
          // stopping before a final wh-word.
          std::size_t last = out.glosses.size();
          while (last > *in_place + 1 && clause[last - 1 - base].role == Role::wh) --last;
          out.markers.push_back(Marker{MarkerKind::negation, *in_place, last});
          sentence.negated = true;
        }
        if (k < items.size()) out.glosses.push_back(std::move(items[k].token));
        clause_start = k + 1;
      }
      sentence.last = out.glosses.size();
      const auto kind = sentence.type == SentenceType::yes_no_question ? std::optional(MarkerKind::yes_no_question)
                        : sentence.type == SentenceType::wh_question   ? std::optional(MarkerKind::wh_question)
                        : sentence.type == SentenceType::exclamation   ? std::optional(MarkerKind::exclamation)
                                                                       : std::nullopt;
      if (kind) out.markers.push_back(Marker{*kind, sentence.first, sentence.last});
      out.sentences.push_back(sentence);
    }
    start = end + 1;
  }
  // Notes come out in word order already; the sort is a guarantee, not the usual path.
  const auto by_position = [](const WordNote& a, const WordNote& b) { return a.begin < b.begin; };
  if (!std::is_sorted(out.notes.begin(), out.notes.end(), by_position))
    std::stable_sort(out.notes.begin(), out.notes.end(), by_position);
  place_referents(out, english, source_words, inventory);
  return out;
}

}  // namespace gestura
