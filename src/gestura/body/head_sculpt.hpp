#pragma once
// The default avatar's head as one sculpted surface (realtime-virtual-humans.txt §2.1 sculpts the
// head apart from the body): a radius for every direction from the head's centre, so the head is
// smooth and exactly mirror-symmetric by construction. The radius is an egg-shaped skull plus a
// face mask whose midline follows a profile through the soft-tissue landmarks (glabella, nasion,
// subnasale, the lips, pogonion, gnathion), plus nose, lips, brow ridge, cheekbones, eye sockets,
// mentolabial sulcus and jaw angles as smooth bumps laid out in the face's own angles. Sizes are
// from head and face anthropometry (Farkas 1994; docs/avatar.md), scaled with the stature.
//
// The mouth: an oral cavity and the slit between the lips are carved out at rest, where the lips
// meet on the "hinge plane" through the jaw joint and the mouth line. The surface is polygonised
// with the jaw open (a hinge warp about the jaw joint: everything below the plane turns down,
// the wedge this opens between the lips stays empty, the cheeks stretch smoothly), so the lips
// come out as two separate sheets with the cavity behind; jaw_weight() is the warp's share at a
// point, which is both the jaw's skin weight and what turns the mesh back to the closed mouth.
#include <array>
#include <memory>

#include "gestura/body/avatar_params.hpp"
#include "gestura/body/implicit_body.hpp"

namespace gestura {

// Where the face's features are, in model space (metres) at rest, for the params' stature, sex
// and build: shared by the sculpt, its materials, the rigid face parts and the facial morphs.
struct FaceLandmarks {
  vec3 centre;          // of the radial sculpt
  vec3 jaw_pivot;       // the temporomandibular joint
  float mouth_y = 0.0f; // the mouth line (stomion) at the midline
  float lip_front = 0.0f;     // z of the lips' front at the midline
  float mouth_half_width = 0.0f;  // cheilion to the midline
  float chin_y = 0.0f;        // gnathion
  float brow_y = 0.0f;        // the brows' middle line
  float brow_z = 0.0f;
  vec3 cheek;           // the left cheek's apex
  float k = 1.0f;       // stature / 1.70 m
};

class HeadSculpt final : public Sculpt {
 public:
  // `jaw_pivot`: the skeleton's temporomandibular joint; `eyes`: the eyeball joints (left, right);
  // `bind_open_degrees`: how far the jaw is open in the surface this sculpt describes.
  HeadSculpt(const AvatarParams& params, vec3 jaw_pivot, std::array<vec3, 2> eyes, float bind_open_degrees);

  float distance(const vec3& p) const override;  // model space, jaw open by the bind angle
  void bounds(vec3& lo, vec3& hi) const override;
  int material(const vec3& p) const override;    // Lips on the vermilion, Mouth in the cavity
  float size() const override { return 0.03f * k_; }

  // The closed-mouth (rest) field and the hinge warp.
  float rest_distance(const vec3& p) const;
  float jaw_weight(const vec3& bind_point) const;  // 0 (skull) .. 1 (jaw)
  vec3 to_rest(const vec3& bind_point) const;

  // Negative on the lips' vermilion (red part), positive elsewhere; roughly metres. At rest.
  float lip_field(const vec3& rest_point) const;
  // The same for a point of the open-mouthed surface, positive on the mouth's lining (where the
  // vermilion's outline would reach into the mouth at its corners).
  float vermilion(const vec3& bind_point) const;
  const FaceLandmarks& landmarks() const { return marks_; }
  // The uncarved head's radius from landmarks().centre in a direction (radians: azimuth from the
  // front towards the avatar's left, elevation up), in metres at 1.70 m (times k for the avatar).
  float radius(float azimuth, float elevation) const;
  float radius_towards(const vec3& unit_direction) const;  // the same for a unit direction

 private:
  float carved(const vec3& rest_point) const;          // the cavity and slit (negative inside)
  float hinge_angle(const vec3& p) const;              // ψ: + above the hinge plane

  float k_;
  Sex sex_;
  float build_;
  FaceLandmarks marks_;
  std::array<vec3, 2> eyes_;
  float bind_open_;  // radians
  vec3 hinge_dir_;   // from the pivot along the hinge plane towards the mouth (yz)
  float hinge_base_;  // its angle in the yz plane
  vec2 eye_angles_;   // the left eye's azimuth and elevation from the centre, degrees
};

// The hair over the scalp as a shell on the head: the head's radius plus the style's thickness
// above the hairline (avatar_material_borders.hpp's hair_field), a little less than the head's
// below it, so the hair rises out of the skin without a step. A bob hangs straight down past the
// ears to the jaw.
class HairSculpt final : public Sculpt {
 public:
  HairSculpt(std::shared_ptr<const HeadSculpt> head, HairStyle style);
  float distance(const vec3& p) const override;
  void bounds(vec3& lo, vec3& hi) const override;
  int material(const vec3& p) const override;
  float size() const override { return 0.03f * k_; }

 private:
  std::shared_ptr<const HeadSculpt> head_;
  HairStyle style_;
  float k_;
};

// The facial landmarks of an avatar with these params and skeleton joints (as HeadSculpt has).
FaceLandmarks face_landmarks(const AvatarParams& params, vec3 jaw_pivot);

}  // namespace gestura
