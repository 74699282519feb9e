#include "gestura/body/head_sculpt.hpp"

#include <algorithm>
#include <cmath>

#include "gestura/body/avatar_material_borders.hpp"
#include "gestura/body/avatar_proportions.hpp"
#include "gestura/body/mesh.hpp"
#include "gestura/body/natural_spline.hpp"

namespace gestura {
namespace {

float clamp01(float t) { return std::clamp(t, 0.0f, 1.0f); }
// 0 at e0, 1 at e1 (either order), C2 between (smootherstep): the shading follows the surface's
// curvature, so where that jumps the shading shows a line.
float ramp(float e0, float e1, float x) {
  const float t = clamp01((x - e0) / (e1 - e0));
  return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}
// A compact, C2 bump of a squared normalised distance: 1 at the centre, 0 from 1 on.
float bump(float d2) {
  if (d2 >= 1.0f) return 0.0f;
  const float u = 1.0f - d2;
  return u * u * u;
}
// An elliptical bump in the face's angles (degrees): centre (±t0, p0), radii (rt, rp); `t` is the
// signed azimuth and the bump is mirrored, so a pair reaching across the midline stays smooth there.
float bump_at(float t, float p, float t0, float p0, float rt, float rp) {
  const float dp = (p - p0) / rp;
  const float a = (t - t0) / rt, b = (t + t0) / rt;
  return bump(a * a + dp * dp) + (t0 != 0.0f ? bump(b * b + dp * dp) : 0.0f);
}
float smin(float a, float b, float k) {
  const float h = std::max(k - std::abs(a - b), 0.0f) / k;
  return std::min(a, b) - h * h * k * 0.25f;
}
float smax(float a, float b, float k) { return -smin(-a, -b, k); }

// atan2 within 1e-5 rad (a minimax polynomial on [0, 1] and the octant's symmetries): the head's
// field takes the direction's angles at every point the polygoniser samples.
float fast_atan2(float y, float x) {
  const float ax = std::abs(x), ay = std::abs(y);
  const float big = std::max(ax, ay), small = std::min(ax, ay);
  if (big == 0.0f) return 0.0f;
  const float z = small / big, z2 = z * z;
  float a = z * (0.99997726f + z2 * (-0.33262347f + z2 * (0.19354346f + z2 * (-0.11643287f + z2 * (0.05265332f + z2 * -0.01172120f)))));
  if (ay > ax) a = 1.57079633f - a;
  if (x < 0.0f) a = 3.14159265f - a;
  return y < 0.0f ? -a : a;
}

float ellipsoid_distance(vec3 q, vec3 r) {
  const float k0 = glm::length(q / r), k1 = glm::length(q / (r * r));
  return k1 > 0.0f ? k0 * (k0 - 1.0f) / k1 : -std::min(r.x, std::min(r.y, r.z));
}

// The face's midline, as the radius of the face plane (without nose and lips) from the sculpt's
// centre by elevation (degrees), at 1.70 m: forehead, the nasal root's dip, the muzzle over the
// teeth, the chin and the jaw's underside (knots from the soft-tissue landmarks, docs/avatar.md).
const NaturalSpline kMidline{{{-90.0f, 0.1240f},
                           {-82.5f, 0.1220f},
                           {-72.5f, 0.1195f},
                           {-60.6f, 0.1263f},
                           {-55.0f, 0.1271f},
                           {-50.0f, 0.1239f},
                           {-46.5f, 0.1103f},
                           {-38.8f, 0.1020f},
                           {-35.4f, 0.0985f},
                           {-28.6f, 0.0958f},
                           {-23.5f, 0.0927f},
                           {-8.0f, 0.0895f},
                           {9.8f, 0.0883f},
                           {18.4f, 0.0960f},
                           {44.0f, 0.1139f}}};
// Half-width (degrees of azimuth) over which the face plane blends into the skull, by elevation.
const NaturalSpline kMaskHalfWidth{
    {{-75.0f, 44.0f}, {-55.0f, 48.0f}, {-40.0f, 55.0f}, {-25.0f, 58.0f}, {-5.0f, 61.0f}, {15.0f, 62.0f}, {40.0f, 64.0f}}};
// The nose's height over the face plane along its dorsum (metres at 1.70 m) and half-width
// (degrees), by elevation: nasal root, dorsum, tip (pronasale), columella down to the subnasale.
const NaturalSpline kNoseHeight{{{-25.0f, 0.0f},
                               {-23.0f, 0.0030f},
                               {-20.0f, 0.0100f},
                               {-17.0f, 0.0150f},
                               {-14.5f, 0.0155f},
                               {-11.0f, 0.0135f},
                               {-5.0f, 0.0095f},
                               {1.0f, 0.0060f},
                               {6.0f, 0.0035f},
                               {10.0f, 0.0012f},
                               {14.0f, 0.0f}}};
const NaturalSpline kNoseHalfWidth{
    {{-24.0f, 8.6f}, {-18.0f, 8.0f}, {-13.0f, 6.4f}, {-6.0f, 5.2f}, {2.0f, 4.6f}, {10.0f, 4.8f}}};

}  // namespace

FaceLandmarks face_landmarks(const AvatarParams& params, vec3 jaw_pivot) {
  const float k = params.height / 1.70f;
  FaceLandmarks m;
  m.k = k;
  m.centre = vec3(0.0f, 1.583f, 0.004f) * k;
  m.jaw_pivot = jaw_pivot;
  m.mouth_y = proportions::kMouthLineY * k;
  m.lip_front = 0.0910f * k;
  m.mouth_half_width = proportions::by_sex(params.sex, 0.0250f, 0.0262f, 0.0272f) * k;
  m.chin_y = 1.479f * k;
  m.brow_y = 1.6205f * k;
  m.brow_z = 0.0905f * k;
  m.cheek = vec3(0.040f, 1.560f, 0.079f) * k;
  return m;
}

HeadSculpt::HeadSculpt(const AvatarParams& params, vec3 jaw_pivot, std::array<vec3, 2> eyes, float bind_open_degrees)
    : k_(params.height / 1.70f),
      sex_(params.sex),
      build_(params.build),
      marks_(face_landmarks(params, jaw_pivot)),
      eyes_(eyes),
      bind_open_(deg(bind_open_degrees)) {
  const vec3 mouth(0.0f, marks_.mouth_y, marks_.lip_front - 0.004f * k_);
  hinge_dir_ = glm::normalize(vec3(0.0f, mouth.y - jaw_pivot.y, mouth.z - jaw_pivot.z));
  hinge_base_ = fast_atan2(hinge_dir_.y, hinge_dir_.z);
  const vec3 eye = (eyes_[0] - marks_.centre) / k_;
  eye_angles_ = vec2(to_degrees(std::atan2(eye.x, eye.z)), to_degrees(std::asin(eye.y / glm::length(eye))));
}

float HeadSculpt::radius(float azimuth, float elevation) const {
  return radius_towards(vec3(std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)));
}

