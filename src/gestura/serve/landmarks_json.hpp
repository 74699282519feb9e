#pragma once
// A room's `landmarks` message (docs/api.md, "Driving your avatar with your body") read into
// plain data for the motion-capture fit. Everything a client sends is checked here, before any
// work is queued: part sizes, point shapes, finite numbers within the ranges MediaPipe reports.
#include <nlohmann/json.hpp>

#include "gestura/mocap/holistic_fit.hpp"

namespace gestura::serve {

// Coordinates are picture-normalised: a point a little outside the picture is fine, one ten
// pictures away is not a landmark.
inline constexpr double kLandmarkRange = 10.0;

// Throws app::AppError (usage) naming the field and the point, e.g. "pose[3][1]".
HolisticFrame landmarks_from_json(const nlohmann::json& message);

}  // namespace gestura::serve
