#include "gestura/body/body_sites.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <vector>

namespace gestura {

std::optional<RayHit> cast_ray(const Mesh& mesh, const vec3& origin, const vec3& direction) {
  // Möller–Trumbore over all triangles: a few hundred rays at bind pose, so brute force is fine.
  const vec3 dir = glm::normalize(direction);
  std::optional<RayHit> best;
  const std::size_t tris = mesh.indices.size() / 3;
  for (std::size_t t = 0; t < tris; ++t) {
    const vec3& a = mesh.positions[mesh.indices[3 * t]];
    const vec3& b = mesh.positions[mesh.indices[3 * t + 1]];
    const vec3& c = mesh.positions[mesh.indices[3 * t + 2]];
    const vec3 e1 = b - a, e2 = c - a;
    const vec3 p = glm::cross(dir, e2);
    const float det = glm::dot(e1, p);
    if (std::abs(det) < 1e-12f) continue;
    const float inv = 1.0f / det;
    const vec3 s = origin - a;
    const float u = glm::dot(s, p) * inv;
    if (u < 0.0f || u > 1.0f) continue;
    const vec3 q = glm::cross(s, e1);
    const float v = glm::dot(dir, q) * inv;
    if (v < 0.0f || u + v > 1.0f) continue;
    const float dist = glm::dot(e2, q) * inv;
    if (dist <= 1e-6f || (best && dist >= best->distance)) continue;
    best = RayHit{dist, origin + dir * dist, glm::normalize(glm::cross(e1, e2))};
    if (mesh.normals.size() == mesh.positions.size()) {
      // A triangle's own normal on a small, sharp feature (the nose's tip, 4 mm triangles) follows
      // how marching cubes cut it, which is not mirror-symmetric: it leaned the nose site's normal
      // 16° to one side. The interpolated vertex normals are the surface's.
      const vec3 smooth = (1.0f - u - v) * mesh.normals[mesh.indices[3 * t]] + u * mesh.normals[mesh.indices[3 * t + 1]] +
                          v * mesh.normals[mesh.indices[3 * t + 2]];
      if (glm::dot(smooth, smooth) > 1e-12f) best->normal = glm::normalize(smooth);
    }
  }
  return best;
}

namespace {

constexpr float kOutside = 0.5f;           // metres: rays cast from outside start this far out
constexpr float kProfileStep = 0.002f;     // metres between the rays of the face's midline profile
constexpr float kProfileDepth = 0.14f;     // how far below the lower lip the profile is followed
constexpr float kChinEdge = 0.012f;        // a step back this large ends the chin (its underside)
constexpr float kChinHeight = 0.02f;       // the chin's front is looked for at most this far above that edge
constexpr float kUnderChinRay = 0.025f;    // the under-chin ray starts this far below the edge
constexpr float kNormalSpread = 0.004f;    // metres between the rays a site's normal is averaged over

struct Anchors {
  const Skeleton& skeleton;
  std::vector<vec3> position;  // bind-pose model positions
  std::vector<mat4> model;

