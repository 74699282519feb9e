// gestura reach: the arm reaches for a point (alias-movement-through-environments.txt §6.2). The hand
// travels on a straight line from the ready posture to the target; every frame is one IK solve
// seeded with the previous frame, so the motion is continuous. Prints iterations, residual and time.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "command.hpp"
#include "gestura/core/error.hpp"
#include "gestura/ik/ccd.hpp"
#include "gestura/ik/combined.hpp"
#include "gestura/ik/dls.hpp"
#include "gestura/ik/limb.hpp"
#include "gestura/ik/reference_arm.hpp"

namespace {

using namespace gestura;

// The skeleton the arm belongs to. Swap this for the default avatar once it is wired in: everything
// below only needs l_shoulder, l_elbow, l_wrist and l_hand_site.
Skeleton reach_skeleton() { return reference_arm_skeleton(); }

vec3 parse_point(const std::string& text) {
  vec3 v(0.0f);
  std::istringstream in(text);
  char comma1 = 0, comma2 = 0;
  if (!(in >> v.x >> comma1 >> v.y >> comma2 >> v.z) || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof() ||
      !is_finite(v))
    throw Error("--target: expected x,y,z in metres, got '" + text + "'");
  return v;
}

// Minimal BVH export of the arm motion (ZXY Euler channels, root with positions). To be replaced by
// io/bvh's make_bvh/save_bvh when that module is on this branch.
void write_bvh(const std::string& path, const Skeleton& skeleton, const std::vector<Pose>& frames, float frame_time) {
  std::ofstream out(path);
  if (!out) throw Error(SourceLocation{path}, "cannot write file");
  std::vector<int> children(skeleton.size(), 0);
  for (std::size_t j = 1; j < skeleton.size(); ++j) children[skeleton.parents[j]]++;
  out << "HIERARCHY\n";
  std::vector<int> order;  // joints with channels, in file order
  auto emit = [&](auto&& self, int j, int depth) -> void {
    const std::string pad(static_cast<std::size_t>(2 * depth), ' ');
    const vec3 o = skeleton.rest_translations[j];
    if (children[j] == 0 && depth > 0) {
      out << pad << "End Site\n" << pad << "{\n" << pad << "  OFFSET " << o.x << " " << o.y << " " << o.z << "\n" << pad << "}\n";
      return;
    }
    out << pad << (depth == 0 ? "ROOT " : "JOINT ") << skeleton.names[j] << "\n" << pad << "{\n";
    out << pad << "  OFFSET " << o.x << " " << o.y << " " << o.z << "\n";
    out << pad << "  CHANNELS " << (depth == 0 ? "6 Xposition Yposition Zposition " : "3 ") << "Zrotation Xrotation Yrotation\n";
    order.push_back(j);
    for (std::size_t c = 0; c < skeleton.size(); ++c)
      if (skeleton.parents[c] == j) self(self, static_cast<int>(c), depth + 1);
    out << pad << "}\n";
  };
  emit(emit, 0, 0);
  out << "MOTION\nFrames: " << frames.size() << "\nFrame Time: " << frame_time << "\n";
  std::vector<vec3> previous(skeleton.size(), vec3(0.0f));
  for (const Pose& pose : frames) {
    const vec3 t = pose.translations[0];
    out << t.x << " " << t.y << " " << t.z;
    for (int j : order) {
      previous[j] = quat_to_euler_near(pose.rotations[j], RotationOrder::ZXY, previous[j]);
      out << " " << to_degrees(previous[j].z) << " " << to_degrees(previous[j].x) << " " << to_degrees(previous[j].y);
    }
    out << "\n";
  }
}

int run_reach(const std::vector<std::string>& args) {
  std::string solver = "dls", output;
  vec3 target(0.0f);
  bool has_target = false;
  int frames = 30;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--target") target = parse_point(cli::flag_value(args, i)), has_target = true;
    else if (args[i] == "--solver") solver = cli::flag_value(args, i);
    else if (args[i] == "-o") output = cli::flag_value(args, i);
    else if (args[i] == "--frames") {
      const std::string v = cli::flag_value(args, i);
      try {
        std::size_t used = 0;
        frames = std::stoi(v, &used);
        if (used != v.size() || frames < 1 || frames > 100000) throw std::invalid_argument(v);
      } catch (const std::exception&) {
        throw Error("--frames: expected a whole number in 1..100000, got '" + v + "'");
      }
    } else throw Error("unknown argument '" + args[i] + "' (see gestura reach --help)");
  }
  if (!has_target) throw Error("--target x,y,z is required");
  if (solver != "ccd" && solver != "dls" && solver != "combined" && solver != "two-bone")
    throw Error("--solver: expected ccd, dls, combined or two-bone, got '" + solver + "'");

