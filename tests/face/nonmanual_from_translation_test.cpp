#include "gestura/face/nonmanual_from_translation.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "gestura/core/error.hpp"
#include "gestura/face/nonmanual.hpp"
#include "gestura/text/translator.hpp"

using namespace gestura;
using namespace gestura::face;
using gestura::Expression;

namespace {

std::vector<TimedGloss> half_second_each(std::size_t n) {
  std::vector<TimedGloss> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back({0.5f * static_cast<float>(i), 0.5f * static_cast<float>(i + 1)});
  return out;
}

const NonManualSpan* find(const NonManualPlan& plan, NonManualKind kind) {
  for (const NonManualSpan& s : plan.spans)
    if (s.kind == kind) return &s;
  return nullptr;
}

}  // namespace

TEST(FaceNonManualFromTranslation, MarkersAffectAndBoundaries) {
  const std::string english = "Are you happy? I don't like coffee. Wow!";
  OpenVocabulary open;
  const Translation t = translate_to_gloss(english, open);
  ASSERT_EQ(t.sentences.size(), 3u);
  const NonManualPlan plan = plan_from_translation(t, english, half_second_each(t.glosses.size()));

  const NonManualSpan* question = find(plan, NonManualKind::yes_no_question);
  ASSERT_NE(question, nullptr);
  EXPECT_EQ(question->first, t.sentences[0].first);
  EXPECT_EQ(question->last, t.sentences[0].last);
  const NonManualSpan* negation = find(plan, NonManualKind::negation);
  ASSERT_NE(negation, nullptr);
  EXPECT_GE(negation->first, t.sentences[1].first);
  EXPECT_LE(negation->last, t.sentences[1].last);

  // "happy" makes the question joyful (mildly); "Wow!" is a full-intensity surprise.
  std::vector<NonManualSpan> affects;
  for (const NonManualSpan& s : plan.spans)
    if (s.kind == NonManualKind::affect) affects.push_back(s);
  ASSERT_EQ(affects.size(), 2u);
  EXPECT_EQ(affects[0].expression, Expression::Joy);
  EXPECT_FLOAT_EQ(affects[0].intensity, 0.6f);
  EXPECT_EQ(affects[0].first, t.sentences[0].first);
  EXPECT_EQ(affects[1].expression, Expression::Surprise);
  EXPECT_FLOAT_EQ(affects[1].intensity, 1.0f);
  EXPECT_EQ(affects[1].first, t.sentences[2].first);

  // A boundary (blink) at the end of each sentence's last gloss.
  for (const Sentence& s : t.sentences) {
    const float end = 0.5f * static_cast<float>(s.last);
    EXPECT_NE(std::find(plan.boundaries.begin(), plan.boundaries.end(), end), plan.boundaries.end()) << end;
  }
  EXPECT_NO_THROW(plan_nonmanual(plan));
}

TEST(FaceNonManualFromTranslation, TimesMustMatchTheGlosses) {
  OpenVocabulary open;
  const Translation t = translate_to_gloss("I like coffee.", open);
  EXPECT_THROW(plan_from_translation(t, "I like coffee.", half_second_each(t.glosses.size() + 1)), Error);
  EXPECT_THROW(plan_from_translation(t, "I like", half_second_each(t.glosses.size())), Error);
}