  explicit Anchors(const Skeleton& s) : skeleton(s), position(s.size()), model(s.size()) {
    const Pose rest = rest_pose(s);
    local_to_model(s, rest, model);
    model_positions(model, position);
  }
  int find(const char* name) const { return skeleton.find(name); }
  vec3 at(int joint) const { return position[static_cast<std::size_t>(joint)]; }
};

struct SiteRay {
  std::string name;
  int joint;
  vec3 origin, direction;
  // Cast from outside, back along the ray: the outermost surface rather than the first one met
  // from inside (the face has eyeballs, teeth, tongue and the mouth's cavity within).
  bool from_outside = false;
};

void add_site(const Anchors& anchors, const Mesh& mesh, const SiteRay& ray, std::vector<BodySite>& out) {
  if (ray.joint < 0) return;
  const auto hit = ray.from_outside
                       ? cast_ray(mesh, ray.origin + kOutside * glm::normalize(ray.direction), -ray.direction)
                       : cast_ray(mesh, ray.origin, ray.direction);
  if (!hit) return;
  // The normal is averaged over the hit and four neighbouring rays (kNormalSpread around it): a
  // single triangle's normal can be a crease's, like the closed lips' seam, and point far off
  // the way the surface faces there.
  const vec3 dir = glm::normalize(ray.direction);
  const vec3 side = glm::normalize(glm::cross(dir, std::abs(dir.y) < 0.9f ? vec3(0, 1, 0) : vec3(1, 0, 0)));
  const vec3 offsets[4] = {side, -side, glm::cross(dir, side), -glm::cross(dir, side)};
  vec3 normal = hit->normal;
  for (const vec3& o : offsets) {
    const vec3 at = (ray.from_outside ? ray.origin + kOutside * dir : ray.origin) + o * kNormalSpread;
    const auto near = cast_ray(mesh, at, ray.from_outside ? -dir : dir);
    if (near && glm::distance(near->point, hit->point) < 2.5f * kNormalSpread) normal += near->normal;
  }
  const mat4 inv = glm::inverse(anchors.model[static_cast<std::size_t>(ray.joint)]);
  out.push_back(BodySite{ray.name, ray.joint, vec3(inv * vec4(hit->point, 1.0f)),
                         glm::normalize(vec3(inv * vec4(glm::normalize(normal), 0.0f)))});
}

// The chin, the surface under it and the throat, from the face's midline profile: horizontal
// rays from the front, kProfileStep apart, down from the lower lip. Where the profile has fallen
// back more than kChinEdge behind the most forward point above it the jaw's underside begins
// (sharply or over a rounded chin); the chin's front is where the profile, followed up from that
// edge, stops coming forward (at most kChinHeight up), under_chin is met by a ray straight up from
// halfway between the chin's front and the throat just below it, and the neck is the throat
// halfway from there down to the neck's base (vc7). Fixed fractions of the head's height missed
// the chin's front on heads of other proportions (a slanted ray slid under it onto the jaw line).
void add_chin_and_neck(const Anchors& a, const Mesh& mesh, int skull, float lower_lip_y, std::vector<BodySite>& out) {
  const float x = a.at(skull).x, back_z = a.at(skull).z;
  struct ProfilePoint {
    float y, z;
  };
  std::vector<ProfilePoint> profile;
  for (float y = lower_lip_y - kProfileStep; y > lower_lip_y - kProfileDepth; y -= kProfileStep) {
    const auto hit = cast_ray(mesh, vec3(x, y, back_z + kOutside), vec3(0, 0, -1));
    if (hit) profile.push_back({y, hit->point.z});
  }
  // A sharp underside steps back within one ray; a rounded one falls back over several.
  std::size_t edge = 0;
  for (std::size_t k = 1; k < profile.size() && edge == 0; ++k)
    if (profile[k].z < profile[k - 1].z - kChinEdge) edge = k;
  const bool sharp = edge != 0;
  float ahead = profile.empty() ? 0.0f : profile[0].z;
  for (std::size_t k = 1; k < profile.size() && edge == 0; ++k) {
    if (profile[k].z < ahead - kChinEdge) edge = k;
    ahead = std::max(ahead, profile[k].z);
  }
  if (edge == 0) return;  // no chin to be found on this mesh: no chin sites rather than invented ones
  // The chin's front: below the hollow under the lower lip, the most forward point above the edge;
  // on a face without that hollow, where the profile followed up from the edge stops coming
  // forward (at most kChinHeight up).
  std::size_t hollow = 0;
  while (hollow + 1 < edge && profile[hollow + 1].z <= profile[hollow].z + 0.0003f) ++hollow;
  std::size_t front = edge - 1;
  if (hollow + 1 < edge && profile[hollow].z + 0.0005f < profile[edge - 1].z) {
    for (std::size_t k = hollow; k < edge; ++k)
      if (profile[k].z > profile[front].z) front = k;
  } else {
    while (front > 0 && profile[front - 1].z >= profile[front].z && profile[front - 1].y <= profile[edge - 1].y + kChinHeight)
      --front;
  }
  const ProfilePoint chin = profile[front];
  add_site(a, mesh, {"chin", skull, vec3(x, chin.y, back_z), vec3(0, 0, 1), true}, out);
  // Straight up from in front of the throat, between the chin's front and the neck below it.
  const float ray_y = profile[edge].y - kUnderChinRay;
  // (Behind a sharp edge the underside is already far back; below a rounded chin the edge is still
  // on the chin's front, and the throat is found from the ray's height alone.)
  float throat_z = sharp ? profile[edge].z : -1.0f;
  for (const ProfilePoint& p : profile)
    if (std::abs(p.y - ray_y) < kProfileStep) throat_z = std::max(throat_z, p.z);
  if (throat_z < -0.5f) throat_z = profile[edge].z;
  const float ray_z = sharp ? std::max(0.5f * (chin.z + profile[edge].z), throat_z + 0.005f)
                            : std::max(0.5f * (chin.z + throat_z), throat_z + 0.005f);
  if (ray_z < chin.z) add_site(a, mesh, {"under_chin", skull, vec3(x, ray_y, ray_z), vec3(0, 1, 0)}, out);
  const int vc7 = a.find("vc7"), vc4 = a.find("vc4");
  if (vc7 >= 0) {
    const float neck_y = 0.5f * (profile[edge].y + a.at(vc7).y);
    add_site(a, mesh, {"neck", vc4 >= 0 ? vc4 : vc7, vec3(x, neck_y, a.at(vc7).z), vec3(0, 0, 1)}, out);
  }
}

// Heights of the nose tip and the lips on the face's midline profile: horizontal rays from the
// front, kProfileStep apart, from just below the eyes down past the mouth. The nose tip is the
// profile's most forward point; the mouth line is the dip below it that is deepest for its
// distance from where faces have their mouth (`expected`, from the head's proportions), since
// lips that stand a little apart let a ray far into the mouth while a closed mouth is a shallow
// groove no deeper than the one under the lower lip; the lips are the most forward points just
// above and below it. Fractions of the head's height alone put these wrongly on any face whose
// proportions differ from the one they were measured on; nullopt when the profile shows no dip
// (a face without lips).
struct MouthProfile {
  float nose, upper_lip, mouth, lower_lip;
};
std::optional<MouthProfile> mouth_profile(const Mesh& mesh, float x, float back_z, float top, float bottom,
                                          float expected, float scale) {
  std::vector<float> ys, zs;
  for (float y = top; y > bottom; y -= kProfileStep)
    if (const auto hit = cast_ray(mesh, vec3(x, y, back_z + kOutside), vec3(0, 0, -1))) ys.push_back(y), zs.push_back(hit->point.z);
  if (zs.size() < 8) return std::nullopt;
  const std::size_t n = zs.size();
  std::size_t tip = 0;
  for (std::size_t i = 1; i < n / 2; ++i)
    if (zs[i] > zs[tip]) tip = i;
  const std::size_t lip_rays = static_cast<std::size_t>(0.12f * scale / kProfileStep);  // a lip's height and more
  std::size_t mouth = 0;
  float best = 0.0f;
  for (std::size_t m = tip + 2; m + 1 < n; ++m) {
    if (!(zs[m] <= zs[m - 1] && zs[m] <= zs[m + 1])) continue;
    float above = zs[m], below = zs[m];
    for (std::size_t i = m; i > tip && i + lip_rays > m; --i) above = std::max(above, zs[i]);
    for (std::size_t i = m; i < n && i < m + lip_rays; ++i) below = std::max(below, zs[i]);
    const float depth = std::min(above, below) - zs[m];
    if (depth < 0.0008f) continue;
    const float score = depth / (1.0f + std::abs(ys[m] - expected) / (0.1f * scale));
    if (score > best) best = score, mouth = m;
  }
  if (mouth == 0) return std::nullopt;
  std::size_t upper = mouth, lower = mouth;
  for (std::size_t i = mouth; i > tip && i + lip_rays > mouth; --i)
    if (zs[i] > zs[upper]) upper = i;
  for (std::size_t i = mouth; i < n && i < mouth + lip_rays; ++i)
    if (zs[i] > zs[lower]) lower = i;
  return MouthProfile{ys[tip], ys[upper], ys[mouth], ys[lower]};
}

}  // namespace

std::vector<BodySite> find_body_sites(const Skeleton& skeleton, const Mesh& mesh) {
  std::vector<BodySite> sites;
  if (mesh.indices.empty()) return sites;
  const Anchors a(skeleton);
  std::vector<SiteRay> rays;
  const vec3 up(0, 1, 0), fwd(0, 0, 1), back(0, 0, -1);

  // Head and face: proportions from the eye line to the crown (e ≈ half the head height).
  const int skull = a.find("skullbase"), l_eye = a.find("l_eyeball_joint"), r_eye = a.find("r_eyeball_joint");
  const int crown = a.find("skull_tip");
  if (skull >= 0 && l_eye >= 0 && r_eye >= 0) {
    const vec3 eyes = 0.5f * (a.at(l_eye) + a.at(r_eye));
    const float e = crown >= 0 ? a.at(crown).y - eyes.y : 1.1f * glm::distance(a.at(l_eye), a.at(r_eye)) * 1.6f;
    const float half_eyes = 0.5f * glm::distance(a.at(l_eye), a.at(r_eye));
    // Ray origins sit on the head's vertical axis (over the skull base), inside the head.
    const vec3 axis(a.at(skull).x, 0.0f, a.at(skull).z);
    auto level = [&](float fraction) { return vec3(axis.x, eyes.y + fraction * e, axis.z); };
    rays.push_back({"head_top", skull, level(0.0f), up});
    rays.push_back({"forehead", skull, level(0.5f), fwd, true});
    rays.push_back({"eyebrows", skull, level(0.22f), fwd, true});
    // Nose and lips where the midline profile has them; fractions of the head's height otherwise.
    const auto profile = mouth_profile(mesh, axis.x, axis.z, eyes.y - 0.15f * e, eyes.y - 1.0f * e, eyes.y - 0.62f * e, e);
    auto at_height = [&](float y) { return vec3(axis.x, y, axis.z); };
    rays.push_back({"nose", skull, profile ? at_height(profile->nose) : level(-0.38f), fwd, true});
    rays.push_back({"upper_lip", skull, profile ? at_height(profile->upper_lip) : level(-0.62f), fwd, true});
    // The lips' site halfway between the two lips: where they meet, or on their edge when they
    // stand apart (a ray at the mouth line itself would then go into the mouth).
    rays.push_back({"lips", skull, profile ? at_height(0.5f * (profile->upper_lip + profile->lower_lip)) : level(-0.70f),
                    fwd, true});
    rays.push_back({"lower_lip", skull, profile ? at_height(profile->lower_lip) : level(-0.78f), fwd, true});
    for (int side = 0; side < 2; ++side) {
      const float x = side == 0 ? 1.0f : -1.0f;
      const std::string p = side == 0 ? "l_" : "r_";
      const int eye = side == 0 ? l_eye : r_eye;
      rays.push_back({p + "eye", skull, vec3(a.at(eye).x, eyes.y, axis.z), fwd, true});
      rays.push_back({p + "cheek", skull, level(-0.40f) + vec3(x * half_eyes, 0, 0), glm::normalize(vec3(0.3f * x, 0, 1)),
                      true});
      rays.push_back({p + "ear", skull, level(-0.12f), vec3(x, 0, 0)});
      rays.push_back({p + "temple", skull, level(0.25f), glm::normalize(vec3(x, 0, 0.6f))});
    }
  }
  // Trunk: forward rays from the spine.
  const char* trunk[][2] = {{"chest", "vt6"}, {"stomach", "vt12"}, {"belly", "vl3"}};
  for (auto& [site, joint] : trunk) {
    const int j = a.find(joint);
    if (j >= 0) rays.push_back({site, j, a.at(j), fwd});
  }
  const int vt1 = a.find("vt1");
  if (vt1 >= 0 && a.find("vt6") >= 0)
    rays.push_back({"upper_chest", vt1, 0.5f * (a.at(vt1) + a.at(a.find("vt6"))), fwd});
  // Arms and hands, per side.
  for (int side = 0; side < 2; ++side) {
    const float x = side == 0 ? 1.0f : -1.0f;
    const std::string p = side == 0 ? "l_" : "r_";
    const int shoulder = a.find((p + "shoulder").c_str()), elbow = a.find((p + "elbow").c_str());
    const int wrist = a.find((p + "wrist").c_str());
    const int index1 = a.find((p + "index1").c_str()), pinky1 = a.find((p + "pinky1").c_str());
    const int middle1 = a.find((p + "middle1").c_str());
    if (shoulder >= 0) rays.push_back({p + "shoulder_top", shoulder, a.at(shoulder), up});
    if (shoulder >= 0 && elbow >= 0)
      rays.push_back({p + "upper_arm", shoulder, 0.5f * (a.at(shoulder) + a.at(elbow)), vec3(x, 0, 0)});
    if (elbow >= 0) rays.push_back({p + "elbow", elbow, a.at(elbow), back});
    if (elbow >= 0 && wrist >= 0) {
      rays.push_back({p + "forearm", elbow, 0.5f * (a.at(elbow) + a.at(wrist)), fwd});
      rays.push_back({p + "wrist_back", wrist, a.at(wrist), vec3(x, 0, 0)});
    }
    if (wrist >= 0 && index1 >= 0 && pinky1 >= 0 && middle1 >= 0) {
      // Palm centre between the wrist and the knuckles; the palm faces the body's midline at rest.
      const vec3 centre = (a.at(wrist) + a.at(index1) + a.at(pinky1) + a.at(middle1)) * 0.25f;
      rays.push_back({p + "palm", wrist, centre, vec3(-x, 0, 0)});
      rays.push_back({p + "back_of_hand", wrist, centre, vec3(x, 0, 0)});
    }
    for (const char* finger : {"thumb", "index", "middle", "ring", "pinky"}) {
      const int tip = a.find((p + finger + "_tip").c_str());
      const int last = a.find((p + finger + "3").c_str());
      if (tip >= 0 && last >= 0) {
        // Just short of the tip, pointing along the finger: the pad of the fingertip.
        const vec3 along = glm::normalize(a.at(tip) - a.at(last));
        rays.push_back({p + finger + "_tip", last, a.at(last) + 0.5f * (a.at(tip) - a.at(last)), along});
      }
    }
  }
  for (const SiteRay& r : rays) add_site(a, mesh, r, sites);
  if (skull >= 0)
    if (const BodySite* lip = find_site(sites, "lower_lip"))
      add_chin_and_neck(a, mesh, skull, site_position(*lip, a.model).y, sites);
  return sites;
}

const BodySite* find_site(std::span<const BodySite> sites, const std::string& name) {
  for (const BodySite& s : sites)
    if (s.name == name) return &s;
  return nullptr;
}

vec3 site_position(const BodySite& site, std::span<const mat4> model) {
  return vec3(model[static_cast<std::size_t>(site.joint)] * vec4(site.local_offset, 1.0f));
}

vec3 site_normal(const BodySite& site, std::span<const mat4> model) {
  return glm::normalize(vec3(model[static_cast<std::size_t>(site.joint)] * vec4(site.local_normal, 0.0f)));
}

SurfacePoint site_surface(const BodySite& site, std::span<const mat4> model) {
  return {site_position(site, model), site_normal(site, model)};
}

std::string body_sites_json(const Skeleton& skeleton, std::span<const BodySite> sites) {
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), model);
  std::string out = "{\"sites\": {";
  char buf[256];
  for (std::size_t i = 0; i < sites.size(); ++i) {
    const vec3 p = site_position(sites[i], model), n = site_normal(sites[i], model);
    std::snprintf(buf, sizeof buf, "%s\n  \"%s\": {\"position\": [%.4f, %.4f, %.4f], \"normal\": [%.3f, %.3f, %.3f], \"joint\": ",
                  i ? "," : "", sites[i].name.c_str(), p.x, p.y, p.z, n.x, n.y, n.z);
    out += buf;
    out += "\"" + skeleton.names[static_cast<std::size_t>(sites[i].joint)] + "\"}";
  }
  out += "\n}}\n";
  return out;
}

}  // namespace gestura
