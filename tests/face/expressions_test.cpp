#include "gestura/face/expressions.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

using namespace gestura::face;
using gestura::Expression;

TEST(FaceExpressions, UseOnlyTheAvatarsMorphTargets) {
  // The avatar's expression morph targets, as its brief lists them.
  const std::set<std::string> morphs{
      "browInnerUp_L", "browInnerUp_R", "browOuterUp_L", "browOuterUp_R", "browDown_L", "browDown_R",
      "eyeBlink_L",    "eyeBlink_R",    "eyeWide_L",     "eyeWide_R",     "eyeSquint_L", "eyeSquint_R",
      "cheekPuff",     "mouthSmile_L",  "mouthSmile_R",  "mouthFrown_L",  "mouthFrown_R", "mouthPucker",
      "mouthPress",    "mouthOpen",     "tongueOut"};
  EXPECT_TRUE(gestura::expression_weights(Expression::Neutral).empty());
  for (Expression e : {Expression::Joy, Expression::Sadness, Expression::Anger, Expression::Fear,
                       Expression::Disgust, Expression::Surprise}) {
    const std::string_view name = gestura::kExpressionNames[static_cast<std::size_t>(e)];
    EXPECT_FALSE(gestura::expression_weights(e).empty()) << name;
    for (const auto& [channel, weight] : gestura::expression_weights(e)) {
      EXPECT_TRUE(morphs.count(std::string(channel))) << name << ": " << channel;
      EXPECT_GT(weight, 0.0f);
      EXPECT_LE(weight, 1.0f);
    }
  }
}

TEST(FaceExpressions, JoySmilesAndSadnessFrowns) {
  auto weight = [](Expression e, std::string_view channel) {
    for (const auto& [name, weight] : gestura::expression_weights(e))
      if (name == channel) return weight;
    return 0.0f;
  };
  EXPECT_GT(weight(Expression::Joy, "mouthSmile_L"), 0.5f);
  EXPECT_EQ(weight(Expression::Joy, "mouthFrown_L"), 0.0f);
  EXPECT_GT(weight(Expression::Sadness, "mouthFrown_R"), 0.5f);
  EXPECT_GT(weight(Expression::Anger, "browDown_L"), 0.5f);
  EXPECT_GT(weight(Expression::Surprise, "eyeWide_R"), 0.5f);
}

TEST(FaceExpressions, AffectFromWordsAndPunctuation) {
  EXPECT_EQ(affect_from_text("I am so HAPPY today."), Expression::Joy);
  EXPECT_EQ(affect_from_text("I'm sorry."), Expression::Sadness);
  EXPECT_EQ(affect_from_text("He was angry!"), Expression::Anger);
  EXPECT_EQ(affect_from_text("Watch out!"), Expression::Surprise);
  EXPECT_EQ(affect_from_text("The store opens at nine."), Expression::Neutral);
  EXPECT_EQ(affect_from_text("unhappy"), Expression::Neutral);  // whole words only
  EXPECT_EQ(affect_from_text(""), Expression::Neutral);
}
