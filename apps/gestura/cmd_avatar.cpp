// gestura avatar — the default virtual human: export it as binary glTF or print what it is made of.
#include <charconv>
#include <cstdio>
#include <iostream>

#include "command.hpp"
#include "gestura/io/avatar_source.hpp"
#include "gestura/body/face_morphs.hpp"
#include "gestura/core/error.hpp"
#include "gestura/body/body_sites.hpp"
#include "gestura/io/gltf_export.hpp"

namespace {

using gestura::Error;

const char* kUsage =
    "usage: gestura avatar export -o FILE.glb [PARAMS]\n"
    "       gestura avatar info [PARAMS]\n"
    "       gestura avatar sites [-o FILE.json] [PARAMS]   (sign locations: name → position in metres)\n"
    "\n"
    "Builds the default avatar from parameters (no asset files) and writes it as binary glTF 2.0\n"
    "(skin, joints, inverse bind matrices, named morph targets, materials), or prints its joints,\n"
    "degrees of freedom, vertex and triangle counts and morph names.\n"
    "\n"
    "PARAMS:\n"
    "  --avatar SPEC         default (built from the parameters below) or makehuman:DIR\n"
    "                        (MakeHuman base mesh + default rig; the parameters are then ignored)\n"
    "  --height M            crown to floor in metres (1.0 .. 2.5, default 1.70)\n"
    "  --build X             girth multiplier (0.6 .. 1.6, default 1)\n"
    "  --sex S               female | male | neutral (default neutral)\n"
    "  --shoulder-width X    multiplier (0.7 .. 1.4)\n"
    "  --arm-length X        multiplier (0.8 .. 1.25)\n"
    "  --hand-size X         multiplier (0.7 .. 1.4)\n"
    "  --finger-length X     multiplier (0.7 .. 1.4)\n"
    "  --finger-thickness X  multiplier (0.6 .. 1.5)\n"
    "  --weights METHOD      skin weights: field (default) | spheres | two-layer";

float parse_number(const std::string& flag, const std::string& text) {
  float value = 0.0f;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) throw Error("flag " + flag + ": '" + text + "' is not a number");
  return value;
}

struct Request {
  gestura::AvatarParams params;
  gestura::AvatarOptions options;
  std::string output;
  std::string spec = "default";  // --avatar: default or makehuman:DIR
};

Request parse(const std::vector<std::string>& args, std::size_t first) {
  Request r;
  for (std::size_t i = first; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "-o" || a == "--output") r.output = gestura::cli::flag_value(args, i);
    else if (a == "--avatar") r.spec = gestura::cli::flag_value(args, i);
    else if (a == "--height") r.params.height = parse_number(a, gestura::cli::flag_value(args, i));
    else if (a == "--build") r.params.build = parse_number(a, gestura::cli::flag_value(args, i));
    else if (a == "--sex") r.params.sex = gestura::parse_sex(gestura::cli::flag_value(args, i));
    else if (a == "--shoulder-width") r.params.shoulder_width = parse_number(a, gestura::cli::flag_value(args, i));
    else if (a == "--arm-length") r.params.arm_length = parse_number(a, gestura::cli::flag_value(args, i));
    else if (a == "--hand-size") r.params.hand_size = parse_number(a, gestura::cli::flag_value(args, i));
    else if (a == "--finger-length") r.params.finger_length = parse_number(a, gestura::cli::flag_value(args, i));
    else if (a == "--finger-thickness") r.params.finger_thickness = parse_number(a, gestura::cli::flag_value(args, i));
    else if (a == "--weights") r.options.weights = gestura::parse_skin_weight_method(gestura::cli::flag_value(args, i));
    else throw Error("avatar: unknown argument '" + a + "' (see gestura avatar --help)");
  }
  r.params.validate();
  return r;
}

void print_info(const gestura::Avatar& a, gestura::SkinWeightMethod weights) {
  const gestura::Skeleton& s = a.skeleton;
  std::printf("height %.3f m, sex %s, skin weights %s\n", a.params.height, std::string(gestura::to_string(a.params.sex)).c_str(),
              std::string(gestura::to_string(weights)).c_str());
  std::printf("joints %zu, degrees of freedom %d\n", s.size(), s.total_dofs());
  for (std::size_t j = 0; j < s.size(); ++j) {
    const gestura::JointDofs& d = s.dofs[j];
    std::printf("  %-20s parent %-20s dof %d", s.names[j].c_str(), s.parents[j] < 0 ? "-" : s.names[static_cast<std::size_t>(s.parents[j])].c_str(),
                d.count());
    for (int axis = 0; axis < 3; ++axis)
      if (d.free(axis))
        std::printf("  %c %.0f..%.0f", "xyz"[axis], gestura::to_degrees(d.min_angle[axis]), gestura::to_degrees(d.max_angle[axis]));
    std::printf("\n");
  }
  std::printf("vertices %zu, triangles %zu\n", a.mesh.vertex_count(), a.mesh.triangle_count());
  std::printf("morph targets %zu:", a.mesh.morphs.size());
  for (const gestura::MorphTarget& m : a.mesh.morphs) std::printf(" %s", m.name.c_str());
  std::printf("\nexpressions:");
  for (std::string_view e : gestura::kExpressionNames) std::printf(" %s", std::string(e).c_str());
  std::printf("\n");
}

gestura::Avatar build(const Request& r) {
  return r.spec == "default" ? gestura::build_avatar(r.params, r.options) : gestura::load_avatar(r.spec);
}

int run(const std::vector<std::string>& args) {
  if (args.empty()) throw Error("avatar: missing subcommand (export, info or sites)");
  if (args[0] == "export") {
    const Request r = parse(args, 1);
    if (r.output.empty()) throw Error("avatar export: missing -o FILE.glb");
    const gestura::Avatar a = build(r);
    gestura::write_glb(r.output, a.skeleton, a.mesh, "gestura_avatar");
    std::printf("wrote %s: %zu joints, %zu vertices, %zu triangles, %zu morph targets\n", r.output.c_str(),
                a.skeleton.size(), a.mesh.vertex_count(), a.mesh.triangle_count(), a.mesh.morphs.size());
    return 0;
  }
  if (args[0] == "info") {
    const Request r = parse(args, 1);
    if (!r.output.empty()) throw Error("avatar info: -o is only for export");
    print_info(build(r), r.options.weights);
    return 0;
  }
  if (args[0] == "sites") {
    const Request r = parse(args, 1);
    const gestura::Avatar a = build(r);
    const std::string json = gestura::body_sites_json(a.skeleton, gestura::find_body_sites(a.skeleton, a.mesh));
    if (r.output.empty()) {
      std::fputs(json.c_str(), stdout);
    } else {
      std::FILE* f = std::fopen(r.output.c_str(), "wb");
      if (!f) throw Error(r.output + ": cannot write here");
      const bool ok = std::fwrite(json.data(), 1, json.size(), f) == json.size();
      if (std::fclose(f) != 0 || !ok) throw Error(r.output + ": write failed");
      std::printf("wrote %s\n", r.output.c_str());
    }
    return 0;
  }
  throw Error("avatar: unknown subcommand '" + args[0] + "' (export, info or sites)");
}

gestura::cli::Registration reg{{"avatar", "build the default avatar; export it as glTF or print its structure", kUsage, run}};

}  // namespace
