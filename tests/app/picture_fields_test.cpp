// The picture fields every command that writes images shares: sizes, frame rates and cameras as
// text, each refused with the text quoted and the field named.
#include <gtest/gtest.h>

#include "gestura/app/motion_output.hpp"

namespace {

using namespace gestura::app;

template <class F>
ErrorReport error_of(F&& f) {
  try {
    f();
  } catch (...) {
    return classify_current();
  }
  return {ErrorCategory::internal, {}, "no error"};
}

TEST(PictureFields, SizesAreWidthByHeightWithinTheRenderersLimits) {
  PictureOptions picture;
  const FieldInfo size{.name = "size"};
  for (const char* text : {"0x0", "100000x100000", "abc", "640", "640x", "-640x480", "15x100", "4097x100", "4096x4096", "x480"}) {
    const ErrorReport e = error_of([&] { set_from_text(picture.size, text, size); });
    EXPECT_EQ(e.category, ErrorCategory::usage) << text;
    EXPECT_EQ(e.place.field, "size") << text;
  }
  EXPECT_NE(error_of([&] { set_from_text(picture.size, "abc", size); }).message.find("'abc'"), std::string::npos);
  set_from_text(picture.size, "1280x720", size);
  EXPECT_EQ(picture.size.width, 1280);
  EXPECT_EQ(picture.size.height, 720);
  set_from_text(picture.size, "4096X2304", size);
  EXPECT_EQ(picture.size.width, 4096);
}

TEST(PictureFields, FrameRatesAreWholeNumbersFrom1To120) {
  const std::vector<FieldInfo> fields = field_list<PictureOptions>();
  const FieldInfo fps = *std::find_if(fields.begin(), fields.end(), [](const FieldInfo& f) { return f.name == "fps"; });
  PictureOptions picture;
  for (const char* text : {"0", "-1", "1000", "30.5", "", "x"}) {
    const ErrorReport e = error_of([&] { set_from_text(picture.fps, text, fps); });
    EXPECT_EQ(e.place.field, "fps") << "'" << text << "'";
  }
  set_from_text(picture.fps, "60", fps);
  EXPECT_EQ(picture.rate(), 60);
  EXPECT_EQ(PictureOptions{}.rate(), 30) << "30 unless asked";
}

TEST(PictureFields, CameraListsNameThePresets) {
  PictureOptions picture;
  const FieldInfo camera{.name = "camera"};
  set_from_text(picture.camera, "front,side,top", camera);
  EXPECT_EQ(picture.camera.size(), 3u);
  EXPECT_EQ(TextCodec<CameraList>::format(picture.camera), "front,side,top");
  const ErrorReport e = error_of([&] { set_from_text(picture.camera, "front,nowhere", camera); });
  EXPECT_EQ(e.place.field, "camera");
  EXPECT_NE(e.message.find("nowhere"), std::string::npos) << e.message;
}

TEST(PictureFields, OutputsAreChosenByExtensionInAnyCase) {
  MotionOutput out;
  for (const char* path : {"a.MP4", "a.Png", "a.GIF", "a.webm", "a.BVH", "a.Json", "a.GLB"}) {
    out.output = path;
    EXPECT_NO_THROW(validate(out, true)) << path;
  }
  out.output = "a.jpg";
  const ErrorReport e = error_of([&] { validate(out, true); });
  EXPECT_EQ(e.place.field, "output");
  EXPECT_NE(e.message.find(".png"), std::string::npos) << e.message;
  out.output = "a.mp4";
  out.sheet = true;
  EXPECT_EQ(error_of([&] { validate(out, true); }).place.field, "output") << "--sheet needs a .png";
}

}  // namespace
