#pragma once
// Caps on what one run may produce. Every output path checks them before it does the work, so
// hostile or mistaken input (a huge text, a sign repeated thousands of times) ends in an error
// naming the limit instead of hours of CPU and a disk filled. The caps are generous for real use:
// a three-hour television programme signed at 60 frames a second fits.
//
// The caps on one sign (its repetitions, the actions it performs) are where the notation is read:
// gestura/sign/sign_limits.hpp.
#include <cstdint>
#include <string_view>

namespace gestura {

// The longest motion or video one command writes: 4 hours.
inline constexpr double kMaxUtteranceSeconds = 4.0 * 3600.0;
// The most frames one output holds: 4 hours at 60 frames a second.
inline constexpr std::int64_t kMaxOutputFrames = 4 * 3600 * 60;
// The largest file one output writes: 4 GiB.
inline constexpr std::uint64_t kMaxOutputBytes = std::uint64_t{4} << 30;

// Throws gestura::Error naming `what` (the output) and the limit when `seconds` of motion sampled
// at `fps` would pass kMaxUtteranceSeconds or kMaxOutputFrames. Returns the frame count
// floor(seconds * fps) + 1.
std::int64_t check_output_length(double seconds, double fps, std::string_view what);

// Throws gestura::Error naming `what` and kMaxOutputBytes when `bytes` pass it.
void check_output_size(std::uint64_t bytes, std::string_view what);

}  // namespace gestura
