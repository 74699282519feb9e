#pragma once
// Rendering a performed scene to a file — a PNG still, a 4×4 contact sheet, or GIF/MP4/WebM — from
// the scene's cameras or the built-in views (scene_cameras.hpp), headless. SceneAnimator is the frame
// driver the file job and the interactive viewer share.
#include <memory>
#include <string>
#include <vector>

#include "gestura/render/render_job.hpp"
#include "gestura/render/scene_cameras.hpp"
#include "gestura/render/scene_renderer.hpp"
#include "gestura/render/subject.hpp"
#include "gestura/world/performance.hpp"

namespace gestura {

struct SceneRenderJob {
  std::string output;                          // .png, .gif, .mp4 or .webm
  ImageSize size{1280, 720};
  int fps = 30;
  std::vector<std::string> cameras{"perspective"};
  bool sheet = false;                          // PNG only: 4×4 contact sheet over the performance
  float still_time = 0.0f;                     // the time a single PNG shows
  int msaa_samples = 4;
};

// Throws gestura::Error for a bad combination (as validate(RenderJob)) or an unknown camera name.
void validate(const SceneRenderJob& job, const Scene& scene);

// The look of a character: the avatar renderer's defaults, the scene's colours for it, and a cloth
// colour of its own (from a small palette by its index) when the scene names none.
Look character_look(const PerformedCharacter& character, std::size_t index);

// Poses every character and door at a time, for the renderer.
class SceneAnimator {
 public:
  // Contract: all three outlive the animator. Throws gestura::Error when a character's clip does
  // not fit its avatar.
  SceneAnimator(const Scene& scene, const SceneGeometry& geometry, const ScenePerformance& performance);
  ~SceneAnimator();

  float duration() const { return performance_->duration; }
  void upload(SceneRenderer& renderer) const;  // environment, lights, characters
  void pose_at(float t);
  std::span<const CharacterFrame> frames() const { return frames_; }
  std::span<const mat4> objects() const { return objects_; }
  std::span<const CharacterView> views() const { return views_; }
  const Aabb& bounds() const { return bounds_; }

 private:
  const Scene* scene_;
  const SceneGeometry* geometry_;
  const ScenePerformance* performance_;
  std::vector<std::unique_ptr<RenderSubject>> subjects_;
  std::vector<std::unique_ptr<Animator>> animators_;
  std::vector<CharacterFrame> frames_;
  std::vector<mat4> objects_;
  std::vector<CharacterView> views_;
  std::vector<int> heads_;
  Aabb bounds_;
};

// Renders headless and writes job.output (staged: nothing is left behind on failure).
RenderReport render_scene_to_file(const Scene& scene, const SceneGeometry& geometry, const ScenePerformance& performance,
                                  const SceneRenderJob& job);

}  // namespace gestura
