#pragma once
// How smooth and how symmetric a body surface is, as numbers a test or a benchmark can hold a
// generator to (the avatar must read as one smooth, mirror-symmetric skin at video size).
//
//   crease angle    the angle between the normals of two triangles sharing an edge: the faceting a
//                   viewer sees along the silhouette and wherever flat shading would show.
//   roughness       the angle between a vertex's shading normal and the mean shading normal of its
//                   neighbours: bumps and blotches one or two triangles across, which smooth
//                   shading does not hide.
//   asymmetry       the distance from a vertex's mirror image (x → −x) to the nearest point of the
//                   surface: 0 for a body that is its own mirror image.
//
// Only the triangles (and vertices) a region predicate accepts are measured, so the face, the hands
// and the trunk can be held to their own standards; material borders, the lips' seam and the eye
// openings are creases by design and can be left out by the predicate.
#include <functional>
#include <span>

#include "gestura/body/mesh.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

struct Spread {
  float mean = 0.0f, p95 = 0.0f, max = 0.0f;
  int count = 0;
};

struct SurfaceQuality {
  Spread crease_degrees;     // per interior edge of the region
  Spread roughness_degrees;  // per vertex of the region
  Spread asymmetry_mm;       // per vertex of the region (vertices within 1 mm of x = 0 skipped)
  float mean_edge_mm = 0.0f;
};

// `keep(triangle index)` selects the measured triangles; a vertex is measured when every triangle
// around it is kept. Asymmetry is measured against all triangles `keep` accepts (a mirror image
// that falls outside the region counts as far). Contract: mesh.normals filled, indices valid.
SurfaceQuality measure_surface(const Mesh& mesh, const std::function<bool(std::size_t triangle)>& keep);

// The regions of a humanoid body the avatar is held to: the face (the skin in front of the skull
// base, from the chin to the hairline, the eye openings left out), both hands (the skin beyond the
// wrists) and the clothed trunk between the hips and the shoulders. Triangles of lips, eyes, teeth,
// tongue and the mouth's lining are never measured. Needs skullbase, both eyeball joints and wrists
// (a missing joint leaves its region empty).
enum class BodyRegion { Face, Hands, Trunk };
SurfaceQuality measure_body_region(const Mesh& mesh, const Skeleton& skeleton, BodyRegion region);

// Distribution summary of `values` (sorted copy; empty gives zeros).
Spread spread_of(std::span<const float> values);

}  // namespace gestura
