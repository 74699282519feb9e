#pragma once
// Where the default avatar's materials meet, as smooth fields for sharpen_material_borders: the
// hairline (scalp against the skin of face, ears and neck), the eyebrows, and the shirt's cuffs
// and collar (cloth against the skin of hands and neck). The eyes and lips keep their own borders.
#include <array>
#include <vector>

#include "gestura/body/avatar_params.hpp"
#include "gestura/body/implicit_body.hpp"
#include "gestura/body/material_borders.hpp"

namespace gestura {

// Negative on the scalp above the hairline (forehead, temples, over the ears, nape), positive on
// the face, ears and neck below it; roughly metres. `k` is the avatar's height / 1.70 m. A bob
// covers the ears and the nape down to the jaw.
float hair_field(const vec3& p, float k, HairStyle style);

// Negative inside the left or right eyebrow (drawn on the brow ridge as seen from the front),
// positive elsewhere; `k` is the avatar's height / 1.70 m.
float eyebrow_field(const vec3& p, float k);

// Negative on the band of lashes along the upper lid's margin of the eye whose eyeball centre is
// `eye` (they take the brows' material); positive elsewhere.
float lash_field(const vec3& p, const vec3& eye, float k);

// The borders in the order they are to be sharpened; `body` must outlive them.
// `eyes`: the eyeball centres (left, right), for the lashes.
std::vector<MaterialBorder> avatar_material_borders(const ImplicitBody& body, float k, HairStyle style,
                                                   std::array<vec3, 2> eyes);

}  // namespace gestura