float HeadSculpt::radius_towards(const vec3& u) const {
  const float azimuth = fast_atan2(u.x, u.z);
  const float elevation = fast_atan2(u.y, std::sqrt(std::max(0.0f, u.x * u.x + u.z * u.z)));
  const float ts = to_degrees(azimuth), t = std::abs(ts), p = to_degrees(elevation);
  const float male = sex_ == Sex::Male ? 1.0f : 0.0f, female = sex_ == Sex::Female ? 1.0f : 0.0f;
  const float fuller = std::clamp(build_ - 1.0f, -0.4f, 0.6f);  // soft tissue of heavier builds

  // The skull: an egg, wider above the ears than at the jaw, longer behind than in front.
  const float ux = std::abs(u.x), uy = u.y, uz = u.z;
  const float horizontal = std::sqrt(std::max(0.0f, u.x * u.x + u.z * u.z));
  const float jaw_taper = proportions::by_sex(sex_, 0.11f, 0.08f, 0.05f);
  const float ax = (0.0745f + 0.0015f * male - 0.002f * female + 0.004f * fuller) * (1.0f - jaw_taper * ramp(-5.0f, -62.0f, p));
  const float ay = 0.112f + 0.006f * ramp(-25.0f, 25.0f, p);
  // Deeper towards the chin, so the face's lower profile is mostly the egg's own (a large face
  // mask there would show its edge as a line down the cheeks).
  const float az_front = 0.098f + 0.019f * ramp(-15.0f, -58.0f, p);
  const float az = az_front + (0.101f - az_front) * ramp(40.0f, 140.0f, t);
  const float egg = 1.0f / std::sqrt((ux / ax) * (ux / ax) + (uy / ay) * (uy / ay) + (uz / az) * (uz / az));
  const float egg_mid = 1.0f / std::sqrt((uy / ay) * (uy / ay) + (horizontal / az_front) * (horizontal / az_front));

  // The face plane over the front, blending into the skull's sides.
  float r = egg;
  const float mid = kMidline(p) + 0.002f * fuller * ramp(-20.0f, -50.0f, p);
  const float half = kMaskHalfWidth(p);
  const float across = t / half;
  const float mask = (1.0f - ramp(0.15f, 1.0f, across)) * (1.0f - ramp(40.0f, 55.0f, p)) * (1.0f - ramp(-80.0f, -92.0f, p));
  r += (mid - egg_mid) * mask;

  // Nose: dorsum from the nasal root to the tip, the rounded tip, the alae.
  // Across the dorsum (1 - x²)³ (1 + 2.7 x²): C2 where it meets the face like (1 - x²)³, but its
  // top is ten times less curved (a ridge about 5 mm round instead of 1 mm, which 4 mm triangles
  // drew as a sharp edge), so it is a little narrower for the same fullness.
  const float nose_half = 0.85f * kNoseHalfWidth(p);
  const float nose_size = proportions::by_sex(sex_, 0.90f, 1.0f, 1.10f);
  const float across_nose = t / nose_half;
  if (across_nose < 1.0f) {
    const float x2 = across_nose * across_nose, profile = 1.0f - x2;
    r += nose_size * kNoseHeight(p) * profile * profile * profile * (1.0f + 2.7f * x2);
  }
  r += nose_size * (0.0028f * bump_at(ts, p, 0.0f, -15.0f, 6.0f, 4.2f) + 0.0042f * bump_at(ts, p, 9.0f, -20.5f, 5.0f, 4.0f));

  // Lips: the upper vermilion with its bow and the philtrum above, the fuller lower lip, the
  // corners and the groove under the lower lip.
  const float lips = proportions::by_sex(sex_, 1.15f, 1.0f, 0.9f);
  r += lips * (0.0050f * bump_at(ts, p, 0.0f, -29.5f, 16.0f, 4.0f) + 0.0009f * bump_at(ts, p, 3.5f, -27.8f, 3.0f, 2.0f) -
               0.0008f * bump_at(ts, p, 0.0f, -25.5f, 1.8f, 4.0f) + 0.0064f * bump_at(ts, p, 0.0f, -38.5f, 14.5f, 4.2f));
  r -= 0.0020f * bump_at(ts, p, 15.5f, -34.5f, 3.2f, 3.0f);

  // Brow ridge (stronger in men), eye sockets, cheekbones, temples and the jaw's angles.
  const float brow = 0.0028f + 0.0020f * male - 0.0013f * female;
  r += brow * bump_at(ts, p, 14.0f, 15.5f, 20.0f, 6.5f);
  // The eyes set deeper under the brow and the cheekbones fuller: with less, the profile read flat
  // (eye, cheek and mouth nearly in one plane behind the nose).
  r -= 0.0058f * bump_at(ts, p, eye_angles_.x, eye_angles_.y, 11.0f, 8.5f);
  r += (0.0036f + 0.001f * fuller) * bump_at(ts, p, 38.0f, -8.0f, 20.0f, 13.0f);
  r -= 0.0015f * bump_at(ts, p, 64.0f, 17.0f, 16.0f, 14.0f);
  r += (0.0030f + 0.002f * fuller) * bump_at(ts, p, 36.0f, -28.0f, 22.0f, 14.0f);  // the cheeks over the teeth
  r += (0.0028f + 0.0015f * male - 0.0010f * female) * bump_at(ts, p, 70.0f, -48.0f, 18.0f, 13.0f);
  return r;
}

