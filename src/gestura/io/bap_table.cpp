// The MPEG-4 BAP list (BAPs 1..186) with the H-Anim joint and axis each one turns.
#include <string>
#include <unordered_map>

#include "gestura/io/bap.hpp"

namespace gestura {
namespace {

constexpr int X = 0, Y = 1, Z = 2;

std::vector<BapInfo> build_table() {
  std::vector<BapInfo> t;
  auto add = [&](const std::string& joint, const std::string& motion, int axis) {
    t.push_back({joint + "_" + motion, joint, axis, false});
  };
  // Left and right side by side, as the list alternates them.
  auto pair = [&](const std::string& joint, const std::string& motion, int axis) {
    add("l_" + joint, motion, axis);
    add("r_" + joint, motion, axis);
  };
  add("sacroiliac", "tilt", X), add("sacroiliac", "torsion", Y), add("sacroiliac", "roll", Z);      // 1–3
  pair("hip", "flexion", X), pair("hip", "abduct", Z), pair("hip", "twisting", Y);                   // 4–9
  pair("knee", "flexion", X), pair("knee", "twisting", Y);                                           // 10–13
  pair("ankle", "flexion", X), pair("ankle", "twisting", Y);                                         // 14–17
  pair("subtalar", "flexion", Z), pair("midtarsal", "twisting", Z), pair("metatarsal", "flexion", X);  // 18–23
  pair("sternoclavicular", "abduct", Z), pair("sternoclavicular", "rotate", Y);                      // 24–27
  pair("acromioclavicular", "abduct", Z), pair("acromioclavicular", "rotate", Y);                    // 28–31
  pair("shoulder", "flexion", X), pair("shoulder", "abduct", Z), pair("shoulder", "twisting", Y);    // 32–37
  pair("elbow", "flexion", X), pair("elbow", "twisting", Y);                                         // 38–41
  pair("wrist", "flexion", Z), pair("wrist", "pivot", X), pair("wrist", "twisting", Y);              // 42–47
  add("skullbase", "roll", Z), add("skullbase", "torsion", Y), add("skullbase", "tilt", X);          // 48–50
  auto vertebra = [&](const std::string& name) { add(name, "roll", Z), add(name, "torsion", Y), add(name, "tilt", X); };
  for (int i = 1; i <= 7; ++i) vertebra("vc" + std::to_string(i));                                  // 51–71
  for (int i = 1; i <= 12; ++i) vertebra("vt" + std::to_string(i));                                 // 72–107
  for (int i = 1; i <= 5; ++i) vertebra("vl" + std::to_string(i));                                  // 108–122
  for (const char* finger : {"pinky", "ring", "middle", "index"}) {                                  // 123–170
    const std::string f = finger;
    pair(f + "0", "flexion", Z), pair(f + "1", "flexion", Z), pair(f + "1", "pivot", X), pair(f + "1", "twisting", Y);
    pair(f + "2", "flexion", Z), pair(f + "3", "flexion", Z);
  }
  pair("thumb1", "flexion", X), pair("thumb1", "pivot", Y), pair("thumb1", "twisting", Z);           // 171–176
  pair("thumb2", "flexion", X), pair("thumb3", "flexion", X);                                        // 177–180
  t.push_back({"HumanoidRoot_tr_vertical", "humanoid_root", Y, true});                               // 181–186
  t.push_back({"HumanoidRoot_tr_lateral", "humanoid_root", X, true});
  t.push_back({"HumanoidRoot_tr_frontal", "humanoid_root", Z, true});
  t.push_back({"HumanoidRoot_rt_body_turn", "humanoid_root", Y, false});
  t.push_back({"HumanoidRoot_rt_body_roll", "humanoid_root", Z, false});
  t.push_back({"HumanoidRoot_rt_body_tilt", "humanoid_root", X, false});
  return t;
}

}  // namespace

const std::vector<BapInfo>& bap_table() {
  static const std::vector<BapInfo> table = build_table();
  return table;
}

int find_bap(std::string_view name) {
  static const std::unordered_map<std::string, int> index = [] {
    std::unordered_map<std::string, int> m;
    for (std::size_t i = 0; i < bap_table().size(); ++i) m.emplace(bap_table()[i].name, static_cast<int>(i) + 1);
    return m;
  }();
  const auto it = index.find(std::string(name));
  return it == index.end() ? 0 : it->second;
}

}  // namespace gestura
