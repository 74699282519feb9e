#include "gestura/core/output_limits.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "gestura/core/error.hpp"

namespace gestura {

namespace {

std::string seconds_text(double seconds) {
  char text[64];
  std::snprintf(text, sizeof text, "%.1f s", seconds);
  return text;
}

}  // namespace

std::int64_t check_output_length(double seconds, double fps, std::string_view what) {
  const std::string name(what);
  if (!std::isfinite(seconds) || seconds < 0.0) throw Error(name + ": the motion has no valid duration");
  if (!(fps > 0.0) || !std::isfinite(fps)) throw Error(name + ": the frame rate must be positive");
  if (seconds > kMaxUtteranceSeconds)
    throw Error(name + ": the motion lasts " + seconds_text(seconds) + ", more than the limit of " +
                seconds_text(kMaxUtteranceSeconds) + " (kMaxUtteranceSeconds, 4 hours)");
  const double frames = std::floor(seconds * fps + 1e-6) + 1.0;
  if (frames > static_cast<double>(kMaxOutputFrames))
    throw Error(name + ": " + std::to_string(static_cast<long long>(frames)) + " frames, more than the limit of " +
                std::to_string(kMaxOutputFrames) + " frames (kMaxOutputFrames, 4 hours at 60 fps)");
  return static_cast<std::int64_t>(frames);
}

void check_output_size(std::uint64_t bytes, std::string_view what) {
  if (bytes > kMaxOutputBytes)
    throw Error(std::string(what) + ": the output would pass the limit of " + std::to_string(kMaxOutputBytes) +
                " bytes (kMaxOutputBytes, 4 GiB)");
}

}  // namespace gestura
