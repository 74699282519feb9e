#include "gestura/io/holistic_landmarks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "gestura/anim/sampler.hpp"
#include "gestura/core/error.hpp"
#include "gestura/skeleton/joint_names.hpp"

namespace gestura {

const std::array<const char*, kHolisticBodyCount> kHolisticBodyNames = {
    "NOSE",           "LEFT_EYE_INNER", "LEFT_EYE",       "LEFT_EYE_OUTER", "RIGHT_EYE_INNER", "RIGHT_EYE",
    "RIGHT_EYE_OUTER", "LEFT_EAR",      "RIGHT_EAR",      "MOUTH_LEFT",     "MOUTH_RIGHT",     "LEFT_SHOULDER",
    "RIGHT_SHOULDER", "LEFT_ELBOW",     "RIGHT_ELBOW",    "LEFT_WRIST",     "RIGHT_WRIST",     "LEFT_PINKY",
    "RIGHT_PINKY",    "LEFT_INDEX",     "RIGHT_INDEX",    "LEFT_THUMB",     "RIGHT_THUMB",     "LEFT_HIP",
    "RIGHT_HIP",      "LEFT_KNEE",      "RIGHT_KNEE",     "LEFT_ANKLE",     "RIGHT_ANKLE",     "LEFT_HEEL",
    "RIGHT_HEEL",     "LEFT_FOOT_INDEX", "RIGHT_FOOT_INDEX"};

namespace {

using Pair = std::array<std::uint16_t, 2>;

constexpr Pair kBodyLimbs[] = {
    {0, 1},   {1, 2},   {2, 3},   {3, 7},   {0, 4},   {4, 5},   {5, 6},   {6, 8},   {9, 10},  {11, 12},
    {11, 13}, {13, 15}, {15, 17}, {15, 19}, {15, 21}, {17, 19}, {12, 14}, {14, 16}, {16, 18}, {16, 20},
    {16, 22}, {18, 20}, {11, 23}, {12, 24}, {23, 24}, {23, 25}, {24, 26}, {25, 27}, {26, 28}, {27, 29},
    {28, 30}, {29, 31}, {30, 32}, {27, 31}, {28, 32}};

constexpr Pair kHandLimbs[] = {{0, 1},   {1, 2},   {2, 3},   {3, 4},   {0, 5},   {5, 6},   {6, 7},
                               {7, 8},   {5, 9},   {9, 10},  {10, 11}, {11, 12}, {9, 13},  {13, 14},
                               {14, 15}, {15, 16}, {13, 17}, {0, 17},  {17, 18}, {18, 19}, {19, 20}};

// The face-mesh contours as ordered runs of landmark indices (the face-mesh numbering is the
// layout's, so these indices are facts of the format). "R" is the signer's right (image left).
// Lips, from the right mouth corner to the left one.
constexpr std::uint16_t kLipsOuterUpper[] = {61, 185, 40, 39, 37, 0, 267, 269, 270, 409, 291};
constexpr std::uint16_t kLipsOuterLower[] = {61, 146, 91, 181, 84, 17, 314, 405, 321, 375, 291};
constexpr std::uint16_t kLipsInnerUpper[] = {78, 191, 80, 81, 82, 13, 312, 311, 310, 415, 308};
constexpr std::uint16_t kLipsInnerLower[] = {78, 95, 88, 178, 87, 14, 317, 402, 318, 324, 308};
// Eyes: corners, then the lids from the outer corner to the inner one.
struct EyeRuns {
  std::uint16_t outer, inner;
  std::uint16_t upper[7], lower[7];
};
constexpr EyeRuns kRightEye{33, 133, {246, 161, 160, 159, 158, 157, 173}, {7, 163, 144, 145, 153, 154, 155}};
constexpr EyeRuns kLeftEye{263, 362, {466, 388, 387, 386, 385, 384, 398}, {249, 390, 373, 374, 380, 381, 382}};
// Brows from the outer end to the inner end: the lower edge, then the upper edge.
struct BrowRuns {
  std::uint16_t lower[5], upper[5];
};
constexpr BrowRuns kRightBrow{{46, 53, 52, 65, 55}, {70, 63, 105, 66, 107}};
constexpr BrowRuns kLeftBrow{{276, 283, 282, 295, 285}, {300, 293, 334, 296, 336}};
// The face oval from the top of the forehead (10) down the signer's left side to the chin (152),
// and the mirror run down the right side (without 10 and 152).
constexpr std::uint16_t kOvalLeft[] = {10, 338, 297, 332, 284, 251, 389, 356, 454, 323,
                                       361, 288, 397, 365, 379, 378, 400, 377, 152};
constexpr std::uint16_t kOvalRight[] = {109, 67, 103, 54, 21, 162, 127, 234, 93, 132, 58, 172, 136, 150, 149, 176, 148};
constexpr std::uint16_t kNoseTip = 1;

std::vector<Pair> face_limbs() {
  std::vector<Pair> limbs;
  const auto run = [&](std::span<const std::uint16_t> r) {
    for (std::size_t i = 1; i < r.size(); ++i) limbs.push_back({r[i - 1], r[i]});
  };
  for (auto r : {std::span<const std::uint16_t>(kLipsOuterUpper), std::span<const std::uint16_t>(kLipsOuterLower),
                 std::span<const std::uint16_t>(kLipsInnerUpper), std::span<const std::uint16_t>(kLipsInnerLower)})
    run(r);
  for (const EyeRuns& e : {kRightEye, kLeftEye}) {
    limbs.push_back({e.outer, e.upper[0]});
    limbs.push_back({e.outer, e.lower[0]});
    run(e.upper);
    run(e.lower);
    limbs.push_back({e.upper[6], e.inner});
    limbs.push_back({e.lower[6], e.inner});
  }
  for (const BrowRuns& b : {kRightBrow, kLeftBrow}) {
    run(b.lower);
    run(b.upper);
  }
  run(kOvalLeft);
  limbs.push_back({kOvalLeft[0], kOvalRight[0]});
  run(kOvalRight);
  limbs.push_back({kOvalRight[16], kOvalLeft[18]});
  return limbs;
}

bool is_eye(std::uint8_t m) {
  return m == std::uint8_t(MaterialId::EyeWhite) || m == std::uint8_t(MaterialId::Iris) || m == std::uint8_t(MaterialId::Pupil);
}
bool is_face_surface(std::uint8_t m) {
  return m == std::uint8_t(MaterialId::Skin) || m == std::uint8_t(MaterialId::Lips) ||
         m == std::uint8_t(MaterialId::Brow) || is_eye(m);
}

// A front (orthographic, from +Z) picture of the head at bind pose: per cell the nearest surface's
// vertex (the corner of the hit triangle nearest the cell centre), material, facing (normal z) and
// whether the jaw carries it. Rows grow upwards (+Y).
class FrontView {
 public:
  FrontView(const Mesh& mesh, const std::vector<std::uint8_t>& in_head, const std::vector<std::uint8_t>& on_jaw) {
    vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
      if (in_head[v]) lo = glm::min(lo, vec2(mesh.positions[v])), hi = glm::max(hi, vec2(mesh.positions[v]));
    if (!(lo.x < hi.x) || !(lo.y < hi.y)) return;
    cell_ = std::max(hi.x - lo.x, hi.y - lo.y) / 280.0f;
    origin_ = lo;
    width_ = static_cast<int>((hi.x - lo.x) / cell_) + 1;
    height_ = static_cast<int>((hi.y - lo.y) / cell_) + 1;
    const std::size_t cells = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
    depth_.assign(cells, -std::numeric_limits<float>::max());
    vertex_.assign(cells, -1);
    facing_.assign(cells, 0.0f);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const std::uint32_t i[3] = {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]};
      if (!in_head[i[0]] || !in_head[i[1]] || !in_head[i[2]]) continue;
      const vec3 p[3] = {mesh.positions[i[0]], mesh.positions[i[1]], mesh.positions[i[2]]};
      const auto edge = [](vec2 a, vec2 b, vec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); };
      const float area = edge(vec2(p[0]), vec2(p[1]), vec2(p[2]));
      if (std::abs(area) < 1e-12f) continue;
      const vec2 tlo = glm::min(glm::min(vec2(p[0]), vec2(p[1])), vec2(p[2]));
      const vec2 thi = glm::max(glm::max(vec2(p[0]), vec2(p[1])), vec2(p[2]));
      const int x0 = std::max(0, static_cast<int>(std::floor((tlo.x - origin_.x) / cell_)));
      const int x1 = std::min(width_ - 1, static_cast<int>(std::ceil((thi.x - origin_.x) / cell_)));
      const int y0 = std::max(0, static_cast<int>(std::floor((tlo.y - origin_.y) / cell_)));
      const int y1 = std::min(height_ - 1, static_cast<int>(std::ceil((thi.y - origin_.y) / cell_)));
      for (int cy = y0; cy <= y1; ++cy)
        for (int cx = x0; cx <= x1; ++cx) {
          const vec2 c = centre(cx, cy);
          const float w0 = edge(vec2(p[1]), vec2(p[2]), c) / area, w1 = edge(vec2(p[2]), vec2(p[0]), c) / area;
          const float w2 = 1.0f - w0 - w1;
          if (w0 < -1e-4f || w1 < -1e-4f || w2 < -1e-4f) continue;
          const float z = w0 * p[0].z + w1 * p[1].z + w2 * p[2].z;
          const std::size_t at = index(cx, cy);
          if (z <= depth_[at]) continue;
          depth_[at] = z;
          const int k = w0 >= w1 && w0 >= w2 ? 0 : (w1 >= w2 ? 1 : 2);
          vertex_[at] = static_cast<std::int32_t>(i[k]);
          const vec3 n = w0 * mesh.normals[i[0]] + w1 * mesh.normals[i[1]] + w2 * mesh.normals[i[2]];
          facing_[at] = glm::length(n) > 0.0f ? glm::normalize(n).z : 0.0f;
        }
    }
    material_.assign(cells, 255);
    jaw_.assign(cells, 0);
    for (std::size_t at = 0; at < cells; ++at)
      if (vertex_[at] >= 0) {
        material_[at] = mesh.materials[static_cast<std::size_t>(vertex_[at])];
        jaw_[at] = on_jaw[static_cast<std::size_t>(vertex_[at])];
      }
  }

  bool empty() const { return width_ == 0; }
  int width() const { return width_; }
  int height() const { return height_; }
  bool inside(int cx, int cy) const { return cx >= 0 && cy >= 0 && cx < width_ && cy < height_; }
  std::int32_t vertex(int cx, int cy) const { return inside(cx, cy) ? vertex_[index(cx, cy)] : -1; }
  std::uint8_t material(int cx, int cy) const { return inside(cx, cy) ? material_[index(cx, cy)] : 255; }
  float facing(int cx, int cy) const { return inside(cx, cy) ? facing_[index(cx, cy)] : 0.0f; }
  float depth(int cx, int cy) const { return inside(cx, cy) ? depth_[index(cx, cy)] : -1e30f; }
  bool jaw(int cx, int cy) const { return inside(cx, cy) && jaw_[index(cx, cy)]; }
  int column_of(float x) const { return static_cast<int>(std::floor((x - origin_.x) / cell_)); }
  int row_of(float y) const { return static_cast<int>(std::floor((y - origin_.y) / cell_)); }

 private:
  std::size_t index(int cx, int cy) const { return static_cast<std::size_t>(cy) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(cx); }
  vec2 centre(int cx, int cy) const { return origin_ + cell_ * vec2(static_cast<float>(cx) + 0.5f, static_cast<float>(cy) + 0.5f); }
  vec2 origin_{0.0f};
  float cell_ = 1.0f;
  int width_ = 0, height_ = 0;
  std::vector<float> depth_, facing_;
  std::vector<std::int32_t> vertex_;
  std::vector<std::uint8_t> material_, jaw_;
};

