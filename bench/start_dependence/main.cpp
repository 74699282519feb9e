// gestura-start-dependence: does where a sign's hands land depend on where they came from?
// Every sign of a lexicon (.jsonl, `hamnosys` or `names`) is performed four times, as the motion
// cache performs it (its plan put 0.4 s after the hands' earlier posture, IK 40 times a second),
// after the hands were relaxed in front, raised to the face, out in front and low. For each start
// the largest palm-centre distance from the plan over the sign is measured; a sign is start-
// dependent when those four differ by more than --threshold (1 cm). Prints each such sign and the
// count. Not a test (1,524 ASL signs take about two minutes on two cores): `make start-dependence`.
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "gestura/body/avatar.hpp"
#include "gestura/core/parallel_for.hpp"
#include "gestura/sign/hamnosys_parser.hpp"
#include "gestura/sign/hand_geometry.hpp"
#include "gestura/sign/sign_performer.hpp"
#include "gestura/sign/sign_planner.hpp"
#include "gestura/sign/signing_rig.hpp"
#include "gestura/sign/two_hand_timeline.hpp"

using namespace gestura;

namespace {

constexpr float kLead = 0.4f, kRate = 40.0f;

// The largest distance of either palm from its planned place, every 1/40 s of the sign, when the
// sign is performed after the hands were at `before`; and the highest the elbows rose above their
// shoulders meanwhile (metres; negative: below).
struct Miss {
  float palm = 0.0f;
  float elbow_over_shoulder = -1.0f;
};

Miss palm_miss_after(const SigningRig& rig, const SignPlan& sign, const ByHand<HandState>& before) {
  TwoHandTimeline timeline(before);
  for (Hand hand : kBothHands)
    if (!sign.hand(hand).segments.empty()) timeline.move_to(hand, sign.hand(hand).segments.front().from, kLead);
  for (Hand hand : kBothHands) timeline.append_shifted(hand, sign.hand(hand), kLead);
  const SignPlan performed = timeline.finish(kLead + sign.sign_start, kLead + sign.sign_end);
  const Clip clip = perform_plan(performed, rig, PerformOptions{kRate});
  Pose pose = rig.neutral;
  std::vector<mat4> model(rig.skeleton().size());
  Miss miss;
  const std::size_t frames = clip.rotations[joint_slot(rig.hand(Hand::Right).wrist)].values.size();
  for (auto f = static_cast<std::size_t>(kLead * kRate); f < frames; ++f) {
    const float t = static_cast<float>(f) / kRate;
    if (t > performed.sign_end) break;
    for (std::size_t j = 0; j < clip.rotations.size(); ++j)
      if (!clip.rotations[j].values.empty()) pose.rotations[j] = clip.rotations[j].values[f];
    local_to_model(rig.skeleton(), pose, model);
    for (Hand hand : kBothHands) {
      if (sign.hand(hand).segments.empty()) continue;
      const HandState planned = sample_hand(sign.hand(hand), t - kLead);
      if (!planned.active) continue;
      const HandRig& h = rig.hand(hand);
      miss.palm = std::max(miss.palm, glm::distance(vec3(model[joint_slot(h.wrist)] * vec4(h.palm_centre_local, 1.0f)),
                                                    planned.position));
      miss.elbow_over_shoulder =
          std::max(miss.elbow_over_shoulder, joint_position(model, h.elbow).y - joint_position(model, h.shoulder).y);
    }
  }
  return miss;
}

}  // namespace

int main(int argc, char** argv) {
  std::string path = "data/lexicon/ase.jsonl";
  float threshold = 0.01f;
  int limit = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--threshold" && i + 1 < argc) threshold = std::strtof(argv[++i], nullptr) / 100.0f;
    else if (a == "--limit" && i + 1 < argc) limit = std::atoi(argv[++i]);
    else if (a == "-h" || a == "--help") {
      std::puts("usage: gestura-start-dependence [LEXICON.jsonl] [--threshold CM] [--limit N]");
      return 0;
    } else path = a;
  }
  std::ifstream file(path);
  if (!file) {
    std::fprintf(stderr, "%s: cannot open\n", path.c_str());
    return 2;
  }
  struct Sign {
    std::string gloss;
    SignPlan plan;
  };
  const Avatar avatar = build_avatar();
  const SigningRig rig = make_signing_rig(avatar);
  std::vector<Sign> signs;
  std::string line;
  while (std::getline(file, line) && (limit == 0 || static_cast<int>(signs.size()) < limit)) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object()) continue;
    try {
      sign::HamSign parsed;
      if (j.contains("hamnosys") && j["hamnosys"].is_string() && !j["hamnosys"].get<std::string>().empty())
        parsed = sign::parse_hamnosys_unicode(j["hamnosys"].get<std::string>());
      else if (j.contains("names") && j["names"].is_string())
        parsed = sign::parse_hamnosys_names(j["names"].get<std::string>());
      else
        continue;
      signs.push_back({j.value("gloss", std::string("?")), plan_citation(parsed, rig, ScheduleOptions{1.0f, 0.0f, 0.0f})});
    } catch (const std::exception&) {
      continue;  // `gestura check` reports what does not parse or plan
    }
  }
  // The starts: relaxed in front, raised to the face, out in front, low (as in tests/sign/hand_solver_test.cpp).
  const ByHand<HandState> relaxed{relaxed_hand_state(rig, Hand::Right), relaxed_hand_state(rig, Hand::Left)};
  std::vector<ByHand<HandState>> befores{relaxed};
  for (const vec3 d : {vec3(0.15f, 0.35f, 0.05f), vec3(0.15f, 0.1f, 0.15f), vec3(0.15f, -0.05f, 0.02f)}) {
    ByHand<HandState> b = relaxed;
    b[Hand::Right].position += vec3(-d.x, d.y, d.z);
    b[Hand::Left].position += d;
    befores.push_back(b);
  }
  std::vector<std::array<Miss, 4>> misses(signs.size());
  parallel_for(signs.size(), [&](std::size_t i) {
    for (std::size_t k = 0; k < 4; ++k) misses[i][k] = palm_miss_after(rig, signs[i].plan, befores[k]);
  });
  int dependent = 0, raised = 0;
  double relaxed_sum = 0.0;
  for (std::size_t i = 0; i < signs.size(); ++i) {
    float lo = 1e9f, hi = 0.0f, elbow = -1.0f;
    for (const Miss& m : misses[i]) lo = std::min(lo, m.palm), hi = std::max(hi, m.palm), elbow = std::max(elbow, m.elbow_over_shoulder);
    relaxed_sum += misses[i][0].palm;
    if (elbow > 0.10f) ++raised;
    if (hi - lo <= threshold) continue;
    ++dependent;
    std::printf("%-24s palm miss by start (relaxed, face, front, low): %.1f %.1f %.1f %.1f cm; elbow up to %+.0f cm over "
                "the shoulder\n", signs[i].gloss.c_str(), 100.0f * misses[i][0].palm, 100.0f * misses[i][1].palm,
                100.0f * misses[i][2].palm, 100.0f * misses[i][3].palm, 100.0f * elbow);
  }
  std::printf("%zu signs; %d land more than %.1f cm differently depending on the start; mean palm miss from the relaxed "
              "start %.2f cm; %d raise an elbow more than 10 cm over its shoulder\n", signs.size(), dependent,
              100.0f * threshold, signs.empty() ? 0.0 : 100.0 * relaxed_sum / static_cast<double>(signs.size()), raised);
  return 0;
}
