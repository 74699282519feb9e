#pragma once
// Mouthing: the English word a sign stands for, silently articulated while the sign is made. The
// word's visemes are stretched over the sign's [start, end], so articulation starts and ends with
// the gesture (ukrainian-sign-language-3d-model.txt). ASL mouthing is often partial, hence the
// amplitude.
#include <string_view>
#include <vector>

#include "gestura/anim/clip.hpp"
#include "gestura/face/face_action.hpp"

namespace gestura::face {

struct MouthingOptions {
  float amplitude = 1.0f;  // 1 = full articulation; ~0.5 for the reduced mouthing common in ASL
};

// Appends the viseme, jaw_open and mouthPucker actions for `word` over [start, end]. A word without
// letters, or end <= start, adds nothing. Throws gestura::Error (from phonemize) for invalid UTF-8,
// an over-long word, or a missing eSpeak NG, and for non-finite times.
void append_mouthing(std::string_view word, float start, float end, const MouthingOptions& options,
                     std::vector<FaceAction>& out);

// One word into a clip: append_mouthing + write_face_channels (which replaces the channels it writes;
// for a sentence, append every word's actions first and write once).
void add_mouthing(std::string_view word, float start, float end, const MouthingOptions& options, Clip& clip);

}  // namespace gestura::face
