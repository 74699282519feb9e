#pragma once
// The body's own collision volumes and their contacts (alias-movement-through-environments.txt §7.2:
// "find the volume of space the character is occupying and test that region against the
// environment"): one capsule per bone, fitted to the skin the bone carries, following the joints.
// Contacts are found in the environment's BVH (broad phase by the capsule's box, then exact
// capsule–triangle distances), between characters capsule against capsule, and with the ground
// (the soles against walkable surfaces).
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "gestura/body/avatar.hpp"
#include "gestura/world/environment.hpp"

namespace gestura {

struct BodyCapsule {
  std::string name;   // the bone: its joint's name
  int joint = -1;     // carried by this joint
  vec3 a{0.0f}, b{0.0f};  // segment ends in the joint's bind frame (model axes at rest)
  float radius = 0.0f;
  bool foot = false;  // touches the ground when standing (ankle and below)
};

// A point of the skin carried by a joint (the soles: where the feet meet the ground).
struct BodyPoint {
  int joint = -1;
  vec3 local{0.0f};  // in the joint's bind frame
};

struct BodyVolumes {
  std::vector<BodyCapsule> capsules;
  std::vector<BodyPoint> soles;  // each foot's lowest skin points per foot joint (heel, arch, ball, toes)
};

// One capsule per joint that carries skin, from the joint to the mean of its children (or along the
// skin it carries for end segments); the radius covers 95 % of that skin's vertices. Deterministic.
BodyVolumes make_body_volumes(const Avatar& avatar);

struct WorldCapsule {
  vec3 a{0.0f}, b{0.0f};
  float radius = 0.0f;
  int capsule = -1;  // index into BodyVolumes::capsules
  bool foot = false;
};

// The capsules placed by the joints' model (world) matrices.
void place_capsules(const BodyVolumes& volumes, std::span<const mat4> model, std::vector<WorldCapsule>& out);

struct Contact {
  float depth = 0.0f;     // how far the capsule goes into the surface (> 0: penetrating)
  vec3 point{0.0f};       // on the surface
  vec3 normal{0.0f};      // from the surface toward the capsule's axis
  int capsule = -1;
  int object = -1;
};

// The deepest contact of a capsule with the environment (depth ≥ −margin: touching within margin
// counts), or none. Walkable triangles are skipped for foot capsules (standing is not colliding).
std::optional<Contact> deepest_contact(const Environment& env, const WorldCapsule& capsule, float margin = 0.0f);

// Every capsule's deepest contact that penetrates deeper than `tolerance`.
std::vector<Contact> body_contacts(const Environment& env, std::span<const WorldCapsule> body, float tolerance = 0.0f);

// How far two bodies overlap (the deepest capsule pair; ≤ 0 when apart, as minus the gap).
float body_overlap(std::span<const WorldCapsule> a, std::span<const WorldCapsule> b, int* capsule_a = nullptr,
                   int* capsule_b = nullptr);

// Ground contact: the deepest the soles go below the ground under them (> 0: into it; < 0: the
// feet are off the ground by that much), for the joints' model matrices `model`.
float sole_penetration(const Environment& env, const BodyVolumes& volumes, std::span<const mat4> model);

}  // namespace gestura
