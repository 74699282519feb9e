#include "gestura/sign/sign_limits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gestura/core/error.hpp"

namespace gestura::sign {

namespace {

[[noreturn]] void fail(int index, const std::string& message) {
  SourceLocation where;
  where.index = index;
  throw Error(where, message);
}

bool is_leaf(ElementKind k) {
  return k == ElementKind::handshape || k == ElementKind::orientation || k == ElementKind::location ||
         k == ElementKind::motion;
}

int times_of(const Repetition& r) {
  return r.kind == RepetitionKind::from_start_several || r.kind == RepetitionKind::continued_several ? 2 : 1;
}

// Walks the actions as the planner performs them, counting. `last` is the action a repetition
// repeats; `open` the groups being performed, which a repetition inside them must not repeat.
class Counter {
 public:
  explicit Counter(bool throw_past_cap) : throw_past_cap_(throw_past_cap) {}

  int count() const { return count_; }
  bool past_cap() const { return count_ > kMaxPerformedActions; }

  void perform(const Element& e) {
    if (past_cap()) return;
    switch (e.kind) {
      case ElementKind::handshape:
      case ElementKind::orientation:
      case ElementKind::location:
      case ElementKind::motion:
        add(e.symbol_index);
        last_ = &e;
        break;
      case ElementKind::contact: add(e.symbol_index); break;
      case ElementKind::repetition: repeat(e); break;
      case ElementKind::sequence:
      case ElementKind::parallel:
      case ElementKind::fusion: {
        const bool flat = !e.children.empty() && std::all_of(e.children.begin(), e.children.end(),
                                                             [](const Element& c) { return is_leaf(c.kind); });
        if (flat && e.kind != ElementKind::sequence) {
          add(e.symbol_index);  // performed at the same time: one action
        } else {
          open_.push_back(&e);
          for (const Element& c : e.children) perform(c);
          open_.pop_back();
        }
        last_ = &e;
        break;
      }
      case ElementKind::hand_pair:
        // Each branch drives one hand; a repetition there repeats that hand's last single action.
        for (const Element& branch : e.children) perform_for_one_hand(branch);
        last_ = &e;
        break;
      case ElementKind::alternatives:
        if (!e.children.empty()) perform(e.children.front());
        break;
      case ElementKind::unspecified:
      case ElementKind::coreference: break;
    }
  }

 private:
  void add(int index) {
    ++count_;
    if (throw_past_cap_ && past_cap())
      fail(index, "the sign performs more than " + std::to_string(kMaxPerformedActions) +
                      " actions once its repetitions are unrolled (limit kMaxPerformedActions)");
  }

  void repeat(const Element& e) {
    if (last_ == nullptr) return;  // nothing before it to repeat
    const Element* again = last_;
    if (std::find(open_.begin(), open_.end(), again) != open_.end()) {
      if (!throw_past_cap_) {
        count_ = kMaxPerformedActions + 1;  // endless
        return;
      }
      fail(e.symbol_index, "this repetition would repeat the group it is written in, without end; a repetition "
                           "repeats the action written before it");
    }
    const Repetition* r = e.repetition();
    for (int k = 0; k < times_of(*r) && !past_cap(); ++k) {
      add(e.symbol_index);  // the move back to where the repeated action began (or the reversal)
      if (r->kind != RepetitionKind::reversed) perform(*again);
    }
    last_ = again;
  }

  void perform_for_one_hand(const Element& e) {
    if (past_cap()) return;
    if (is_leaf(e.kind) || e.kind == ElementKind::repetition) add(e.symbol_index);
    else if (e.kind == ElementKind::sequence || e.kind == ElementKind::parallel || e.kind == ElementKind::fusion)
      for (const Element& c : e.children) perform_for_one_hand(c);
  }

  bool throw_past_cap_;
  int count_ = 0;
  const Element* last_ = nullptr;
  std::vector<const Element*> open_;
};

void count_repetitions(const Element& e, int& count) {
  if (e.kind == ElementKind::repetition && ++count > kMaxRepetitions)
    fail(e.symbol_index, "more than " + std::to_string(kMaxRepetitions) +
                             " repetitions in one sign (limit kMaxRepetitions)");
  for (const Element& c : e.children) count_repetitions(c, count);
}

void perform_sign(const HamSign& sign, Counter& counter) {
  for (const ManualSign& segment : sign.segments) {
    for (const Element& e : segment.actions) {
      counter.perform(e);
      if (counter.past_cap()) return;
    }
  }
}

}  // namespace

int performed_actions(const HamSign& sign) {
  Counter counter(false);
  perform_sign(sign, counter);
  return counter.count();
}

void check_sign_limits(const HamSign& sign) {
  int repetitions = 0;
  for (const ManualSign& segment : sign.segments)
    for (const Element& e : segment.actions) count_repetitions(e, repetitions);
  Counter counter(true);
  perform_sign(sign, counter);
}

void check_sign_duration(float seconds) {
  if (std::isfinite(seconds) && seconds <= kMaxSignSeconds) return;
  char text[96];
  std::snprintf(text, sizeof text, "the sign lasts %.1f s, more than the limit of %.0f s (kMaxSignSeconds)", seconds,
                kMaxSignSeconds);
  throw Error(text);
}

}  // namespace gestura::sign
