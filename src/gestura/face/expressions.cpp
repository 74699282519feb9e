#include "gestura/face/expressions.hpp"

#include <array>
#include <cctype>
#include <string>


namespace gestura::face {
namespace {

struct AffectWord {
  std::string_view word;
  Expression expression;
};
constexpr std::array kAffectWords{
    AffectWord{"happy", Expression::Joy},     AffectWord{"glad", Expression::Joy},
    AffectWord{"love", Expression::Joy},      AffectWord{"great", Expression::Joy},
    AffectWord{"wonderful", Expression::Joy}, AffectWord{"thanks", Expression::Joy},
    AffectWord{"thank", Expression::Joy},     AffectWord{"congratulations", Expression::Joy},
    AffectWord{"sad", Expression::Sadness},   AffectWord{"sorry", Expression::Sadness},
    AffectWord{"miss", Expression::Sadness},  AffectWord{"cry", Expression::Sadness},
    AffectWord{"angry", Expression::Anger},   AffectWord{"mad", Expression::Anger},
    AffectWord{"hate", Expression::Anger},    AffectWord{"furious", Expression::Anger},
    AffectWord{"afraid", Expression::Fear},   AffectWord{"scared", Expression::Fear},
    AffectWord{"fear", Expression::Fear},     AffectWord{"danger", Expression::Fear},
    AffectWord{"disgusting", Expression::Disgust}, AffectWord{"gross", Expression::Disgust},
    AffectWord{"yuck", Expression::Disgust},  AffectWord{"wow", Expression::Surprise},
    AffectWord{"surprise", Expression::Surprise},  AffectWord{"amazing", Expression::Surprise},
};

}  // namespace

Expression affect_from_text(std::string_view sentence) {
  std::string word;
  auto flush = [&]() -> Expression {
    Expression found = Expression::Neutral;
    for (const AffectWord& w : kAffectWords)
      if (word == w.word) found = w.expression;
    word.clear();
    return found;
  };
  for (char c : sentence) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalpha(u)) {
      word.push_back(static_cast<char>(std::tolower(u)));
    } else if (Expression e = flush(); e != Expression::Neutral) {
      return e;
    }
  }
  if (Expression e = flush(); e != Expression::Neutral) return e;
  const std::size_t last = sentence.find_last_not_of(" \t\r\n\"')");
  if (last != std::string_view::npos && sentence[last] == '!') return Expression::Surprise;
  return Expression::Neutral;
}

}  // namespace gestura::face