float HeadSculpt::carved(const vec3& rest) const {
  const vec3 q = rest / k_;
  const float y = marks_.mouth_y / k_;
  // The oral cavity: a flattened egg behind the lips, across the mouth line.
  const float cavity = ellipsoid_distance(q - vec3(0.0f, y - 0.0005f, 0.0505f), vec3(0.0225f, 0.0110f, 0.0205f));
  // The slit: a thin disc in the hinge plane from the cavity out through the lips.
  const vec3 pivot = marks_.jaw_pivot / k_;
  const vec3 along = hinge_dir_;
  const vec3 normal = glm::cross(vec3(1, 0, 0), along);  // points up
  const vec3 centre = pivot + along * (glm::dot(vec3(0.0f, y, 0.085f) - pivot, along));
  const vec3 d = q - centre;
  const vec3 local(d.x, glm::dot(d, normal), glm::dot(d, along));
  const float half = marks_.mouth_half_width / k_;
  // An elliptic disc: its outline in the plane, its thickness across (a flat ellipsoid's distance
  // would measure along the plane inside it).
  const vec2 in_plane(local.x / half, local.z / 0.028f);
  const float outline = (glm::length(in_plane) - 1.0f) * std::min(half, 0.028f);
  // Hairline thin where the lips meet, opening up towards the cavity (hidden behind the lips), so
  // the cavity is one with the mouth even on a coarse lattice.
  const float thickness = 0.0002f + 0.0030f * ramp(-0.004f, -0.020f, local.z);
  const float slit = std::max(outline, std::abs(local.y) - thickness);
  return smin(cavity, slit, 0.0015f) * k_;
}

