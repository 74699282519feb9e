// Fuzz target: the world's scene files (docs/scene.md), as `gestura scene` reads them.
// parse_scene, then what a read scene must allow: written back by scene_to_json (what an editor
// saves) it reads again (else abort: a finding), it flattens into triangles within the triangle cap,
// and the script it carries is read and checked against it. Mesh files are not opened (a scene that
// names one is not flattened): the fuzzer must not read the machine's files.
#include <cstdlib>

#include "fuzz_target.hpp"
#include "gestura/world/scene_geometry.hpp"
#include "gestura/world/scene_json.hpp"
#include "gestura/world/script.hpp"

namespace {

bool names_a_mesh(const gestura::SceneObject& object) {
  if (object.shape.kind == gestura::ShapeKind::Mesh) return true;
  for (const auto& part : object.parts)
    if (names_a_mesh(part)) return true;
  return false;
}

bool names_a_mesh(const gestura::Scene& scene) {
  for (const auto& object : scene.objects)
    if (names_a_mesh(object)) return true;
  for (const auto& [name, prototype] : scene.prototypes)
    if (names_a_mesh(prototype)) return true;
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace gestura;
  const std::string_view text = fuzz::text_of(data, size);
  fuzz::expect_result_or_error([&] {
    const Scene scene = parse_scene(text, "fuzz.json", "/nonexistent-fuzz-folder");
    try {
      (void)parse_scene(scene_to_json(scene).dump(), "written.json", "/nonexistent-fuzz-folder");
    } catch (const Error&) {
      std::abort();  // a scene that reads must read back after it is written
    }
    if (!names_a_mesh(scene)) (void)build_scene_geometry(scene);
    if (!scene.script.empty()) check_script(parse_script(scene.script, "fuzz.json (its script)"), scene);
  });
  return 0;
}
