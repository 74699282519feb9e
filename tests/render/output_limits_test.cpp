// The cap on one output's length: a render or a motion file longer than kMaxUtteranceSeconds
// (4 hours) stops before any work with an error naming the limit, and writes nothing.
#include <gtest/gtest.h>

#include <filesystem>

#include "gestura/anim/synthetic_motion.hpp"
#include "gestura/core/error.hpp"
#include "gestura/core/output_limits.hpp"
#include "gestura/io/bvh.hpp"
#include "gestura/io/joint_positions_json.hpp"
#include "gestura/render/render_job.hpp"
#include "support/test_figure.hpp"

namespace {

using namespace gestura;

template <class Body>
std::string error_of(Body&& body) {
  try {
    body();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(OutputLimits, AFiveHourVideoIsRefusedBeforeRendering) {
  RenderSubject subject = make_test_figure();
  subject.clip->duration = 5.0f * 3600.0f;  // a five-hour utterance
  RenderJob job;
  job.output = ::testing::TempDir() + "five_hours.mp4";
  job.size = {64, 48};
  std::filesystem::remove(job.output);
  const std::string message = error_of([&] { render_to_file(subject, job); });
  EXPECT_NE(message.find("kMaxUtteranceSeconds"), std::string::npos) << message;
  EXPECT_NE(message.find(job.output), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(job.output));
}

TEST(OutputLimits, MotionFilesHaveTheSameCap) {
  const Skeleton skeleton = synthetic_humanoid();
  Clip clip = synthetic_clip(skeleton, 1.0f, 30.0f);
  clip.duration = 5.0f * 3600.0f;
  EXPECT_NE(error_of([&] { make_bvh(skeleton, clip, 1.0f / 30.0f); }).find("kMaxUtteranceSeconds"), std::string::npos);
  EXPECT_NE(error_of([&] { joint_positions_json(skeleton, clip, 30.0f); }).find("kMaxUtteranceSeconds"),
            std::string::npos);
  clip.duration = 3600.0f;  // an hour at 1000 frames a second is too many frames
  EXPECT_NE(error_of([&] { joint_positions_json(skeleton, clip, 1000.0f); }).find("kMaxOutputFrames"),
            std::string::npos);
}

}  // namespace
