#pragma once
// The jaw joint driven by the jaw_open channel (face_channels.hpp): temporomandibular pitch =
// jaw_open · kJawOpenMaxDegrees, keyed at the channel's keys.
#include "gestura/anim/clip.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::face {

// Replaces the temporomandibular track with one following the clip's jaw_open channel. Does
// nothing when the clip has no such channel or the skeleton no such joint (the caller knows its
// avatar). Sizes the clip's joint tracks to the skeleton when it has none.
void write_jaw_from_channel(const Skeleton& skeleton, Clip& clip);

}  // namespace gestura::face