// Cells of one feature (a predicate over materials) within a column range, per column.
struct Region {
  int x0 = 0, x1 = -1;                 // columns that hold any cell
  std::vector<int> top, bottom;        // per column x0..x1: highest and lowest row, -1 when none
  bool empty() const { return x1 < x0; }
  int top_at(int cx) const { return cx < x0 || cx > x1 ? -1 : top[static_cast<std::size_t>(cx - x0)]; }
  int bottom_at(int cx) const { return cx < x0 || cx > x1 ? -1 : bottom[static_cast<std::size_t>(cx - x0)]; }
  // The column at fraction t from `from` to `to` that has cells (searching inwards).
  int column(float t, int from, int to) const {
    int cx = static_cast<int>(std::lround(static_cast<float>(from) + t * static_cast<float>(to - from)));
    const int step = to >= from ? 1 : -1;
    while (top_at(cx) < 0 && cx != to) cx += step;
    return cx;
  }
};

template <class Predicate>
Region region(const FrontView& view, int col_lo, int col_hi, int row_lo, int row_hi, Predicate keep) {
  Region r;
  col_lo = std::max(col_lo, 0), col_hi = std::min(col_hi, view.width() - 1);
  row_lo = std::max(row_lo, 0), row_hi = std::min(row_hi, view.height() - 1);
  for (int cx = col_lo; cx <= col_hi; ++cx)
    for (int cy = row_lo; cy <= row_hi; ++cy)
      if (keep(cx, cy)) {
        if (r.empty()) r.x0 = cx;
        r.x1 = cx;
        break;
      }
  if (r.empty()) return r;
  r.top.assign(static_cast<std::size_t>(r.x1 - r.x0 + 1), -1);
  r.bottom = r.top;
  for (int cx = r.x0; cx <= r.x1; ++cx)
    for (int cy = row_lo; cy <= row_hi; ++cy)
      if (keep(cx, cy)) {
        auto& b = r.bottom[static_cast<std::size_t>(cx - r.x0)];
        if (b < 0) b = cy;
        r.top[static_cast<std::size_t>(cx - r.x0)] = cy;
      }
  return r;
}

