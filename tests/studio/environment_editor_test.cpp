// The environment editor's plain-data half: rays from pixels and back, rays against the primitives,
// the gizmo's drags, and the editor's selection, edits, undo and files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "gestura/core/error.hpp"
#include "gestura/studio/colour_editor.hpp"
#include "gestura/studio/environment_editor.hpp"
#include "gestura/studio/environment_pick.hpp"
#include "gestura/world/scene_json.hpp"
#include "lexicon/temp_dir.hpp"

namespace gestura::studio {
namespace {

using gestura::testing::TempDir;

Camera plan_camera(float half_height, float aspect) {
  Camera c;
  c.orthographic = true;
  c.eye = vec3(0, 10, 0), c.target = vec3(0);
  c.view = glm::lookAt(c.eye, c.target, vec3(0, 0, -1));
  c.projection = glm::ortho(-half_height * aspect, half_height * aspect, -half_height, half_height, 0.1f, 30.0f);
  return c;
}

Camera perspective_camera(const vec3& eye, const vec3& target, float fov_degrees, float aspect) {
  Camera c;
  c.eye = eye, c.target = target;
  c.view = glm::lookAt(eye, target, vec3(0, 1, 0));
  c.projection = glm::perspective(deg(fov_degrees), aspect, 0.05f, 100.0f);
  return c;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(EnvironmentPick, PerspectivePixelRayPassesThroughThePointThatProjectsThere) {
  const Camera c = perspective_camera(vec3(3, 2, 4), vec3(0, 0.5f, 0), 50.0f, 1.5f);
  const vec2 size(600, 400);
  for (const vec3 p : {vec3(0, 0.5f, 0), vec3(1, 0, -1), vec3(-0.7f, 1.4f, 0.3f)}) {
    const auto pixel = project_to_pixel(c, p, size);
    ASSERT_TRUE(pixel);
    const Ray r = pixel_ray(c, *pixel, size);
    EXPECT_NEAR(1.0f, glm::length(r.direction), 1e-5f);
    // The ray leaves from the eye and passes within a millimetre of the point.
    EXPECT_LT(glm::length(r.origin - c.eye), 0.1f);
    const float t = glm::dot(p - r.origin, r.direction);
    EXPECT_LT(glm::length(r.at(t) - p), 1e-3f) << p.x << " " << p.y << " " << p.z;
  }
  // The image centre looks at the target; the top-left corner is above and to the left of it.
  const Ray centre = pixel_ray(c, size * 0.5f, size);
  EXPECT_GT(glm::dot(centre.direction, glm::normalize(c.target - c.eye)), 0.99999f);
  EXPECT_FALSE(project_to_pixel(c, c.eye * 2.0f - c.target, size));  // behind the camera
}

TEST(EnvironmentPick, PlanViewPixelsAreMetresOnTheFloor) {
  // 4 m of height over 400 pixels: a pixel is a centimetre; +x to the right, -z (north) up.
  const Camera c = plan_camera(2.0f, 1.5f);
  const vec2 size(600, 400);
  const Ray a = pixel_ray(c, vec2(300, 200), size), b = pixel_ray(c, vec2(400, 150), size);
  EXPECT_NEAR(-1.0f, a.direction.y, 1e-5f);
  EXPECT_NEAR(-1.0f, b.direction.y, 1e-5f);
  const auto move = drag_in_plane(a, b, vec3(0), vec3(0, 1, 0));
  ASSERT_TRUE(move);
  EXPECT_NEAR(1.0f, move->x, 1e-4f);
  EXPECT_NEAR(-0.5f, move->z, 1e-4f);
  EXPECT_NEAR(0.0f, move->y, 1e-5f);
  const auto pixel = project_to_pixel(c, vec3(-1.5f, 0.7f, 1.0f), size);
  ASSERT_TRUE(pixel);
  EXPECT_NEAR(150.0f, pixel->x, 1e-2f);
  EXPECT_NEAR(300.0f, pixel->y, 1e-2f);
}

TEST(EnvironmentPick, RaysAgainstThePrimitives) {
  Shape box;
  box.kind = ShapeKind::Box, box.size = vec3(2, 1, 4);
  EXPECT_NEAR(4.0f, *ray_shape(Ray{vec3(5, 0, 0), vec3(-1, 0, 0)}, box), 1e-5f);
  EXPECT_NEAR(5.5f, *ray_shape(Ray{vec3(0, 6, 1.9f), vec3(0, -1, 0)}, box), 1e-5f);
  EXPECT_FALSE(ray_shape(Ray{vec3(0, 6, 2.1f), vec3(0, -1, 0)}, box));
  EXPECT_FALSE(ray_shape(Ray{vec3(5, 0, 0), vec3(1, 0, 0)}, box));  // pointing away
  EXPECT_NEAR(1.0f, *ray_shape(Ray{vec3(0), vec3(1, 0, 0)}, box), 1e-5f);  // from inside: the way out

  Shape sphere;
  sphere.kind = ShapeKind::Sphere, sphere.radius = 0.5f;
  EXPECT_NEAR(2.5f, *ray_shape(Ray{vec3(0, 0, 3), vec3(0, 0, -1)}, sphere), 1e-5f);
  EXPECT_FALSE(ray_shape(Ray{vec3(0.51f, 0, 3), vec3(0, 0, -1)}, sphere));

  Shape cylinder;
  cylinder.kind = ShapeKind::Cylinder, cylinder.radius = 0.3f, cylinder.height = 1.0f;
  EXPECT_NEAR(1.7f, *ray_shape(Ray{vec3(2, 0.4f, 0), vec3(-1, 0, 0)}, cylinder), 1e-5f);   // the side
  EXPECT_FALSE(ray_shape(Ray{vec3(2, 0.6f, 0), vec3(-1, 0, 0)}, cylinder));                // above it
  EXPECT_NEAR(1.5f, *ray_shape(Ray{vec3(0.1f, 2, 0.1f), vec3(0, -1, 0)}, cylinder), 1e-5f);  // the top cap
  EXPECT_FALSE(ray_shape(Ray{vec3(0.25f, 2, 0.25f), vec3(0, -1, 0)}, cylinder));           // beside the cap

  Shape plane;
  plane.kind = ShapeKind::Plane, plane.size = vec3(2, 0, 2);
  EXPECT_NEAR(3.0f, *ray_shape(Ray{vec3(0.5f, 3, -0.5f), vec3(0, -1, 0)}, plane), 1e-5f);
  EXPECT_FALSE(ray_shape(Ray{vec3(1.5f, 3, 0), vec3(0, -1, 0)}, plane));
  EXPECT_FALSE(ray_shape(Ray{vec3(0, 3, 0), vec3(1, 0, 0)}, plane));  // parallel

  // Placed: a box scaled ×2 in x, turned 90° about y and moved to (10, 0, 0): its long side now
  // runs along x over 4 m... the world distance is kept.
  const ObjectTransform t{vec3(10, 0, 0), vec3(0, 90, 0), vec3(2, 1, 1)};
  // In its frame the box spans x ±2 (scaled), z ±2; turned, world x spans 10 ± 2 and z ± 2.
  EXPECT_NEAR(3.0f, *ray_placed_shape(Ray{vec3(10, 0, 5), vec3(0, 0, -1)}, box, t.matrix()), 1e-4f);
  EXPECT_NEAR(6.0f, *ray_placed_shape(Ray{vec3(2, 0, 0), vec3(1, 0, 0)}, box, t.matrix()), 1e-4f);
  EXPECT_NEAR(2.0f, *ray_upright_cylinder(Ray{vec3(0, 1, 2.3f), vec3(0, 0, -1)}, vec3(0), 0.3f, 1.7f), 1e-5f);
  EXPECT_FALSE(ray_upright_cylinder(Ray{vec3(0, 1.8f, 2.3f), vec3(0, 0, -1)}, vec3(0), 0.3f, 1.7f));
  EXPECT_NEAR(1.0f, *ray_triangle(Ray{vec3(0.2f, 0.2f, 1), vec3(0, 0, -1)}, vec3(0), vec3(1, 0, 0), vec3(0, 1, 0)), 1e-6f);
  EXPECT_FALSE(ray_triangle(Ray{vec3(0.8f, 0.8f, 1), vec3(0, 0, -1)}, vec3(0), vec3(1, 0, 0), vec3(0, 1, 0)));
}

TEST(EnvironmentPick, GizmoDragsAlongAnAxisRoundAnAxisAndSnap) {
  const Camera c = perspective_camera(vec3(4, 3, 5), vec3(0, 0.5f, 0), 45.0f, 1.0f);
  const vec2 size(500, 500);
  // A drag from where (0,0,0) projects to where (0.8, 0, 0) projects moves 0.8 m along x.
  const Ray from = pixel_ray(c, *project_to_pixel(c, vec3(0), size), size);
  const Ray to = pixel_ray(c, *project_to_pixel(c, vec3(0.8f, 0, 0), size), size);
  EXPECT_NEAR(0.8f, *drag_along_axis(from, to, vec3(0), vec3(1, 0, 0)), 1e-3f);
  // A ray along the axis cannot move along it.
  EXPECT_FALSE(closest_on_axis(Ray{vec3(0, 5, 0), vec3(0, -1, 0)}, vec3(0), vec3(0, 1, 0)));

  // A quarter turn round y seen from above: from +x to -z is counter-clockwise (toward -z from +x is
  // the right-hand rule's positive sense about +y).
  const Ray above_x{vec3(1, 5, 0), vec3(0, -1, 0)}, above_minus_z{vec3(0, 5, -1), vec3(0, -1, 0)};
  EXPECT_NEAR(kPi / 2, *drag_angle(above_x, above_minus_z, vec3(0), vec3(0, 1, 0)), 1e-5f);
  EXPECT_FALSE(drag_angle(Ray{vec3(5, 0, 0), vec3(-1, 0, 0)}, Ray{vec3(5, 0, 1), vec3(-1, 0, 0)}, vec3(0), vec3(0, 1, 0)));

  // Turning about world y adds to the yaw; about x after a yaw composes (and reads back the same).
  EXPECT_NEAR(120.0f, rotate_euler(vec3(0, 30, 0), vec3(0, 1, 0), deg(90.0f)).y, 1e-3f);
  const vec3 e = rotate_euler(vec3(0, 90, 0), vec3(1, 0, 0), deg(30.0f));
  const ObjectTransform a{vec3(0), e, vec3(1)};
  const quat expected = glm::angleAxis(deg(30.0f), vec3(1, 0, 0)) * glm::angleAxis(deg(90.0f), vec3(0, 1, 0));
  EXPECT_GT(std::abs(glm::dot(a.orientation(), expected)), 0.99999f);

  EXPECT_FLOAT_EQ(0.75f, snap(0.8f, 0.25f));
  EXPECT_FLOAT_EQ(0.8f, snap(0.8f, 0.0f));
  EXPECT_FLOAT_EQ(-15.0f, snap(-16.0f, 15.0f));
  EXPECT_NEAR(3.0f, distance_to_segment(vec2(5, 3), vec2(0, 0), vec2(10, 0)), 1e-6f);
  EXPECT_NEAR(5.0f, distance_to_segment(vec2(13, 4), vec2(0, 0), vec2(10, 0)), 1e-6f);
}

Scene room() {
  return parse_scene(R"({
    "materials": {"wood": "#8a5a36", "fabric": "#51677a"},
    "objects": [
      {"name": "floor", "shape": "plane", "size": [8, 6]},
      {"name": "table", "material": "wood", "position": [1, 0, 0], "parts": [
        {"shape": "box", "size": [1.2, 0.05, 0.8], "position": [0, 0.72, 0]},
        {"shape": "box", "size": [0.06, 0.7, 0.06], "position": [0.5, 0.35, 0.3]}]},
      {"name": "ball", "shape": "sphere", "radius": 0.2, "position": [-2, 0.2, 1], "material": "fabric"}],
    "places": {"door": {"position": [3, 0, -2.5]}},
    "characters": [{"name": "anna", "position": [-1, 0, 2]}]
  })", "room.json");
}

EnvironmentEditor editor_with(const TempDir& dir, const Scene& scene) {
  const std::string path = dir.file("room.json");
  std::ofstream(path) << scene_to_json(scene).dump(2);
  EnvironmentEditor editor;
  editor.open(path);
  return editor;
}

TEST(EnvironmentEditor, PicksTheNearestPartPlaceOrCharacter) {
  TempDir dir;
  EnvironmentEditor editor = editor_with(dir, room());
  const Ray down_on_table{vec3(1.1f, 5, 0.1f), vec3(0, -1, 0)};
  float distance = 0;
  EnvSelection s = editor.pick(down_on_table, nullptr, &distance);
  ASSERT_EQ(EnvItem::Object, s.kind);
  EXPECT_EQ((std::vector<int>{1, 0}), s.path);  // the table's top, not the floor under it
  EXPECT_NEAR(5.0f - 0.745f, distance, 1e-4f);
  editor.select(s);
  EXPECT_EQ("table/0", editor.selection_name());
  // The leg, from the side, below the top.
  s = editor.pick(Ray{vec3(1.5f, 0.3f, 5), vec3(0, 0, -1)});
  EXPECT_EQ((std::vector<int>{1, 1}), s.path);
  EXPECT_EQ(EnvItem::Place, editor.pick(Ray{vec3(3, 5, -2.5f), vec3(0, -1, 0)}).kind);
  s = editor.pick(Ray{vec3(-1, 1, 6), vec3(0, 0, -1)});
  EXPECT_EQ(EnvItem::Character, s.kind);
  EXPECT_EQ(EnvItem::None, editor.pick(Ray{vec3(-1, 5, 2.9f), vec3(0, 1, 0)}).kind);  // looking up at the sky
  EXPECT_THROW(editor.select("chiar"), Error);
  EXPECT_THROW(editor.select("table/7"), Error);
  EXPECT_THROW(editor.select("place:window"), Error);
}

TEST(EnvironmentEditor, ADragIsOneUndoableStepAndPartsMoveInTheirGroupsFrame) {
  TempDir dir;
  Scene s = room();
  s.objects[1].transform.rotation = vec3(0, 90, 0);  // the table turned: its parts' frame is turned
  EnvironmentEditor editor = editor_with(dir, s);
  editor.select("ball");
  editor.begin_edit("move ball");
  for (int i = 1; i <= 5; ++i) {
    EnvTransform t = *editor.transform();
    t.position.x += 0.1f;
    editor.set_transform(t);
  }
  editor.end_edit();
  EXPECT_NEAR(-1.5f, editor.scene().objects[2].transform.position.x, 1e-5f);
  EXPECT_EQ("move ball", editor.undo_label());
  EXPECT_TRUE(editor.dirty());
  ASSERT_TRUE(editor.undo());
  EXPECT_NEAR(-2.0f, editor.scene().objects[2].transform.position.x, 1e-5f);
  ASSERT_TRUE(editor.redo());
  EXPECT_NEAR(-1.5f, editor.scene().objects[2].transform.position.x, 1e-5f);

  // The table's leg: its world position comes through the turned group.
  editor.select("table/1");
  const vec3 world = vec3(*editor.world_matrix() * vec4(0, 0, 0, 1));
  EXPECT_NEAR(1.0f + 0.3f, world.x, 1e-4f);  // local (0.5, _, 0.3) turned 90° about y: x' = z, z' = -x
  EXPECT_NEAR(-0.5f, world.z, 1e-4f);
  const std::uint64_t geometry = editor.geometry_revision();
  EnvTransform t = *editor.transform();
  t.scale.y = -3.0f;  // stops at a millimetre instead of turning inside out
  editor.set_transform(t);
  EXPECT_GT(editor.scene().objects[1].parts[1].transform.scale.y, 0.0f);
  EXPECT_GT(editor.geometry_revision(), geometry);  // a part changes its group's triangles
  // Moving a top-level object is drawn by its transform alone.
  editor.select("ball");
  const std::uint64_t before = editor.geometry_revision();
  t = *editor.transform();
  t.position.z = 0.0f;
  editor.set_transform(t);
  EXPECT_EQ(before, editor.geometry_revision());
  t.position.z = std::nanf("");
  editor.set_transform(t);
  EXPECT_EQ(0.0f, editor.scene().objects[2].transform.position.z);
}

TEST(EnvironmentEditor, AddDeleteDuplicateGroupAndColourAreUndoable) {
  TempDir dir;
  EnvironmentEditor editor = editor_with(dir, room());
  editor.add_primitive(ShapeKind::Cylinder, vec3(2, 0, 2));
  ASSERT_EQ(4u, editor.scene().objects.size());
  EXPECT_EQ("cylinder1", editor.selection_name());
  EXPECT_NEAR(0.25f, editor.scene().objects[3].transform.position.y, 1e-6f);  // standing on the floor
  editor.duplicate_selected();
  ASSERT_EQ(5u, editor.scene().objects.size());
  EXPECT_NEAR(2.5f, editor.scene().objects[4].transform.position.x, 1e-6f);
  editor.group({"cylinder1", "cylinder1-1"}, "stools");
  ASSERT_EQ(4u, editor.scene().objects.size());
  const SceneObject& g = editor.scene().objects.back();
  EXPECT_EQ("stools", g.name);
  ASSERT_EQ(2u, g.parts.size());
  // Nothing moved: group origin + part offset = where each was.
  EXPECT_NEAR(2.0f, g.transform.position.x + g.parts[0].transform.position.x, 1e-5f);
  EXPECT_NEAR(2.5f, g.transform.position.x + g.parts[1].transform.position.x, 1e-5f);
  EXPECT_NEAR(0.25f, g.transform.position.y + g.parts[0].transform.position.y, 1e-5f);

  editor.select("ball");
  editor.set_color(vec3(1, 0, 0));
  EXPECT_EQ(vec3(1, 0, 0), *editor.selected_color());
  EXPECT_EQ(vec3(1, 0, 0), editor.scene().materials.at("ball").color);
  editor.select("place:door");
  editor.remove_selected();
  EXPECT_FALSE(editor.scene().places.contains("door"));
  editor.add_character("ben", vec3(0, 0, -1));
  ASSERT_EQ(2u, editor.scene().characters.size());

  // Undo all the way back: the scene is the one opened.
  const std::string opened = scene_to_json(room()).dump();
  int undone = 0;
  while (editor.undo()) ++undone;
  EXPECT_EQ(6, undone);
  EXPECT_EQ(opened, scene_to_json(editor.scene()).dump());
  EXPECT_EQ("", editor.undo_label());
  EXPECT_EQ("add character ben", [&] { while (editor.redo()) {} return editor.undo_label(); }());
}

TEST(EnvironmentEditor, SavesAtomicallyAndAMalformedFileChangesNothing) {
  TempDir dir;
  EnvironmentEditor editor = editor_with(dir, room());
  editor.select("table");
  EnvTransform t = *editor.transform();
  t.position.x = 2.5f;
  editor.set_transform(t);
  editor.save();
  EXPECT_FALSE(editor.dirty());
  Scene saved = read_scene(dir.file("room.json"));
  EXPECT_NEAR(2.5f, saved.objects[1].transform.position.x, 1e-6f);
  // A malformed file: the error names its place, the editor keeps its scene and its file name.
  const std::string bad = dir.file("bad.json");
  const std::string bad_text = R"({"objects": [{"name": "x", "shape": "cube"}]})";
  std::ofstream(bad) << bad_text;
  t.position.x = 3.0f;
  editor.set_transform(t);
  try {
    editor.open(bad);
    FAIL() << "opened a malformed scene";
  } catch (const Error& e) {
    EXPECT_NE(std::string::npos, std::string(e.what()).find("bad.json:1:")) << e.what();
    EXPECT_NE(std::string::npos, std::string(e.what()).find("cube")) << e.what();
  }
  EXPECT_EQ(dir.file("room.json"), editor.file());
  EXPECT_NEAR(3.0f, editor.scene().objects[1].transform.position.x, 1e-6f);
  EXPECT_TRUE(editor.dirty());
  EXPECT_EQ(bad_text, read_text(bad));
  ASSERT_TRUE(editor.undo());
  EXPECT_NEAR(2.5f, editor.scene().objects[1].transform.position.x, 1e-6f);
  // A file that cannot be written: the error names it, the old file stays whole.
  EXPECT_THROW(editor.save(dir.file("no-such-dir/room.json")), Error);
  EXPECT_NEAR(2.5f, read_scene(dir.file("room.json")).objects[1].transform.position.x, 1e-6f);
}

TEST(ColourEditor, HsvAndRgbAgreeAndThePaletteFollowsAndColoursTheSelection) {
  EXPECT_EQ(vec3(0, 1, 1), rgb_to_hsv(vec3(1, 0, 0)));
  const vec3 blue = rgb_to_hsv(vec3(0, 0, 1));
  EXPECT_NEAR(2.0f / 3.0f, blue.x, 1e-6f);
  for (const vec3 c : {vec3(0.2f, 0.4f, 0.6f), vec3(0.9f, 0.1f, 0.5f), vec3(0.3f), vec3(0.0f), vec3(0.7f, 0.65f, 0.1f)}) {
    const vec3 back = hsv_to_rgb(rgb_to_hsv(c));
    EXPECT_LT(glm::length(back - c), 1e-5f) << c.x << " " << c.y << " " << c.z;
  }
  EXPECT_EQ("#2060c0", color_hex(vec3(0x20, 0x60, 0xc0) / 255.0f));

  TempDir dir;
  EnvironmentEditor editor = editor_with(dir, room());
  ColourEditor colour;
  editor.select("ball");
  colour.follow(editor);
  EXPECT_EQ("#51677a", color_hex(colour.palette().color()));  // the ball's fabric
  colour.choose_ramp(editor, 0, 3);                             // four steps of red up
  const vec3 chosen = editor.scene().materials.at("ball").color;
  EXPECT_NEAR(0x51 / 255.0f + 4.0f / 16.0f, chosen.x, 1e-5f);
  EXPECT_EQ(chosen, colour.palette().color());
  EXPECT_EQ(vec3(0x8a, 0x5a, 0x36) / 255.0f, editor.scene().materials.at("wood").color);  // others keep theirs
  colour.store(0);
  colour.choose_hsv(editor, vec3(0.0f, 0.0f, 1.0f));
  EXPECT_EQ(vec3(1.0f), editor.scene().materials.at("ball").color);
  colour.choose_slot(editor, 0);
  EXPECT_EQ(chosen, editor.scene().materials.at("ball").color);
  EXPECT_THROW(colour.choose_slot(editor, 1), Error);  // empty
  EXPECT_THROW(colour.choose_ramp(editor, 6, 0), Error);
  // Undo takes the colour back and the palette follows it.
  ASSERT_TRUE(editor.undo());
  colour.follow(editor);
  EXPECT_EQ(vec3(1.0f), colour.palette().color());
}

}  // namespace
}  // namespace gestura::studio
