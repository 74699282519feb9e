#include "gestura/app/mouth.hpp"

#include <algorithm>

#include "gestura/face/mouthing.hpp"
#include "gestura/face/phonemizer.hpp"

namespace gestura::app {

void validate(const MouthRequest& request) {
  check_fields(request);
  if (!(request.end > request.start)) usage_error("end", "must be later than --start");
}

MouthResult run(const MouthRequest& request, const RunContext&) {
  validate(request);
  MouthResult result;
  as_field_error(ErrorCategory::input, "word", [&] {
    result.phonemes = face::phonemize(request.word);
    face::add_mouthing(request.word, request.start, request.end, face::MouthingOptions{request.amplitude}, result.clip);
  });
  return result;
}

nlohmann::json to_json(const MouthResult& result) {
  nlohmann::json out;
  auto& phonemes = out["phonemes"] = nlohmann::json::array();
  for (const face::Phoneme& p : result.phonemes)
    phonemes.push_back({{"symbol", p.symbol}, {"stress", p.stress == face::Stress::primary     ? "primary"
                                                         : p.stress == face::Stress::secondary ? "secondary"
                                                                                                : "none"}});
  auto& channels = out["channels"] = nlohmann::json::array();
  for (std::size_t c = 0; c < result.clip.channels.size(); ++c) {
    const auto& track = result.clip.channels[c];
    const auto peak = std::max_element(track.values.begin(), track.values.end());
    if (peak == track.values.end()) continue;
    channels.push_back({{"name", result.clip.channel_names[c]},
                        {"peak", *peak},
                        {"at", track.times[static_cast<std::size_t>(peak - track.values.begin())]},
                        {"keys", track.size()}});
  }
  return out;
}

}  // namespace gestura::app
