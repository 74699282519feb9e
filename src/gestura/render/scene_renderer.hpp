#pragma once
// Draws a scene: the environment's objects (each under its own transform, so doors swing) and any
// number of characters (skinned on the CPU into world space), lit by the scene's lights with a
// shadow map for the first shadow-casting directional light. Needs a current OpenGL 3.3 core
// context (HeadlessGlContext or WindowGlContext) for its whole life.
//
// Characters use the avatar renderer's material colours and surface responses (Look) so they look
// the same in a scene as alone; the shading itself is the scene's (its lights, not the avatar
// renderer's fixed interpreter lighting).
#include <memory>
#include <span>
#include <vector>

#include "gestura/body/mesh.hpp"
#include "gestura/render/image.hpp"
#include "gestura/render/look.hpp"
#include "gestura/render/renderer.hpp"
#include "gestura/world/bvh.hpp"
#include "gestura/world/scene.hpp"
#include "gestura/world/scene_geometry.hpp"

namespace gestura {

struct CharacterFrame {
  std::span<const mat4> skinning;      // joint model matrix (world) × inverse bind, one per joint
  std::span<const float> morph_weights;
  bool visible = true;
};

class SceneRenderer {
 public:
  explicit SceneRenderer(int msaa_samples = 4);  // throws gestura::Error on GL failure
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  // Uploads the environment (object-local triangles, colours from the materials).
  void set_environment(const SceneGeometry& geometry);
  // Up to 4 directional, 4 point lights and any ambient ones (summed); none = default_lights().
  void set_lights(std::span<const SceneLight> lights, const vec3& background);
  // Uploads a character's bind-pose mesh; returns its index for CharacterFrame lists. Throws
  // gestura::Error when the mesh's arrays disagree.
  int add_character(const Mesh& mesh, const Look& look);

  void resize(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }

  // Draws every view. `object_transforms`: one per environment object (empty = as uploaded);
  // `characters`: one per added character.
  void render(std::span<const View> views, std::span<const mat4> object_transforms, std::span<const CharacterFrame> characters);
  void read_pixels(Image& out);
  void read_window_pixels(Image& out, int framebuffer_width, int framebuffer_height);
  void present(int framebuffer_width, int framebuffer_height);
  // The last render() as a texture (width() × height(), rows bottom-up): what a UI draws as an image.
  unsigned resolved_texture() const;

 private:
  struct Gl;
  struct Character;
  void draw_geometry(bool depth_only, std::span<const mat4> object_transforms);
  std::unique_ptr<Gl> gl_;
  std::vector<std::unique_ptr<Character>> characters_;
  std::vector<mat4> object_transforms_;
  std::vector<std::uint32_t> object_first_, object_count_;
  std::vector<SceneLight> lights_;
  vec3 background_{0.6f};
  Aabb bounds_;  // environment bounds at upload (what the shadow map covers, with the characters)
  int samples_ = 4;
  int width_ = 0, height_ = 0;
};

}  // namespace gestura