std::vector<std::uint8_t> head_vertices(const Skeleton& skeleton, const Mesh& mesh, const char* root, float share) {
  const int head = skeleton.find(root);
  std::vector<std::uint8_t> below(skeleton.size(), 0), out(mesh.positions.size(), 0);
  if (head < 0) return out;
  for (std::size_t j = 0; j < skeleton.size(); ++j)
    for (int p = static_cast<int>(j); p >= 0; p = skeleton.parents[static_cast<std::size_t>(p)])
      if (p == head) { below[j] = 1; break; }
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    float w = 0.0f;
    for (int k = 0; k < 4; ++k)
      if (mesh.joints[v][k] < below.size() && below[mesh.joints[v][k]]) w += mesh.weights[v][k];
    out[v] = w >= share ? 1 : 0;
  }
  return out;
}

}  // namespace

std::span<const std::array<std::uint16_t, 2>> holistic_body_limbs() { return kBodyLimbs; }
std::span<const std::array<std::uint16_t, 2>> holistic_hand_limbs() { return kHandLimbs; }
std::span<const std::array<std::uint16_t, 2>> holistic_face_limbs() {
  static const std::vector<Pair> limbs = face_limbs();
  return limbs;
}

int FaceLandmarkBinding::bound() const {
  return static_cast<int>(std::count_if(vertex.begin(), vertex.end(), [](std::int32_t v) { return v >= 0; }));
}

