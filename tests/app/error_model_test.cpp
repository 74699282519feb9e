// The command layer's one error model: every failure is a category, a message and a place, and
// the category alone decides the exit status and the HTTP status.
#include <gtest/gtest.h>

#include <new>
#include <stdexcept>

#include "gestura/app/error.hpp"

namespace {

using namespace gestura::app;

TEST(AppErrorModel, CategoriesMapToExitAndHttpStatus) {
  EXPECT_EQ(exit_code(ErrorCategory::usage), 2);
  EXPECT_EQ(http_status(ErrorCategory::usage), 400);
  EXPECT_EQ(exit_code(ErrorCategory::input), 1);
  EXPECT_EQ(http_status(ErrorCategory::input), 422);
  EXPECT_EQ(http_status(ErrorCategory::not_found), 404);
  EXPECT_EQ(http_status(ErrorCategory::conflict), 409);
  EXPECT_EQ(http_status(ErrorCategory::too_large), 413);
  EXPECT_EQ(http_status(ErrorCategory::output), 500);
  EXPECT_EQ(exit_code(ErrorCategory::cancelled), 130);
  EXPECT_EQ(http_status(ErrorCategory::internal), 500);
  for (ErrorCategory c : {ErrorCategory::input, ErrorCategory::not_found, ErrorCategory::conflict,
                          ErrorCategory::too_large, ErrorCategory::output, ErrorCategory::internal})
    EXPECT_EQ(exit_code(c), 1) << to_string(c);
}

TEST(AppErrorModel, WhatNamesTheFieldThenThePlaceInTheInput) {
  const AppError e(ErrorCategory::input, Place{"sigml", {"sign.sigml", 4, 2, -1}}, "expected a handshape");
  EXPECT_STREQ(e.what(), "sigml: sign.sigml:4:2: expected a handshape");
  EXPECT_EQ(e.message(), "expected a handshape");
  EXPECT_EQ(e.where().line, 4) << "the library's view of the place is kept";
  EXPECT_STREQ(AppError(ErrorCategory::usage, "plain").what(), "plain");
}

TEST(AppErrorModel, ClassifyKeepsCategoriesAndPlacesOfEveryKindOfException) {
  const ErrorReport usage = classify(AppError(ErrorCategory::usage, Place{"fps", {}}, "500 is outside 1..120"));
  EXPECT_EQ(usage.category, ErrorCategory::usage);
  EXPECT_EQ(usage.place.field, "fps");
  EXPECT_EQ(usage.exit_code(), 2);

  // A library error is bad input at its own place.
  const ErrorReport input = classify(gestura::Error(gestura::SourceLocation{"", 0, 0, 7}, "expected a handshape"));
  EXPECT_EQ(input.category, ErrorCategory::input);
  EXPECT_EQ(input.place.source.index, 7);
  EXPECT_EQ(input.message, "expected a handshape");
  EXPECT_EQ(input.http_status(), 422);

  EXPECT_EQ(classify(gestura::Cancelled("render stopped")).category, ErrorCategory::cancelled);
  EXPECT_EQ(classify(std::bad_alloc()).category, ErrorCategory::too_large);
  const ErrorReport bug = classify(std::logic_error("index out of range"));
  EXPECT_EQ(bug.category, ErrorCategory::internal);
  EXPECT_EQ(bug.message, "index out of range");
}

TEST(AppErrorModel, FieldErrorsWrapLibraryErrorsButPassOwnCategoriesThrough) {
  try {
    as_field_error(ErrorCategory::usage, "size", [] { throw gestura::Error("each side must be 16..4096 pixels"); });
    FAIL() << "should throw";
  } catch (const AppError& e) {
    EXPECT_EQ(e.category(), ErrorCategory::usage);
    EXPECT_EQ(e.place().field, "size");
  }
  try {
    as_field_error(ErrorCategory::usage, "size", [] { not_found("db", "no such lexicon"); });
    FAIL() << "should throw";
  } catch (const AppError& e) {
    EXPECT_EQ(e.category(), ErrorCategory::not_found) << "an AppError keeps its own category";
    EXPECT_EQ(e.place().field, "db");
  }
  EXPECT_THROW(as_field_error(ErrorCategory::input, "x", [] { throw gestura::Cancelled("stop"); }), gestura::Cancelled);
  EXPECT_EQ(as_field_error(ErrorCategory::input, "x", [] { return 42; }), 42);
}

}  // namespace
