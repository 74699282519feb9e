#include "gestura/face/mouthing.hpp"

#include <cmath>
#include <string>

#include "gestura/core/error.hpp"
#include "gestura/face/phonemizer.hpp"
#include "gestura/face/viseme_track.hpp"

namespace gestura::face {

void append_mouthing(std::string_view word, float start, float end, const MouthingOptions& options,
                     std::vector<FaceAction>& out) {
  if (!std::isfinite(start) || !std::isfinite(end) || !std::isfinite(options.amplitude))
    throw Error("mouthing '" + std::string(word.substr(0, 40)) + "': non-finite time or amplitude");
  const std::vector<Phoneme> phonemes = phonemize(word);
  append_viseme_actions(phonemes, start, end, options.amplitude, out);
}

void add_mouthing(std::string_view word, float start, float end, const MouthingOptions& options, Clip& clip) {
  std::vector<FaceAction> actions;
  append_mouthing(word, start, end, options, actions);
  write_face_channels(actions, clip);
}

}  // namespace gestura::face