float HeadSculpt::rest_distance(const vec3& p) const {
  const vec3 q = (p - marks_.centre) / k_;
  const float len = glm::length(q);
  if (len < 1e-6f) return -0.1f * k_;
  const float outer = 0.9f * (len - radius_towards(q / len)) * k_;
  return smax(outer, -carved(p), 0.0010f * k_);
}

float HeadSculpt::hinge_angle(const vec3& p) const {
  const vec3 v = p - marks_.jaw_pivot;
  const float a = fast_atan2(v.y, v.z) - hinge_base_;
  return std::remainder(a, 2.0f * kPi);
}

float HeadSculpt::jaw_weight(const vec3& p) const {
  const float psi = hinge_angle(p);
  const float open = std::max(bind_open_, deg(0.5f));
  const float collapse = clamp01(-psi / open);                     // the wedge between the lips
  const float smooth = ramp(deg(2.0f), -deg(20.0f), psi);          // the cheeks, stretched
  const float half = marks_.mouth_half_width;
  // Across the mouth's corners the jaw's share falls from the lips' (collapse) to the cheeks'
  // (smooth) over 1.1 half-widths: over 0.3 the shear of closing the mouth from the bind angle
  // drew a crease from each corner down to the jaw.
  const float mouth = (1.0f - ramp(0.90f * half, 2.00f * half, std::abs(p.x))) *
                      ramp(marks_.jaw_pivot.z - 0.001f * k_, marks_.jaw_pivot.z + 0.007f * k_, p.z);
  const float front = ramp(marks_.jaw_pivot.z - 0.040f * k_, marks_.jaw_pivot.z - 0.005f * k_, p.z);
  return front * (smooth + (collapse - smooth) * mouth);
}

