#pragma once
// reach: an arm of the default avatar reaches for a point (alias-movement-through-environments.txt
// §6.2). One IK solve from the signer's ready posture finds the reaching posture; the motion then
// moves every joint from the ready posture to it on a minimum-jerk profile (Flash & Hogan:
// s = 10τ³ − 15τ⁴ + 6τ⁵, zero velocity and acceleration at both ends), Euler angles interpolated
// per joint, so every frame stays inside the joints' limit boxes.
#include <optional>
#include <string>

#include "gestura/app/codecs.hpp"
#include "gestura/app/context.hpp"
#include "gestura/app/motion_output.hpp"
#include "gestura/ik/chain.hpp"

namespace gestura::app {

enum class IkSolver { ccd, dls, combined, two_bone };
enum class ArmSide { left, right };

template <>
struct TextCodec<IkSolver> {
  static IkSolver parse(std::string_view text);
  static std::string format(IkSolver solver);
};
template <>
struct TextCodec<ArmSide> {
  static ArmSide parse(std::string_view text);
  static std::string format(ArmSide side) { return side == ArmSide::left ? "l" : "r"; }
};

struct ReachRequest {
  std::optional<vec3> target;  // metres, +Y up, the avatar facing +Z, its left +X
  ArmSide arm = ArmSide::left;
  IkSolver solver = IkSolver::combined;
  int frames = 30;
  MotionOutput output;  // optional

  template <class Self, class Visit>
  static void fields(Self& self, Visit&& visit) {
    visit(self.target, FieldInfo{.name = "target", .help = "the point the middle knuckle reaches for, metres (+Y up, facing +Z, left is +X)", .value = "x,y,z", .required = true});
    visit(self.arm, FieldInfo{.name = "arm", .help = "l (left) or r (right)", .value = "l|r"});
    visit(self.solver, FieldInfo{.name = "solver", .help = "ccd, dls, combined or two-bone (shoulder and elbow only)", .value = "NAME"});
    visit(self.frames, FieldInfo{.name = "frames", .help = "frames of the motion after the first", .value = "N", .min = 1, .max = 100000});
    MotionOutput::fields(self.output, visit);
  }
};

struct ReachResult {
  IkResult solve;
  float residual = 0.0f;   // metres from the target after the solve
  double seconds = 0.0;    // the solve's time
  bool clamped = false;    // two-bone: the analytic solution was clamped to the joint limits
  Clip clip;               // ready posture → reach, on the avatar's skeleton (with an output)
  std::optional<WrittenFile> written;
};

void validate(const ReachRequest& request);
ReachResult run(const ReachRequest& request, const RunContext& context = {});
nlohmann::json to_json(const ReachResult& result);

}  // namespace gestura::app
