#include "gestura/face/expressions.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

using namespace gestura::face;

TEST(FaceExpressions, UseOnlyTheAvatarsMorphTargets) {
  // The avatar's expression morph targets, as its brief lists them.
  const std::set<std::string> morphs{
      "browInnerUp_L", "browInnerUp_R", "browOuterUp_L", "browOuterUp_R", "browDown_L", "browDown_R",
      "eyeBlink_L",    "eyeBlink_R",    "eyeWide_L",     "eyeWide_R",     "eyeSquint_L", "eyeSquint_R",
      "cheekPuff",     "mouthSmile_L",  "mouthSmile_R",  "mouthFrown_L",  "mouthFrown_R", "mouthPucker",
      "mouthPress",    "mouthOpen",     "tongueOut"};
  EXPECT_TRUE(expression_weights(Expression::neutral).empty());
  for (Expression e : {Expression::joy, Expression::sadness, Expression::anger, Expression::fear,
                       Expression::disgust, Expression::surprise}) {
    EXPECT_FALSE(expression_weights(e).empty()) << to_string(e);
    for (const ChannelWeight& w : expression_weights(e)) {
      EXPECT_TRUE(morphs.count(std::string(w.channel))) << to_string(e) << ": " << w.channel;
      EXPECT_GT(w.weight, 0.0f);
      EXPECT_LE(w.weight, 1.0f);
    }
  }
}

TEST(FaceExpressions, JoySmilesAndSadnessFrowns) {
  auto weight = [](Expression e, std::string_view channel) {
    for (const ChannelWeight& w : expression_weights(e))
      if (w.channel == channel) return w.weight;
    return 0.0f;
  };
  EXPECT_GT(weight(Expression::joy, "mouthSmile_L"), 0.5f);
  EXPECT_EQ(weight(Expression::joy, "mouthFrown_L"), 0.0f);
  EXPECT_GT(weight(Expression::sadness, "mouthFrown_R"), 0.5f);
  EXPECT_GT(weight(Expression::anger, "browDown_L"), 0.5f);
  EXPECT_GT(weight(Expression::surprise, "eyeWide_R"), 0.5f);
}

TEST(FaceExpressions, AffectFromWordsAndPunctuation) {
  EXPECT_EQ(affect_from_text("I am so HAPPY today."), Expression::joy);
  EXPECT_EQ(affect_from_text("I'm sorry."), Expression::sadness);
  EXPECT_EQ(affect_from_text("He was angry!"), Expression::anger);
  EXPECT_EQ(affect_from_text("Watch out!"), Expression::surprise);
  EXPECT_EQ(affect_from_text("The store opens at nine."), Expression::neutral);
  EXPECT_EQ(affect_from_text("unhappy"), Expression::neutral);  // whole words only
  EXPECT_EQ(affect_from_text(""), Expression::neutral);
}