vec3 HeadSculpt::to_rest(const vec3& p) const {
  const float w = jaw_weight(p);
  if (w <= 0.0f) return p;
  const quat turn = glm::angleAxis(-bind_open_ * w, vec3(1, 0, 0));
  return marks_.jaw_pivot + turn * (p - marks_.jaw_pivot);
}

float HeadSculpt::distance(const vec3& p) const {
  const float d = rest_distance(to_rest(p));
  // Inside the wedge the open jaw leaves between the lips every point maps onto the closed mouth's
  // slit, where the field is flat: there the distance to the nearer lip is the field (so the
  // polygoniser places the lips' inner walls where they are).
  const float psi = hinge_angle(p);
  if (d > 0.0f && psi < 0.0f && psi > -bind_open_) {
    const vec3 v = p - marks_.jaw_pivot;
    const float arm = std::sqrt(v.y * v.y + v.z * v.z);
    return std::max(d, arm * std::sin(std::min(-psi, bind_open_ + psi)));
  }
  return d;
}

void HeadSculpt::bounds(vec3& lo, vec3& hi) const {
  lo = marks_.centre + vec3(-0.100f, -0.165f, -0.115f) * k_;
  hi = marks_.centre + vec3(0.100f, 0.130f, 0.145f) * k_;
}

float HeadSculpt::lip_field(const vec3& rest) const {
  const vec3 q = (rest - marks_.centre) / k_;
  const float len = glm::length(q);
  if (len < 1e-6f) return 1.0f;
  const float t = std::abs(to_degrees(std::atan2(q.x, q.z))), p = to_degrees(std::asin(std::clamp(q.y / len, -1.0f, 1.0f)));
  // The vermilion's outline in the face's angles: the corners, the upper border with its bow,
  // the lower border.
  // (The vermilion ends a little short of the commissure, so it does not run out into a sliver.)
  const float corner_t = 0.92f * to_degrees(std::atan2(marks_.mouth_half_width / k_, 0.080f));
  const float corner_p = -35.0f;
  const float across = std::min(t / corner_t, 1.0f);
  const float open = std::pow(std::max(0.0f, 1.0f - across * across), 0.65f);
  const float upper = corner_p + 6.2f * open + 0.55f * bump_at(t, 0.0f, 3.6f, 0.0f, 2.6f, 1.0f) -
                      0.35f * bump_at(t, 0.0f, 0.0f, 0.0f, 1.6f, 1.0f);
  const float lower = corner_p - 5.2f * std::pow(std::max(0.0f, 1.0f - across * across), 0.55f);
  const float inside = std::min({p - lower, upper - p, (corner_t - t) * 0.8f});  // degrees, + inside
  return -deg(inside) * len * k_;
}

namespace {
// How far a rest point lies inside the uncarved head (negative inside), metres.
float depth_in(const HeadSculpt& head, const vec3& rest) {
  const FaceLandmarks& m = head.landmarks();
  const vec3 q = (rest - m.centre) / m.k;
  const float len = glm::length(q);
  if (len < 1e-6f) return -1.0f;
  return (len - head.radius_towards(q / len)) * m.k;
}
}  // namespace

float HeadSculpt::vermilion(const vec3& p) const {
  const vec3 rest = to_rest(p);
  return depth_in(*this, rest) < -0.0030f * k_ ? 0.01f * k_ : lip_field(rest);
}

int HeadSculpt::material(const vec3& p) const {
  const vec3 rest = to_rest(p);
  // Deeper than the lips' rounded edge inside the uncarved head: the mouth's lining; the vermilion
  // only on the outer skin (not on the lining at the mouth's corners).
  const bool inside = depth_in(*this, rest) < -0.0030f * k_;
  if (inside && std::abs(carved(rest)) < 0.0025f * k_) return static_cast<int>(MaterialId::Mouth);
  if (!inside && lip_field(rest) < 0.0f) return static_cast<int>(MaterialId::Lips);
  return static_cast<int>(MaterialId::Skin);
}

