#include <gtest/gtest.h>

#include "gestura/core/error.hpp"

using gestura::Error;
using gestura::SourceLocation;

TEST(Error, MessageNamesThePlace) {
  const Error e(SourceLocation{"clip.bvh", 12, 5, -1}, "expected a number");
  EXPECT_STREQ(e.what(), "clip.bvh:12:5: expected a number");
  EXPECT_EQ(e.where().line, 12);
  EXPECT_EQ(e.message(), "expected a number");
}

TEST(Error, SymbolIndexForNotation) {
  const Error e(SourceLocation{"", 0, 0, 7}, "expected a handshape");
  EXPECT_STREQ(e.what(), "symbol 7: expected a handshape");
}

TEST(Error, NoPlaceGivesJustTheMessage) {
  EXPECT_STREQ(Error("plain").what(), "plain");
}