FaceLandmarkBinding bind_face_landmarks(const Skeleton& skeleton, const Mesh& mesh) {
  FaceLandmarkBinding out;
  out.vertex.fill(-1);
  const int skull = skeleton.find("skullbase");
  if (skull < 0 || mesh.positions.empty() || mesh.materials.size() != mesh.positions.size() ||
      mesh.joints.size() != mesh.positions.size() || mesh.weights.size() != mesh.positions.size())
    return out;
  const std::vector<std::uint8_t> in_head = head_vertices(skeleton, mesh, "skullbase", 0.5f);
  const std::vector<std::uint8_t> on_jaw = head_vertices(skeleton, mesh, "temporomandibular", 0.5f);
  const FrontView view(mesh, in_head, on_jaw);
  if (view.empty()) return out;
  std::vector<mat4> rest(skeleton.size());
  local_to_model(skeleton, rest_pose(skeleton), rest);
  const int mid = view.column_of(rest[static_cast<std::size_t>(skull)][3].x);
  const auto set = [&](std::uint16_t landmark, int cx, int cy) {
    const std::int32_t v = view.vertex(cx, cy);
    if (v >= 0) out.vertex[landmark] = v;
  };
  const auto has = [&](MaterialId m) {
    return [&view, m](int cx, int cy) { return view.material(cx, cy) == std::uint8_t(m); };
  };
  const int W = view.width(), H = view.height();

  // Eyes: the lids are the skin just above and below the visible eye, the corners just beside it.
  int eye_row = -1;
  for (int side = 0; side < 2; ++side) {  // 0: the signer's right (x below the midline)
    const Region eye = region(view, side == 0 ? 0 : mid + 1, side == 0 ? mid - 1 : W - 1, 0, H - 1,
                              [&](int cx, int cy) { return is_eye(view.material(cx, cy)); });
    if (eye.empty()) continue;
    const EyeRuns& runs = side == 0 ? kRightEye : kLeftEye;
    const int outer = side == 0 ? eye.x0 : eye.x1, inner = side == 0 ? eye.x1 : eye.x0;
    const int step_out = side == 0 ? -1 : 1;
    const auto middle_row = [&](int cx) { return (eye.top_at(cx) + eye.bottom_at(cx)) / 2; };
    set(runs.outer, outer + step_out, middle_row(outer));
    set(runs.inner, inner - step_out, middle_row(inner));
    for (int k = 0; k < 7; ++k) {
      const int cx = eye.column(static_cast<float>(k + 1) / 8.0f, outer, inner);
      set(runs.upper[k], cx, eye.top_at(cx) + 1);
      set(runs.lower[k], cx, eye.bottom_at(cx) - 1);
    }
    const int centre = eye.column(0.5f, outer, inner);
    eye_row = eye_row < 0 ? middle_row(centre) : (eye_row + middle_row(centre)) / 2;
  }

  // Brows, above the eyes.
  for (int side = 0; side < 2; ++side) {
    const Region brow = region(view, side == 0 ? 0 : mid + 1, side == 0 ? mid - 1 : W - 1, std::max(0, eye_row), H - 1,
                               has(MaterialId::Brow));
    if (brow.empty()) continue;
    const BrowRuns& runs = side == 0 ? kRightBrow : kLeftBrow;
    const int outer = side == 0 ? brow.x0 : brow.x1, inner = side == 0 ? brow.x1 : brow.x0;
    for (int k = 0; k < 5; ++k) {
      const int cx = brow.column(0.05f + 0.225f * static_cast<float>(k), outer, inner);
      set(runs.lower[k], cx, brow.bottom_at(cx));
      set(runs.upper[k], cx, brow.top_at(cx));
    }
  }

  // Lips, below the eyes: the outer contour is the lip region's edge; the inner contour is where
  // the upper lip (the skull carries it) meets the lower lip (the jaw carries it).
  const Region lips = region(view, 0, W - 1, 0, eye_row < 0 ? H - 1 : eye_row - 1, has(MaterialId::Lips));
  int mouth_row = -1;
  if (!lips.empty()) {
    const int right = lips.x0, left = lips.x1;
    const auto middle_row = [&](int cx) { return (lips.top_at(cx) + lips.bottom_at(cx)) / 2; };
    const int corner_row = (middle_row(right) + middle_row(left)) / 2;
    const auto lower_lip = [&](int cx, int cy) {
      return on_jaw.empty() || std::none_of(on_jaw.begin(), on_jaw.end(), [](std::uint8_t j) { return j != 0; })
                 ? cy < corner_row
                 : view.jaw(cx, cy);
    };
    for (int k = 0; k < 11; ++k) {
      const int cx = lips.column(static_cast<float>(k) / 10.0f, right, left);
      const bool corner = k == 0 || k == 10;
      set(kLipsOuterUpper[k], cx, corner ? middle_row(cx) : lips.top_at(cx));
      set(kLipsOuterLower[k], cx, corner ? middle_row(cx) : lips.bottom_at(cx));
      const int ix = lips.column(0.04f + 0.092f * static_cast<float>(k), right, left);
      int upper_inner = -1, lower_inner = -1;  // lowest upper-lip row, highest lower-lip row
      for (int cy = lips.bottom_at(ix); cy >= 0 && cy <= lips.top_at(ix); ++cy) {
        const std::uint8_t m = view.material(ix, cy);
        if (m != std::uint8_t(MaterialId::Lips)) continue;
        if (lower_lip(ix, cy)) lower_inner = cy;
        else if (upper_inner < 0) upper_inner = cy;
      }
      if (upper_inner < 0) upper_inner = middle_row(ix);
      if (lower_inner < 0) lower_inner = middle_row(ix);
      if (corner) upper_inner = lower_inner = (upper_inner + lower_inner) / 2;
      set(kLipsInnerUpper[k], ix, upper_inner);
      set(kLipsInnerLower[k], ix, lower_inner);
    }
    mouth_row = corner_row;
  }

  // The nose tip: the most forward point on the midline between the eyes and the mouth.
  if (eye_row >= 0 && mouth_row >= 0) {
    int best_x = -1, best_y = -1;
    float best = -1e30f;
    const int half = std::max(2, (lips.x1 - lips.x0) / 4);
    for (int cy = mouth_row + 1; cy < eye_row; ++cy)
      for (int cx = mid - half; cx <= mid + half; ++cx)
        if (view.vertex(cx, cy) >= 0 && view.depth(cx, cy) > best) best = view.depth(cx, cy), best_x = cx, best_y = cy;
    if (best_x >= 0) set(kNoseTip, best_x, best_y);
  }

  // The face oval: walk out from between the eyes and the mouth; the oval is the last face cell
  // before a wide gap of non-face (hair, the side of the head turning away from the camera, no
  // head surface at all). Short gaps — the underside of the nose, a nostril — are crossed.
  if (eye_row >= 0 && mouth_row >= 0) {
    const vec2 origin(static_cast<float>(mid) + 0.5f, 0.5f * static_cast<float>(eye_row + mouth_row) + 0.5f);
    const float gap = 0.035f * static_cast<float>(W);
    const auto walk = [&](float angle) {
      const vec2 d(std::cos(angle), std::sin(angle));
      int last_x = -1, last_y = -1;
      float last_r = 0.0f;
      for (float r = 0.0f; r < static_cast<float>(W + H); r += 0.5f) {
        const vec2 p = origin + r * d;
        const int cx = static_cast<int>(std::floor(p.x)), cy = static_cast<int>(std::floor(p.y));
        if (view.inside(cx, cy) && is_face_surface(view.material(cx, cy)) && view.facing(cx, cy) >= 0.3f) {
          last_x = cx, last_y = cy, last_r = r;
        } else if (r - last_r > gap) {
          break;
        }
      }
      return std::pair{last_x, last_y};
    };
    for (int k = 0; k < 19; ++k) {
      const float degrees = k <= 8 ? 90.0f - 11.25f * static_cast<float>(k) : -9.0f * static_cast<float>(k - 8);
      const auto [lx, ly] = walk(deg(degrees));
      if (lx >= 0) set(kOvalLeft[k], lx, ly);
      if (k == 0 || k == 18) continue;
      const auto [rx, ry] = walk(deg(180.0f - degrees));
      if (rx >= 0) set(kOvalRight[k - 1], rx, ry);
    }
  }
  return out;
}

