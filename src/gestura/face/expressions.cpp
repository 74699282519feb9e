#include "gestura/face/expressions.hpp"

#include <array>
#include <cctype>
#include <string>

#include "gestura/face/face_channels.hpp"

namespace gestura::face {
namespace {

// Poses after the MPEG-4 descriptions of the basic expressions: joy raises the mouth corners and
// squints the eyes; sadness raises the inner brows and lowers the corners; anger lowers the brows and
// presses the lips; fear raises and draws the brows with wide eyes; disgust wrinkles (squint) and
// lowers the corners with a raised upper lip (pucker stands in); surprise raises all brows and
// widens the eyes (the jaw drop is left to jaw_open).
constexpr std::array kJoy{ChannelWeight{kMouthSmileL, 0.9f}, ChannelWeight{kMouthSmileR, 0.9f},
                          ChannelWeight{kEyeSquintL, 0.4f}, ChannelWeight{kEyeSquintR, 0.4f},
                          ChannelWeight{kBrowOuterUpL, 0.2f}, ChannelWeight{kBrowOuterUpR, 0.2f}};
constexpr std::array kSadness{ChannelWeight{kBrowInnerUpL, 0.8f}, ChannelWeight{kBrowInnerUpR, 0.8f},
                              ChannelWeight{kMouthFrownL, 0.7f}, ChannelWeight{kMouthFrownR, 0.7f},
                              ChannelWeight{kEyeSquintL, 0.2f}, ChannelWeight{kEyeSquintR, 0.2f}};
constexpr std::array kAnger{ChannelWeight{kBrowDownL, 0.9f}, ChannelWeight{kBrowDownR, 0.9f},
                            ChannelWeight{kEyeSquintL, 0.5f}, ChannelWeight{kEyeSquintR, 0.5f},
                            ChannelWeight{kMouthPress, 0.6f}, ChannelWeight{kMouthFrownL, 0.3f},
                            ChannelWeight{kMouthFrownR, 0.3f}};
constexpr std::array kFear{ChannelWeight{kBrowInnerUpL, 0.9f}, ChannelWeight{kBrowInnerUpR, 0.9f},
                           ChannelWeight{kBrowOuterUpL, 0.4f}, ChannelWeight{kBrowOuterUpR, 0.4f},
                           ChannelWeight{kEyeWideL, 0.8f}, ChannelWeight{kEyeWideR, 0.8f},
                           ChannelWeight{kMouthFrownL, 0.3f}, ChannelWeight{kMouthFrownR, 0.3f}};
constexpr std::array kDisgust{ChannelWeight{kBrowDownL, 0.5f}, ChannelWeight{kBrowDownR, 0.5f},
                              ChannelWeight{kEyeSquintL, 0.6f}, ChannelWeight{kEyeSquintR, 0.6f},
                              ChannelWeight{kMouthFrownL, 0.6f}, ChannelWeight{kMouthFrownR, 0.6f},
                              ChannelWeight{kMouthPucker, 0.3f}};
constexpr std::array kSurprise{ChannelWeight{kBrowInnerUpL, 0.9f}, ChannelWeight{kBrowInnerUpR, 0.9f},
                               ChannelWeight{kBrowOuterUpL, 0.9f}, ChannelWeight{kBrowOuterUpR, 0.9f},
                               ChannelWeight{kEyeWideL, 0.9f}, ChannelWeight{kEyeWideR, 0.9f},
                               ChannelWeight{kMouthOpen, 0.3f}};

struct AffectWord {
  std::string_view word;
  Expression expression;
};
constexpr std::array kAffectWords{
    AffectWord{"happy", Expression::joy},     AffectWord{"glad", Expression::joy},
    AffectWord{"love", Expression::joy},      AffectWord{"great", Expression::joy},
    AffectWord{"wonderful", Expression::joy}, AffectWord{"thanks", Expression::joy},
    AffectWord{"thank", Expression::joy},     AffectWord{"congratulations", Expression::joy},
    AffectWord{"sad", Expression::sadness},   AffectWord{"sorry", Expression::sadness},
    AffectWord{"miss", Expression::sadness},  AffectWord{"cry", Expression::sadness},
    AffectWord{"angry", Expression::anger},   AffectWord{"mad", Expression::anger},
    AffectWord{"hate", Expression::anger},    AffectWord{"furious", Expression::anger},
    AffectWord{"afraid", Expression::fear},   AffectWord{"scared", Expression::fear},
    AffectWord{"fear", Expression::fear},     AffectWord{"danger", Expression::fear},
    AffectWord{"disgusting", Expression::disgust}, AffectWord{"gross", Expression::disgust},
    AffectWord{"yuck", Expression::disgust},  AffectWord{"wow", Expression::surprise},
    AffectWord{"surprise", Expression::surprise},  AffectWord{"amazing", Expression::surprise},
};

}  // namespace

std::string_view to_string(Expression e) {
  switch (e) {
    case Expression::neutral: return "neutral";
    case Expression::joy: return "joy";
    case Expression::sadness: return "sadness";
    case Expression::anger: return "anger";
    case Expression::fear: return "fear";
    case Expression::disgust: return "disgust";
    case Expression::surprise: return "surprise";
  }
  return "neutral";
}

std::span<const ChannelWeight> expression_weights(Expression e) {
  switch (e) {
    case Expression::neutral: return {};
    case Expression::joy: return kJoy;
    case Expression::sadness: return kSadness;
    case Expression::anger: return kAnger;
    case Expression::fear: return kFear;
    case Expression::disgust: return kDisgust;
    case Expression::surprise: return kSurprise;
  }
  return {};
}

Expression affect_from_text(std::string_view sentence) {
  std::string word;
  auto flush = [&]() -> Expression {
    Expression found = Expression::neutral;
    for (const AffectWord& w : kAffectWords)
      if (word == w.word) found = w.expression;
    word.clear();
    return found;
  };
  for (char c : sentence) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalpha(u)) {
      word.push_back(static_cast<char>(std::tolower(u)));
    } else if (Expression e = flush(); e != Expression::neutral) {
      return e;
    }
  }
  if (Expression e = flush(); e != Expression::neutral) return e;
  const std::size_t last = sentence.find_last_not_of(" \t\r\n\"')");
  if (last != std::string_view::npos && sentence[last] == '!') return Expression::surprise;
  return Expression::neutral;
}

}  // namespace gestura::face
