#pragma once
// The animation of one utterance for a web player that already holds the avatar (GET
// /api/avatar.glb): binary glTF with the skeleton's nodes and one animation, no body, made small
// for the wire (a sentence in tens of kilobytes, not the 19 MB of a .glb with the body):
// - every track is sampled at `fps` and keys that linear interpolation between their neighbours
//   reproduces (within 0.1° per joint, 0.5 mm, 0.005 of a morph weight) are dropped; a track that
//   never moves keeps one key;
// - rotations are written as normalised 16-bit integers (glTF core allows them for animation);
// - the face's morph weights drive a one-triangle stand-in mesh whose targets carry the avatar's
//   morph names in the avatar's order (mesh.extras.targetNames) and share one empty offset, so a
//   player moves the avatar's own targets by index.
// `extras` (glosses, timeline) is stored in the animation's extras.
#include <string>

#include <nlohmann/json.hpp>

#include "gestura/anim/clip.hpp"
#include "gestura/body/mesh.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura::serve {

struct ClipGlbOptions {
  float fps = 30.0f;
  float rotation_tolerance = 0.1f;      // degrees
  float translation_tolerance = 5e-4f;  // metres
  float weight_tolerance = 5e-3f;
};

// Contract: clip valid for skeleton; avatar_mesh is the avatar's (only its morph names are read).
std::string clip_glb(const Skeleton& skeleton, const Clip& clip, const Mesh& avatar_mesh, const nlohmann::json& extras,
                     const ClipGlbOptions& options = {});

// Indices of the frames kept so that linear interpolation between kept frames stays within
// `tolerance` of every frame: error(a, b, t) is the error at frame i of interpolating frames a..b
// (a < i < b). The first and last frames are always kept; a constant sequence keeps one.
template <class Error>
std::vector<std::size_t> reduce_keys(std::size_t frames, Error&& error, float tolerance) {
  std::vector<std::size_t> kept;
  if (frames == 0) return kept;
  kept.push_back(0);
  std::size_t a = 0;
  while (a + 1 < frames) {
    std::size_t b = a + 1;
    // Extend the segment while every frame inside it is reproduced.
    while (b + 1 < frames) {
      bool fits = true;
      for (std::size_t i = a + 1; i <= b && fits; ++i) fits = error(a, b + 1, i) <= tolerance;
      if (!fits) break;
      ++b;
    }
    kept.push_back(b);
    a = b;
  }
  return kept;
}

}  // namespace gestura::serve