namespace {

// A point of the body or a hand: a joint, the midpoint of two, or an offset (model space at rest)
// that turns with the first joint.
struct JointPoint {
  const char* a = nullptr;
  const char* b = nullptr;
  vec3 offset{0.0f};
  int face = -1;  // a face-mesh landmark that places this point better when it is bound
};

const std::array<JointPoint, kHolisticBodyCount>& body_points() {
  static const std::array<JointPoint, kHolisticBodyCount> points = {{
      {"skullbase", nullptr, {0.0f, 0.02f, 0.105f}, 1},              // nose
      {"l_eyeball_joint", nullptr, {-0.012f, 0.0f, 0.012f}, 362},   // left eye inner
      {"l_eyeball_joint", nullptr, {0.0f, 0.0f, 0.012f}},           // left eye
      {"l_eyeball_joint", nullptr, {0.014f, 0.0f, 0.008f}, 263},    // left eye outer
      {"r_eyeball_joint", nullptr, {0.012f, 0.0f, 0.012f}, 133},    // right eye inner
      {"r_eyeball_joint", nullptr, {0.0f, 0.0f, 0.012f}},           // right eye
      {"r_eyeball_joint", nullptr, {-0.014f, 0.0f, 0.008f}, 33},    // right eye outer
      {"skullbase", nullptr, {0.075f, 0.04f, 0.0f}},                // left ear
      {"skullbase", nullptr, {-0.075f, 0.04f, 0.0f}},               // right ear
      {"skullbase", nullptr, {0.025f, -0.035f, 0.09f}, 291},        // mouth left
      {"skullbase", nullptr, {-0.025f, -0.035f, 0.09f}, 61},        // mouth right
      {"l_shoulder"}, {"r_shoulder"}, {"l_elbow"}, {"r_elbow"}, {"l_wrist"}, {"r_wrist"},
      {"l_pinky1"}, {"r_pinky1"}, {"l_index1"}, {"r_index1"}, {"l_thumb2"}, {"r_thumb2"},
      {"l_hip"}, {"r_hip"}, {"l_knee"}, {"r_knee"}, {"l_ankle"}, {"r_ankle"},
      {"l_ankle", nullptr, {0.0f, -0.065f, -0.05f}}, {"r_ankle", nullptr, {0.0f, -0.065f, -0.05f}},
      {"l_toe_tip"}, {"r_toe_tip"},
  }};
  return points;
}

std::array<std::string, kHolisticHandCount> hand_joint_names(const char* side) {
  std::array<std::string, kHolisticHandCount> names;
  names[0] = std::string(side) + "wrist";
  std::size_t at = 1;
  for (const char* finger : {"thumb", "index", "middle", "ring", "pinky"})
    for (const char* part : {"1", "2", "3", "_tip"}) names[at++] = std::string(side) + finger + part;
  return names;
}

}  // namespace

