#include "gestura/studio/learning.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "gestura/core/error.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/studio/sign_draft.hpp"

namespace gestura::studio {
namespace {

std::string text_of(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : std::string();
}

// The notation as symbol names: the "names" field, else the Unicode "hamnosys" decoded.
std::string names_of(const nlohmann::json& j) {
  if (std::string names = text_of(j, "names"); !names.empty()) return names;
  std::string out;
  for (const sign::Symbol s : sign::symbols_from_unicode(text_of(j, "hamnosys")))
    out += (out.empty() ? "" : ",") + std::string(sign::symbol_name(s));
  return out;
}

}  // namespace

Topic user_topic(std::span<const SignEntry> entries) {
  Topic topic{kUserTopic, {}, {}};
  for (const SignEntry& e : entries) {
    LessonWord w{e.gloss, e.language, {}, {}, {}, e.variant, false};
    for (const Keyword& k : e.keywords) w.keywords.push_back(k.word);
    if (e.notation_kind == NotationKind::clip) {
      w.clip_sign = true;
      w.names = "(none: a clip sign)";
      w.description = "A keyframed sign, made in the studio's timeline editor; `gestura say` plays it in sentences.";
    } else if (e.notation_kind == NotationKind::hamnosys) {
      try {
        for (const sign::Symbol s : sign::symbols_from_unicode(e.notation))
          w.names += (w.names.empty() ? "" : ",") + std::string(sign::symbol_name(s));
      } catch (const Error&) {
        continue;  // notation that does not decode is not a lesson
      }
    } else {
      try {  // SiGML: its symbols and non-manual tiers (gestural SiGML is not a lesson here)
        const SignDraft d = draft_from_entry(e, false);
        w.names = d.names;
        w.nonmanuals = d.nonmanuals;
      } catch (const Error&) {
        continue;
      }
    }
    topic.words.push_back(std::move(w));
  }
  return topic;
}

std::vector<Topic> load_topics(const std::vector<std::string>& lexicon_files, const std::string& sentences_json) {
  std::vector<Topic> topics;
  std::map<std::string, std::size_t> index;
  auto topic = [&](const std::string& name) -> Topic& {
    const auto [it, added] = index.emplace(name, topics.size());
    if (added) topics.push_back(Topic{name, {}, {}});
    return topics[it->second];
  };
  for (const std::string& file : lexicon_files) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(SourceLocation{file}, "cannot read the lexicon file");
    int number = 0;
    for (std::string line; std::getline(in, line);) {
      ++number;
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
      if (j.is_discarded() || !j.is_object()) throw Error(SourceLocation{file, number}, "not a JSON object");
      if (!text_of(j, "sigml").empty() || !text_of(j, "clip_base64").empty()) continue;
      LessonWord w;
      w.gloss = text_of(j, "gloss");
      w.language = text_of(j, "lang");
      w.description = text_of(j, "description");
      try {
        w.names = names_of(j);
      } catch (const Error& e) {
        throw Error(SourceLocation{file, number}, e.message());
      }
      if (w.gloss.empty() || w.names.empty()) continue;
      if (const auto k = j.find("keywords"); k != j.end() && k->is_array()) {
        for (const auto& word : *k) {
          if (word.is_string()) w.keywords.push_back(word.get<std::string>());
          else if (word.is_object()) w.keywords.push_back(text_of(word, "word"));
        }
      }
      const std::string category = text_of(j, "category");
      topic(category.empty() ? "other" : category).words.push_back(std::move(w));
    }
  }
  if (!sentences_json.empty() && std::filesystem::exists(sentences_json)) {
    std::ifstream in(sentences_json, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    const nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, false);
    if (j.is_discarded() || !j.is_object()) throw Error(SourceLocation{sentences_json}, "not a JSON object of topics");
    for (const auto& [name, list] : j.items()) {
      if (!list.is_array() || index.find(name) == index.end()) continue;  // "_about", topics without words
      for (const auto& s : list)
        if (s.is_string()) topics[index[name]].sentences.push_back(s.get<std::string>());
    }
  }
  return topics;
}

std::string default_sentences_file(const std::vector<std::string>& lexicon_files) {
  if (lexicon_files.empty()) return {};
  const std::filesystem::path p = std::filesystem::path(lexicon_files.front()).parent_path().parent_path() / "learning" / "sentences.json";
  return std::filesystem::exists(p) ? p.string() : std::string();
}

Quiz::Quiz(const Topic& topic, std::uint32_t seed, int choices) : topic_(&topic), state_(seed ? seed : 1u), choice_count_(choices) {
  current_ = topic_->words.empty() ? 0 : random() % topic_->words.size();
  make_choices();
  asked_ = 1;
}

std::uint32_t Quiz::random() {
  // xorshift32: small, deterministic, good enough to shuffle a handful of choices.
  state_ ^= state_ << 13;
  state_ ^= state_ >> 17;
  state_ ^= state_ << 5;
  return state_;
}

const LessonWord& Quiz::word() const { return topic_->words[current_]; }

bool Quiz::answer(const std::string& gloss) {
  if (answered_) return *answered_;
  answered_ = gloss == word().gloss;
  right_ += *answered_;
  return *answered_;
}

void Quiz::next() {
  const std::size_t n = topic_->words.size();
  if (n == 0) return;
  if (n > 1) {
    std::size_t pick = random() % (n - 1);
    if (pick >= current_) ++pick;  // never the same word twice in a row
    current_ = pick;
  }
  make_choices();
  ++asked_;
}

void Quiz::make_choices() {
  const std::size_t n = topic_->words.size();
  if (n == 0) return;
  choices_ = {topic_->words[current_].gloss};
  const std::size_t want = std::min<std::size_t>(static_cast<std::size_t>(std::max(1, choice_count_)), n);
  for (int guard = 0; choices_.size() < want && guard < 1000; ++guard) {
    const std::string& g = topic_->words[random() % n].gloss;
    if (std::find(choices_.begin(), choices_.end(), g) == choices_.end()) choices_.push_back(g);
  }
  for (std::size_t i = choices_.size(); i > 1; --i) std::swap(choices_[i - 1], choices_[random() % i]);
  answered_.reset();
}

}  // namespace gestura::studio
