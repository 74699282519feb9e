#pragma once
// Euler angles with a per-joint rotation order (ukrainian-sign-language-3d-model.txt eq. 1–2).
//
// Convention: the order names the rotations from outermost to innermost, acting on column vectors.
// RotationOrder::ZXY with angles (x, y, z) means R = Rz(z) · Rx(x) · Ry(y) — the same reading as a BVH
// channel list "Zrotation Xrotation Yrotation". Equivalently: intrinsic rotations applied in the
// listed order. Angles are always given per axis (x, y, z), whatever the order.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "gestura/core/math.hpp"

namespace gestura {

enum class RotationOrder : std::uint8_t { XYZ, XZY, YXZ, YZX, ZXY, ZYX };

inline constexpr std::array<RotationOrder, 6> kAllRotationOrders{
    RotationOrder::XYZ, RotationOrder::XZY, RotationOrder::YXZ,
    RotationOrder::YZX, RotationOrder::ZXY, RotationOrder::ZYX};

// Axis indices (0 = x, 1 = y, 2 = z), outermost first.
std::array<int, 3> axes_of(RotationOrder order);
std::string_view to_string(RotationOrder order);
std::optional<RotationOrder> parse_rotation_order(std::string_view text);  // "XYZ", "zxy", …

// angles = (about x, about y, about z) in radians.
quat euler_to_quat(const vec3& angles, RotationOrder order);

// Inverse of euler_to_quat. The middle angle lies in [-pi/2, pi/2]; at gimbal lock the innermost
// angle is set to 0. `near` (optional) picks, among the equivalent solutions and 2π shifts, the one
// closest to a previous frame's angles, so that converting a sequence of keys never flips.
vec3 quat_to_euler(const quat& q, RotationOrder order);
vec3 quat_to_euler_near(const quat& q, RotationOrder order, const vec3& near);

}  // namespace gestura