HolisticTrack holistic_track(const Skeleton& skeleton, const Mesh* mesh, const Clip& clip, float fps) {
  if (!(fps > 0.0f) || fps > 1000.0f) throw Error("holistic landmarks: fps must be in (0, 1000], got " + std::to_string(fps));
  const float duration = std::max(clip.duration, 0.0f);
  const double n = std::floor(double(duration) * fps + 0.5) + 1.0;
  if (n > 1e7) throw Error("holistic landmarks: more than 10,000,000 frames");
  HolisticTrack out;
  out.frames = static_cast<int>(n);

  const std::vector<std::string> hanim = guess_hanim_names(skeleton);
  std::map<std::string, int, std::less<>> by_name;
  for (std::size_t j = 0; j < hanim.size(); ++j)
    if (!hanim[j].empty()) by_name.emplace(hanim[j], static_cast<int>(j));
  const auto find = [&](const char* name) {
    if (!name) return -1;
    const auto it = by_name.find(std::string_view(name));
    return it == by_name.end() ? -1 : it->second;
  };

  // Face: bound vertices, the morph deltas that move them and the clip channels that drive those.
  FaceLandmarkBinding face;
  face.vertex.fill(-1);
  const bool mesh_fits = mesh && !mesh->positions.empty() && mesh->joints.size() == mesh->positions.size() &&
                         mesh->weights.size() == mesh->positions.size() &&
                         std::all_of(mesh->joints.begin(), mesh->joints.end(), [&](const JointIndices& j) {
                           return std::max(std::max(j.x, j.y), std::max(j.z, j.w)) < skeleton.size();
                         });
  if (mesh_fits) face = bind_face_landmarks(skeleton, *mesh);
  struct Delta {
    int morph;
    vec3 delta;
  };
  std::vector<std::vector<Delta>> deltas(kHolisticFaceCount);
  std::vector<int> channel_morph;
  if (face.bound() > 0) {
    std::map<std::uint32_t, std::vector<int>> landmarks_of_vertex;
    for (int i = 0; i < kHolisticFaceCount; ++i)
      if (face.vertex[static_cast<std::size_t>(i)] >= 0)
        landmarks_of_vertex[static_cast<std::uint32_t>(face.vertex[static_cast<std::size_t>(i)])].push_back(i);
    for (std::size_t m = 0; m < mesh->morphs.size(); ++m) {
      const MorphTarget& t = mesh->morphs[m];
      for (std::size_t k = 0; k < t.vertices.size() && k < t.position_deltas.size(); ++k)
        if (const auto it = landmarks_of_vertex.find(t.vertices[k]); it != landmarks_of_vertex.end())
          for (int i : it->second) deltas[static_cast<std::size_t>(i)].push_back({static_cast<int>(m), t.position_deltas[k]});
    }
    for (const std::string& name : clip.channel_names) channel_morph.push_back(mesh->find_morph(name));
  }

  const std::size_t frames = static_cast<std::size_t>(out.frames);
  out.body.assign(frames * kHolisticBodyCount, vec3(0.0f));
  out.face.assign(frames * kHolisticFaceCount, vec3(0.0f));
  out.left_hand.assign(frames * kHolisticHandCount, vec3(0.0f));
  out.right_hand.assign(frames * kHolisticHandCount, vec3(0.0f));
  out.body_confidence.assign(out.body.size(), 0.0f);
  out.face_confidence.assign(out.face.size(), 0.0f);
  out.left_confidence.assign(out.left_hand.size(), 0.0f);
  out.right_confidence.assign(out.right_hand.size(), 0.0f);

  const Pose rest = rest_pose(skeleton);
  std::vector<mat4> rest_model(skeleton.size()), model(skeleton.size()), skin(skeleton.size());
  local_to_model(skeleton, rest, rest_model);
  std::vector<mat4> inverse_bind(skeleton.size());
  for (std::size_t j = 0; j < skeleton.size(); ++j) inverse_bind[j] = glm::inverse(rest_model[j]);
  Sampler sampler(clip);
  Pose pose;
  std::vector<float> channels(clip.channels.size(), 0.0f);
  const auto hands = std::array{hand_joint_names("l_"), hand_joint_names("r_")};

  for (std::size_t f = 0; f < frames; ++f) {
    sampler.sample(std::min(static_cast<float>(f) / fps, duration), WrapMode::Clamp, rest, pose, channels);
    local_to_model(skeleton, pose, model);
    for (std::size_t j = 0; j < skeleton.size(); ++j) skin[j] = model[j] * inverse_bind[j];
    const auto at = [&](int j) { return vec3(model[static_cast<std::size_t>(j)][3]); };

    for (int i = 0; i < kHolisticFaceCount; ++i) {
      const std::int32_t v = face.vertex[static_cast<std::size_t>(i)];
      if (v < 0) continue;
      vec3 p = mesh->positions[static_cast<std::size_t>(v)];
      for (const Delta& d : deltas[static_cast<std::size_t>(i)]) {
        float w = 0.0f;
        for (std::size_t c = 0; c < channel_morph.size(); ++c)
          if (channel_morph[c] == d.morph) w = channels[c];
        p += w * d.delta;
      }
      const JointIndices& j = mesh->joints[static_cast<std::size_t>(v)];
      const vec4& w = mesh->weights[static_cast<std::size_t>(v)];
      vec3 q(0.0f);
      for (int k = 0; k < 4; ++k) q += w[k] * vec3(skin[j[k]] * vec4(p, 1.0f));
      out.face[f * kHolisticFaceCount + static_cast<std::size_t>(i)] = q;
      out.face_confidence[f * kHolisticFaceCount + static_cast<std::size_t>(i)] = 1.0f;
    }

    const auto& points = body_points();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const JointPoint& d = points[i];
      const std::size_t o = f * kHolisticBodyCount + i;
      if (d.face >= 0 && face.vertex[static_cast<std::size_t>(d.face)] >= 0) {
        out.body[o] = out.face[f * kHolisticFaceCount + static_cast<std::size_t>(d.face)];
        out.body_confidence[o] = 1.0f;
        continue;
      }
      const int a = find(d.a), b = find(d.b);
      if (a < 0 || (d.b && b < 0)) continue;
      vec3 p = b >= 0 ? 0.5f * (at(a) + at(b)) : at(a);
      if (d.offset != vec3(0.0f))
        p += mat3(model[static_cast<std::size_t>(a)]) * glm::inverse(mat3(rest_model[static_cast<std::size_t>(a)])) * d.offset;
      out.body[o] = p;
      out.body_confidence[o] = 1.0f;
    }
    // Eye centres from the eyelid points when the face is bound: the middle of the eye opening.
    for (const auto& [centre, e] : {std::pair{2, kLeftEye}, std::pair{5, kRightEye}}) {
      if (face.vertex[e.outer] < 0 || face.vertex[e.inner] < 0) continue;
      const vec3 p = 0.5f * (out.face[f * kHolisticFaceCount + e.outer] + out.face[f * kHolisticFaceCount + e.inner]);
      out.body[f * kHolisticBodyCount + static_cast<std::size_t>(centre)] = p;
      out.body_confidence[f * kHolisticBodyCount + static_cast<std::size_t>(centre)] = 1.0f;
    }

    for (int side = 0; side < 2; ++side) {
      std::vector<vec3>& dst = side == 0 ? out.left_hand : out.right_hand;
      std::vector<float>& conf = side == 0 ? out.left_confidence : out.right_confidence;
      for (int i = 0; i < kHolisticHandCount; ++i) {
        const int j = find(hands[static_cast<std::size_t>(side)][static_cast<std::size_t>(i)].c_str());
        if (j < 0) continue;
        dst[f * kHolisticHandCount + static_cast<std::size_t>(i)] = at(j);
        conf[f * kHolisticHandCount + static_cast<std::size_t>(i)] = 1.0f;
      }
    }
  }
  return out;
}

}  // namespace gestura