  const Skeleton skeleton = reach_skeleton();
  const IkChain chain = arm_chain(skeleton);
  IkWorkspace ws(chain);
  const int shoulder = skeleton.find("l_shoulder"), elbow = skeleton.find("l_elbow"), wrist = skeleton.find("l_wrist"),
            site = skeleton.find("l_hand_site");
  Pose pose = arm_ready_pose(skeleton);
  std::vector<mat4> model(skeleton.size());
  local_to_model(skeleton, pose, model);
  const vec3 start(model[site][3]);
  const mat4 base = parent_model_matrix(skeleton, pose, shoulder);

  std::vector<Pose> motion{pose};
  IkResult last;
  long long total_iterations = 0;
  double seconds = 0.0;
  for (int f = 1; f <= frames; ++f) {
    const float s = static_cast<float>(f) / static_cast<float>(frames);
    const float ease = s * s * (3.0f - 2.0f * s);  // slow in, slow out
    const vec3 goal = glm::mix(start, target, ease);
    const auto t0 = std::chrono::steady_clock::now();
    if (solver == "two-bone") {
      // The two-bone solver places the wrist; aim the hand site by targeting the wrist a hand's
      // length short of the goal along the forearm's current direction.
      local_to_model(skeleton, pose, model);
      const vec3 hand = vec3(model[site][3]) - vec3(model[wrist][3]);
      const LimbIkResult r = solve_limb(skeleton, pose, shoulder, elbow, wrist, vec3(-1, 0, 0), goal - hand,
                                        vec3(0.6f, 0.9f, -0.6f), 0.98f);
      last = IkResult{1, r.position_error, 0.0f, r.position_error < 1e-4f};
    } else {
      last = solver == "ccd"   ? solve_ccd(skeleton, chain, base, IkTarget{goal}, IkSettings{}, ws, pose)
             : solver == "dls" ? solve_dls(skeleton, chain, base, IkTarget{goal}, IkSettings{}, ws, pose)
                               : solve_combined(skeleton, chain, base, IkTarget{goal}, IkSettings{}, ws, pose);
    }
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    total_iterations += last.iterations;
    motion.push_back(pose);
  }
  local_to_model(skeleton, pose, model);
  const float residual = glm::length(vec3(model[site][3]) - target);
  std::printf("solver %s, %d frames toward (%.3f, %.3f, %.3f)\n", solver.c_str(), frames, target.x, target.y, target.z);
  std::printf("last frame: %d iterations, residual %.6f m%s\n", last.iterations, residual,
              residual < 1e-4f ? "" : " (target out of reach or blocked by joint limits: closest reach)");
  std::printf("all frames: %lld iterations, %.1f us solving (%.2f us per frame)\n", total_iterations, seconds * 1e6,
              seconds * 1e6 / frames);
  if (!output.empty()) {
    write_bvh(output, skeleton, motion, 1.0f / 30.0f);
    std::printf("wrote %s\n", output.c_str());
  }
  return 0;
}

const cli::Registration reg{{"reach", "reach for a point with the arm (IK demo: ccd, dls, combined or two-bone)",
                             "usage: gestura reach --target x,y,z [--solver ccd|dls|combined|two-bone] [--frames N] [-o out.bvh]\n"
                             "  Moves the left hand of the 7-DoF reference arm (shoulder at 0.18,1.40,0; reach\n"
                             "  0.65 m; metres, +Y up, facing +Z) from the ready posture to the target over N frames\n"
                             "  (default 30, 30 fps), solving IK per frame within the joints' limits.",
                             run_reach}};

}  // namespace
