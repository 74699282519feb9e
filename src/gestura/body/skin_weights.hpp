#pragma once
// Automatic skin weights for a mesh generated from an ImplicitBody, three ways:
//
//  InfluenceSpheres — mpeg4-humanoid-animation.txt §3: each vertex first belongs to one bone (the
//    bone of its nearest primitive); each joint has an influence sphere of radius ρ (the limb's
//    local radius); inside it the child bone gets w = 0.5·(ρ + α·d)/ρ, d the distance to the joint
//    centre, α = +1 for vertices of the child bone and −1 for the parent's, the parent 1 − w; the
//    weight vector is normalised.
//  TwoLayerBending — sign-language-interpreter.txt §4.2: the vertices shared by two segments (a
//    neighbour belongs to the other bone) get 0.5/0.5, their neighbours 0.8/0.2; all others are
//    rigid.
//  FieldDiffused (default) — each bone's weight is the smooth share of its primitives in the field
//    (exp(−d/σ) with σ tied to the primitive's size), then a few rounds of Laplacian diffusion over
//    the mesh so that creases at elbows, wrists, knuckles and shoulders bend gradually. A vertex
//    keeps only bones within two skeleton steps of its own (a farther bone's share goes to the bone
//    two steps towards it), so the chest wall does not follow the upper arm hanging beside it.
//
// All methods keep at most four influences per vertex, sorted by weight, summing to 1.
#include <cstdint>
#include <string_view>

#include "gestura/body/implicit_body.hpp"
#include "gestura/body/mesh.hpp"
#include "gestura/skeleton/skeleton.hpp"

namespace gestura {

enum class SkinWeightMethod : std::uint8_t { InfluenceSpheres, TwoLayerBending, FieldDiffused };

std::string_view to_string(SkinWeightMethod method);
// "spheres", "two-layer", "field" ; throws gestura::Error otherwise.
SkinWeightMethod parse_skin_weight_method(std::string_view text);

// Fills mesh.joints and mesh.weights from mesh.positions and mesh.indices.
void compute_skin_weights(const Skeleton& skeleton, const ImplicitBody& body, SkinWeightMethod method, Mesh& mesh);

}  // namespace gestura
