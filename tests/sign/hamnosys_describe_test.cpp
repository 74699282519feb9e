// The one-line rendering used by `gestura check --show`, checked against the notation by hand.
#include <gtest/gtest.h>

#include "gestura/sign/hamnosys_describe.hpp"
#include "gestura/sign/hamnosys_parser.hpp"

namespace {

using namespace gestura::sign;

TEST(HamnosysDescribe, PillSign) {
  const HamSign sign = parse_hamnosys_names(
      "hampinch12,hamextfingerul,hampalml,hamlips,hamparbegin,hammovei,hamsmallmod,hamreplace,hamcee12,"
      "hamfingerstraightmod,hamthumbopenmod,hamparend,hamclose,hamrepeatfromstart");
  EXPECT_EQ(describe(sign),
            "dominant: pinch12, fingers ul, palm l, at lips; "
            "par(move i small & replace handshape cee12 thumb-open bent), close, repeat");
}

TEST(HamnosysDescribe, HandPairLocationsAndSymmetry) {
  const HamSign sign = parse_hamnosys_names(
      "hamsymmlr,hamfinger23spread,hamextfingerui,hamextfingeril,hampalmdr,hamparbegin,hamforehead,hamlrat,"
      "hamtouch,hamplus,hamcheek,hamlrat,hamclose,hamparend,hamparbegin,hammovedo,hamreplace,hamextfingero,"
      "hampalmu,hamparend");
  EXPECT_EQ(describe(sign),
            "symmetric-lr; dominant: finger23spread, fingers uil, palm dr, at dominant-side forehead touch; "
            "non-dominant: at dominant-side cheek close; par(move do & replace fingers o, palm u)");
}

TEST(HamnosysDescribe, FingerPartWithoutNamedFinger) {
  const HamSign sign = parse_hamnosys_names("hamfinger2,hamextfingerul,hampalmdl,hamfingertip,hamtouch,hammoveor");
  EXPECT_EQ(describe(sign), "dominant: finger2, fingers ul, palm dl, at fingers tip touch; move or");
}

}  // namespace
