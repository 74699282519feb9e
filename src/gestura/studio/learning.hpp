#pragma once
// The learning mode's material and its self-test, without a window: topics (the built-in lexicon's
// categories) → words (gloss, notation, plain description, keywords) → practice sentences, and a
// quiz in which the avatar signs a word of the topic and the learner picks it among a few.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gestura/lexicon/sign_entry.hpp"
#include "gestura/studio/nonmanual_tiers.hpp"

namespace gestura::studio {

struct LessonWord {
  std::string gloss, language, names, description;
  std::vector<std::string> keywords;
  int variant = 1;
  bool clip_sign = false;  // a keyframed sign (no notation): played from its recorded motion
  std::vector<DraftNonManual> nonmanuals;  // a SiGML sign's non-manual tiers, performed with it
};

struct Topic {
  std::string name;  // "greeting", "colour", ...
  std::vector<LessonWord> words;
  std::vector<std::string> sentences;  // English, signed as `gestura say` does
};

// Reads the lexicon .jsonl files (their "category" and "description" fields; HamNoSys signs only)
// and, when it exists, `sentences_json` ({"topic": ["sentence", ...]}). Topics come in the order
// they first appear; words without a category go to "other". Throws gestura::Error naming the file
// and line for unreadable input.
std::vector<Topic> load_topics(const std::vector<std::string>& lexicon_files, const std::string& sentences_json);
// The name of the topic that holds the user's own signs.
inline constexpr const char* kUserTopic = "your signs";
// The user's lexicon as one topic, kUserTopic: its HamNoSys signs and its clip signs (keyframed in
// the timeline editor) alike; SiGML entries are left out. Empty words when there are none.
Topic user_topic(std::span<const SignEntry> entries);
// data/learning/sentences.json beside the built-in lexicon's folder (empty when there is none).
std::string default_sentences_file(const std::vector<std::string>& lexicon_files);

// The self-test: each question is a word of the topic (never the same twice in a row) and `choices`
// glosses to pick from, the right one among them, in random order. Deterministic for a seed.
class Quiz {
 public:
  Quiz(const Topic& topic, std::uint32_t seed, int choices = 4);
  // Contract: the topic has at least one word.
  const LessonWord& word() const;
  const std::vector<std::string>& choices() const { return choices_; }
  // Records the learner's answer to the current question; true when right. Once answered, the same
  // question keeps its first answer until next().
  bool answer(const std::string& gloss);
  std::optional<bool> answered() const { return answered_; }
  void next();
  int asked() const { return asked_; }
  int right() const { return right_; }

 private:
  std::uint32_t random();
  void make_choices();
  const Topic* topic_;
  std::uint32_t state_;
  int choice_count_;
  std::size_t current_ = 0;
  std::vector<std::string> choices_;
  std::optional<bool> answered_;
  int asked_ = 0, right_ = 0;
};

}  // namespace gestura::studio