HairSculpt::HairSculpt(std::shared_ptr<const HeadSculpt> head, HairStyle style)
    : head_(std::move(head)), style_(style), k_(head_->landmarks().k) {}

float HairSculpt::distance(const vec3& bind_point) const {
  // Through the head's hinge warp, so hair that reaches the jaw stays on it.
  const vec3 p = head_->to_rest(bind_point);
  const vec3 centre = head_->landmarks().centre;
  const vec3 q = (p - centre) / k_;
  const float len = glm::length(q);
  if (len < 1e-6f) return -0.1f * k_;
  const vec3 u = q / len;
  const float r = head_->radius_towards(u);
  const float elevation = fast_atan2(u.y, std::sqrt(std::max(0.0f, u.x * u.x + u.z * u.z)));
  const float azimuth = fast_atan2(u.x, u.z);
  const vec3 skin = centre + q / len * (r * k_);
  const float line = hair_field(skin, k_, style_);
  const float el = to_degrees(elevation), around = std::abs(to_degrees(azimuth));
  float thick = 0.0f, covered = 0.0f;
  switch (style_) {
    case HairStyle::Short:
      // The shell rises over 3 cm above the hairline: over 1.6 cm its edge stood as a ledge that
      // the head box's 4 mm cells drew ragged in side views.
      covered = ramp(0.002f * k_, -0.030f * k_, line);
      thick = 0.0055f + 0.0045f * ramp(5.0f, 60.0f, el);
      break;
    case HairStyle::Buzz:
      covered = ramp(0.001f * k_, -0.004f * k_, line);
      thick = 0.0018f;
      break;
    case HairStyle::Curly:
      covered = ramp(0.002f * k_, -0.030f * k_, line);
      thick = 0.014f + 0.010f * ramp(0.0f, 60.0f, el);
      break;
    case HairStyle::Bun:
      covered = ramp(0.002f * k_, -0.018f * k_, line);
      thick = 0.0035f + 0.0015f * ramp(10.0f, 60.0f, el);
      break;
    case HairStyle::Bob:
      covered = ramp(0.0010f * k_, -0.0080f * k_, line);
      // Fuller over the crown; below the skull's widest line it hangs straight down instead of
      // following the head in towards the neck.
      thick = 0.0085f + 0.0040f * ramp(10.0f, 60.0f, el) +
              0.024f * ramp(1.600f * k_, 1.515f * k_, skin.y) * ramp(55.0f, 95.0f, around);
      // Locks: shallow vertical waves round the back and sides, deepening towards the ends, so the
      // light breaks up the way it does on hair (one smooth shell read as a helmet from behind).
      // In |azimuth|, so both sides match.
      thick += 0.0022f * ramp(45.0f, 5.0f, el) * ramp(40.0f, 80.0f, around) *
               (0.5f + 0.5f * std::cos(deg(around) * 13.0f));
      break;
  }
  const float t = covered * thick - (1.0f - covered) * 0.003f;
  // Nothing of the shell below the hairline, where it lies inside the skin (and would stand out of
  // the lower face the hinge warp has turned away from it).
  return smax(0.9f * (len - r - t) * k_, line - 0.004f * k_, 0.002f * k_);
}

void HairSculpt::bounds(vec3& lo, vec3& hi) const {
  const vec3 c = head_->landmarks().centre;
  lo = c + vec3(-0.115f, -0.095f, -0.135f) * k_;
  hi = c + vec3(0.115f, 0.150f, 0.125f) * k_;
}

int HairSculpt::material(const vec3&) const { return static_cast<int>(MaterialId::Hair); }

}  // namespace gestura
