// Requests list their fields once; JSON in and out, command-line text and the checks all walk that
// list, so a field is read, bounded and named the same way whichever adapter fills it.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "gestura/app/avatar.hpp"
#include "gestura/app/check.hpp"
#include "gestura/app/compress.hpp"
#include "gestura/app/convert.hpp"
#include "gestura/app/fingerspell.hpp"
#include "gestura/app/gloss.hpp"
#include "gestura/app/info.hpp"
#include "gestura/app/lexicon.hpp"
#include "gestura/app/mouth.hpp"
#include "gestura/app/reach.hpp"
#include "gestura/app/render.hpp"
#include "gestura/app/retarget.hpp"
#include "gestura/app/say.hpp"
#include "gestura/app/sign.hpp"
#include "gestura/app/subtitles.hpp"

namespace {

using namespace gestura::app;
using nlohmann::json;

// The error a call throws, or a report of internal with "no error" when it throws none.
template <class F>
ErrorReport error_of(F&& f) {
  try {
    f();
  } catch (...) {
    return classify_current();
  }
  return {ErrorCategory::internal, {}, "no error"};
}

TEST(RequestFields, OneNumberParserForEveryField) {
  const FieldInfo fps{.name = "fps", .min = 1, .max = 120};
  EXPECT_EQ(parse_number<int>("30", fps), 30);
  EXPECT_EQ(parse_number<int>("+2", fps), 2);
  EXPECT_FLOAT_EQ(parse_number<float>("1e-1", FieldInfo{.name = "speed"}), 0.1f);
  for (const char* bad : {"", "3x", " 3", "3 ", "2.5", "abc", "+", "+-2", "0x10"}) {
    const ErrorReport e = error_of([&] { parse_number<int>(bad, fps); });
    EXPECT_EQ(e.category, ErrorCategory::usage) << bad;
    EXPECT_EQ(e.place.field, "fps") << bad;
    EXPECT_NE(e.message.find("whole number"), std::string::npos) << bad << ": " << e.message;
  }
  const ErrorReport range = error_of([&] { parse_number<int>("500", fps); });
  EXPECT_EQ(range.message, "500 is outside 1..120");
  for (const char* bad : {"nan", "inf", "-inf", "1e400"})
    EXPECT_EQ(error_of([&] { parse_number<float>(bad, FieldInfo{.name = "speed"}); }).category, ErrorCategory::usage) << bad;
  EXPECT_EQ(parse_number_list("0.2,-1.5,3", {3}, FieldInfo{.name = "target"}), (std::vector<float>{0.2f, -1.5f, 3.0f}));
  const ErrorReport two = error_of([&] { parse_number_list("1,2", {3}, FieldInfo{.name = "target"}); });
  EXPECT_NE(two.message.find("expected 3 numbers"), std::string::npos) << two.message;
}

TEST(RequestFields, JsonRoundTripKeepsEveryField) {
  SayRequest request;
  request.text = "Where do you live?";
  request.speed = 1.5f;
  request.mouthing = false;
  request.avatar.params.height = 1.8f;
  request.avatar.params.sex = gestura::Sex::Female;
  request.output.output = "where.mp4";
  request.output.picture.size = {640, 360};
  request.output.picture.fps = 25;
  request.output.picture.camera = {gestura::CameraPreset::Front, gestura::CameraPreset::Side};
  const json j = to_json(request);
  EXPECT_EQ(j.at("text"), "Where do you live?");
  EXPECT_EQ(j.at("size"), "640x360");
  EXPECT_EQ(j.at("camera"), "front,side");
  EXPECT_EQ(j.at("sex"), "female");
  EXPECT_EQ(j.at("mouthing"), false);
  const SayRequest back = request_from_json<SayRequest>(j);
  EXPECT_EQ(to_json(back), j);
  EXPECT_EQ(back.output.picture.size.width, 640);
  EXPECT_EQ(back.output.picture.fps, 25);
  EXPECT_EQ(back.avatar.params.sex, gestura::Sex::Female);
}

TEST(RequestFields, JsonKeepsDefaultsForAbsentKeysAndRefusesUnknownOrMistypedOnes) {
  const SayRequest minimal = request_from_json<SayRequest>(json{{"text", "hello"}});
  EXPECT_EQ(minimal.lang, "ase");
  EXPECT_FLOAT_EQ(minimal.speed, 1.0f);
  EXPECT_FALSE(minimal.output.picture.fps.has_value());

  const ErrorReport unknown = error_of([] { request_from_json<SayRequest>(json{{"text", "hi"}, {"sped", 2}}); });
  EXPECT_EQ(unknown.category, ErrorCategory::usage);
  EXPECT_EQ(unknown.place.field, "sped");
  EXPECT_NE(unknown.message.find("speed"), std::string::npos) << "lists the known fields: " << unknown.message;

  const ErrorReport type = error_of([] { request_from_json<SayRequest>(json{{"text", "hi"}, {"speed", "fast"}}); });
  EXPECT_EQ(type.place.field, "speed");
  EXPECT_NE(type.message.find("expected a number"), std::string::npos) << type.message;

  const ErrorReport whole = error_of([] { request_from_json<SayRequest>(json{{"text", "hi"}, {"fps", 29.5}}); });
  EXPECT_EQ(whole.place.field, "fps");

  const ErrorReport coded = error_of([] { request_from_json<SayRequest>(json{{"text", "hi"}, {"size", "12x12"}}); });
  EXPECT_EQ(coded.category, ErrorCategory::usage);
  EXPECT_EQ(coded.place.field, "size");
  EXPECT_NE(coded.message.find("16..4096"), std::string::npos) << coded.message;

  EXPECT_EQ(error_of([] { request_from_json<SayRequest>(json::array()); }).category, ErrorCategory::usage);
}

TEST(RequestFields, LimitsHoldHoweverAValueArrives) {
  SayRequest set_in_code;
  set_in_code.text = "hello";
  set_in_code.speed = 9.0f;  // not through any parser
  const ErrorReport e = error_of([&] { validate(set_in_code); });
  EXPECT_EQ(e.category, ErrorCategory::usage);
  EXPECT_EQ(e.place.field, "speed");
  EXPECT_EQ(e.message, "9 is outside 0.25..2");
  EXPECT_EQ(error_of([] { request_from_json<SayRequest>(json{{"speed", 9}}); }).place.field, "speed");
  SayRequest from_text;
  const ErrorReport text = error_of([&] {
    set_from_text(from_text.avatar.params.height, "0.5", FieldInfo{.name = "height", .min = 1.0, .max = 2.5});
  });
  EXPECT_EQ(text.place.field, "height");
  EXPECT_FLOAT_EQ(from_text.avatar.params.height, 1.7f) << "a refused value is not stored";
}

TEST(RequestFields, AvatarFieldRangesAreTheBodysOwn) {
  // The field table bounds the generated avatar's parameters exactly where AvatarParams::validate does.
  AvatarChoice probe;
  AvatarChoice::fields(probe, [&](auto& value, const FieldInfo& field) {
    if constexpr (std::is_same_v<std::remove_cvref_t<decltype(value)>, float>) {
      const float saved = value;
      for (const double edge : {field.min, field.max}) {
        value = static_cast<float>(edge);
        EXPECT_NO_THROW(probe.params.validate()) << field.name << " = " << edge;
      }
      for (const double outside : {field.min - 0.01, field.max + 0.01}) {
        value = static_cast<float>(outside);
        EXPECT_THROW(probe.params.validate(), gestura::Error) << field.name << " = " << outside;
      }
      value = saved;
    }
  });
}

// Every field a request shares with another is the same field: same flag letter, placeholder and
// heading, so a flag is spelled the same way by every command (and every JSON body).
template <class R>
void collect(std::map<std::string, std::vector<FieldInfo>>& by_name) {
  for (const FieldInfo& f : field_list<R>()) by_name[std::string(f.name)].push_back(f);
}

template <class... R>
struct Requests {
  static void collect_all(std::map<std::string, std::vector<FieldInfo>>& by_name) { (collect<R>(by_name), ...); }
  static std::vector<std::vector<FieldInfo>> lists() { return {field_list<R>()...}; }
};
using AllRequests = Requests<SayRequest, SignRequest, FingerspellRequest, GlossRequest, CheckRequest, InfoRequest,
                             ConvertRequest, CompressRequest, DecompressRequest, MouthRequest, ReachRequest,
                             RetargetRequest, RenderRequest, ViewRequest, SubtitlesRequest, AvatarRequest, LexiconQuery,
                             LexiconAddRequest, LexiconImportRequest, LexiconExportRequest, LexiconRemoveRequest>;

TEST(RequestFields, ASharedFieldIsSpelledTheSameInEveryRequest) {
  std::map<std::string, std::vector<FieldInfo>> by_name;
  AllRequests::collect_all(by_name);
  std::size_t shared = 0;
  for (const auto& [name, uses] : by_name) {
    shared += uses.size() > 1;
    for (const FieldInfo& f : uses) {
      if (f.positional || uses.front().positional) continue;
      EXPECT_EQ(f.short_flag, uses.front().short_flag) << name;
      EXPECT_EQ(f.negated, uses.front().negated) << name;
    }
  }
  EXPECT_GE(shared, 20u) << "the avatar, output and input fields are shared";
  // The flags the commands share, one spelling each: -o is always the output file.
  for (const char* name : {"output", "avatar", "size", "fps", "camera", "speed", "lang", "scale", "z_up", "skeleton", "db"})
    EXPECT_GE(by_name[name].size(), 2u) << name << " is shared";
  for (const FieldInfo& f : by_name["output"])
    if (!f.positional) {
      EXPECT_EQ(f.short_flag, 'o');
    }
  for (const auto& [name, uses] : by_name)
    for (char c : name) EXPECT_TRUE((c >= 'a' && c <= 'z') || c == '_') << "field names are snake_case: " << name;
}

TEST(RequestFields, EachRequestNamesAFieldOnce) {
  for (const auto& list : AllRequests::lists()) {
    std::set<std::string> names;
    for (const FieldInfo& f : list) EXPECT_TRUE(names.insert(std::string(f.name)).second) << f.name;
  }
}

}  // namespace
