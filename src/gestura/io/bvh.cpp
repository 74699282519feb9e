// The BVH channel layout: names, rotation order implied by a channel list, per-file counts.
#include "gestura/io/bvh.hpp"

#include <algorithm>

namespace gestura {

std::string_view to_string(BvhChannel channel) {
  static constexpr std::string_view names[] = {"Xposition", "Yposition", "Zposition",
                                               "Xrotation", "Yrotation", "Zrotation"};
  return names[static_cast<int>(channel)];
}

bool BvhChannels::has_rotation() const {
  return std::any_of(order.begin(), order.begin() + count, [](BvhChannel c) { return !is_position(c); });
}

bool BvhChannels::has_position() const {
  return std::any_of(order.begin(), order.begin() + count, [](BvhChannel c) { return is_position(c); });
}

RotationOrder BvhChannels::rotation_order() const {
  std::array<int, 3> axes{};
  int n = 0;
  bool used[3] = {false, false, false};
  for (int i = 0; i < count; ++i) {
    const BvhChannel c = order[static_cast<std::size_t>(i)];
    if (is_position(c) || used[axis_of(c)]) continue;
    used[axis_of(c)] = true;
    axes[static_cast<std::size_t>(n++)] = axis_of(c);
  }
  for (int a = 0; a < 3; ++a)
    if (!used[a]) axes[static_cast<std::size_t>(n++)] = a;
  for (RotationOrder o : kAllRotationOrders)
    if (axes_of(o) == axes) return o;
  return RotationOrder::XYZ;  // unreachable: every permutation of three axes is one of the six orders
}

int BvhFile::channel_count() const {
  int total = 0;
  for (const BvhChannels& c : channels) total += c.count;
  return total;
}

int BvhFile::root() const {
  for (std::size_t j = 0; j < skeleton.parents.size(); ++j)
    if (skeleton.parents[j] < 0) return static_cast<int>(j);
  return -1;
}

}  // namespace gestura
