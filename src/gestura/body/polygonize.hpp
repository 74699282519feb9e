#pragma once
// Polygonises an ImplicitBody into a closed, manifold, consistently oriented triangle mesh.
//
// Marching cubes with the case triangulation derived per cell rather than read from a table: on
// every cube face the sign changes are paired into segments (ambiguous faces decided by the
// bilinear saddle value, which depends on that face's four values only, so both cubes sharing the
// face agree); the segments of a cube close into polygons that are fanned into triangles. Because
// neighbouring cubes agree on every face, the surface has no cracks and every edge has exactly two
// triangles.
//
// Detail where it matters: the coarse lattice leaves out axis-aligned detail boxes (hands, head),
// each polygonised on its own lattice `refine` times finer. The surface must enter a box through
// one face only (the open face: wrist, neck); the coarse lattice stops one cell short of that face
// and the two boundary loops are joined by a band of triangles, so the result is one closed
// surface.
#include <cstdint>
#include <vector>

#include "gestura/body/implicit_body.hpp"

namespace gestura {

struct DetailBox {
  vec3 lo{0.0f}, hi{0.0f};  // world bounds (snapped outwards to the coarse lattice)
  int refine = 4;           // fine cell = coarse cell / refine
  int open_axis = 1;        // the face the body enters through: axis 0/1/2 …
  int open_side = 1;        // … at hi (+1) or lo (−1)
};

struct PolygonizeOptions {
  float cell = 0.013f;  // coarse cell edge, metres
  std::vector<DetailBox> detail;
};

struct Polygonization {
  std::vector<vec3> positions;
  std::vector<std::uint32_t> indices;  // counter-clockwise seen from outside (field > 0)
  int active_blocks = 0;
};

// Throws gestura::Error for a non-positive cell, a bad detail box, or a surface that crosses a
// detail box elsewhere than once through its open face.
Polygonization polygonize(const ImplicitBody& body, const PolygonizeOptions& options);

}  // namespace gestura
