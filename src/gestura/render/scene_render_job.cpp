#include "gestura/render/scene_render_job.hpp"

#include "gestura/core/error.hpp"
#include "gestura/render/camera_glide.hpp"
#include "gestura/render/encoder_thread.hpp"
#include "gestura/render/gl_context.hpp"
#include "gestura/render/png_writer.hpp"
#include "gestura/render/progress.hpp"
#include "gestura/core/staged_file.hpp"
#include "gestura/render/video_writer.hpp"

namespace gestura {
namespace {

bool is_png(const std::string& path) {
  return path.size() >= 4 && (path.compare(path.size() - 4, 4, ".png") == 0 || path.compare(path.size() - 4, 4, ".PNG") == 0);
}

// Cloth colours that tell characters apart, dark enough for hands to show against them.
constexpr float kCloth[][3] = {{0.16f, 0.20f, 0.30f}, {0.38f, 0.14f, 0.14f}, {0.14f, 0.28f, 0.20f},
                               {0.30f, 0.24f, 0.12f}, {0.24f, 0.16f, 0.32f}, {0.12f, 0.26f, 0.30f}};

}  // namespace

void validate(const SceneRenderJob& job, const Scene& scene) {
  RenderJob plain;
  plain.output = job.output;
  plain.size = job.size;
  plain.fps = job.fps;
  plain.sheet = job.sheet;
  plain.msaa_samples = job.msaa_samples;
  validate(plain);
  expand_scene_cameras(job.cameras, scene);
}

Look character_look(const PerformedCharacter& character, std::size_t index) {
  Look look;
  const auto& c = kCloth[index % std::size(kCloth)];
  look.set_color(MaterialId::Cloth, vec3(c[0], c[1], c[2]));
  for (const auto& [name, color] : character.colors) look.set_color(parse_material(name), color);
  return look;
}

SceneAnimator::SceneAnimator(const Scene& scene, const SceneGeometry& geometry, const ScenePerformance& performance)
    : scene_(&scene), geometry_(&geometry), performance_(&performance) {
  for (const PerformedCharacter& c : performance.characters) {
    auto subject = std::make_unique<RenderSubject>();
    subject->skeleton = c.avatar->skeleton;
    subject->mesh = c.avatar->mesh;
    subject->clip = c.clip;
    animators_.push_back(std::make_unique<Animator>(*subject));
    subjects_.push_back(std::move(subject));
    heads_.push_back(c.avatar->skeleton.find("skullbase"));
  }
  frames_.resize(performance.characters.size());
  views_.resize(performance.characters.size());
  for (std::size_t o = 0; o < geometry.object_names.size(); ++o)
    for (std::uint32_t k = geometry.object_first[o]; k < geometry.object_first[o] + geometry.object_count[o]; ++k)
      bounds_.grow(vec3(geometry.object_transforms[o] * vec4(geometry.positions[geometry.indices[k]], 1.0f)));
}

SceneAnimator::~SceneAnimator() = default;

void SceneAnimator::upload(SceneRenderer& renderer) const {
  renderer.set_environment(*geometry_);
  renderer.set_lights(scene_->lights, scene_->background);
  for (std::size_t i = 0; i < performance_->characters.size(); ++i)
    renderer.add_character(subjects_[i]->mesh, character_look(performance_->characters[i], i));
}

void SceneAnimator::pose_at(float t) {
  objects_ = object_transforms_at(*scene_, *performance_, t);
  for (std::size_t i = 0; i < animators_.size(); ++i) {
    Animator& a = *animators_[i];
    a.pose_at(t);
    frames_[i] = CharacterFrame{a.skinning(), a.morph_weights(), true};
    const std::span<const mat4> model = a.model();
    CharacterView& v = views_[i];
    v.name = performance_->characters[i].name;
    const mat4& root = model[0];
    v.position = vec3(root[3].x, 0.0f, root[3].z);
    const vec3 forward = vec3(root[2]);
    v.facing = std::atan2(forward.x, forward.z);
    v.head = heads_[i] >= 0 ? vec3(model[static_cast<std::size_t>(heads_[i])][3]) + vec3(0, 0.08f, 0) : vec3(root[3]) + vec3(0, 0.7f, 0);
    v.position.y = v.head.y - 1.6f;
  }
}

RenderReport render_scene_to_file(const Scene& scene, const SceneGeometry& geometry, const ScenePerformance& performance,
                                  const SceneRenderJob& job) {
  validate(job, scene);
  SceneAnimator animator(scene, geometry, performance);
  const bool png = is_png(job.output);
  std::optional<StagedFile> still;
  std::optional<VideoWriter> video;
  if (png) still.emplace(job.output);
  else video.emplace(job.output, job.size.width, job.size.height, job.fps);

  HeadlessGlContext context;
  SceneRenderer renderer(job.msaa_samples);
  animator.upload(renderer);
  RenderReport report;
  report.renderer = context.description();
  Image frame;
  const float duration = std::max(performance.duration, 0.0f);
  // The characters view glides between its shots in a video (a still or a sheet's tiles show the shot).
  const std::vector<std::string> names = expand_scene_cameras(job.cameras, scene);
  std::vector<CameraGlide> glides(names.size());
  auto draw = [&](float t, int width, int height, float dt = 0.0f) {
    animator.pose_at(t);
    std::vector<View> views = scene_views(job.cameras, scene, animator.bounds(), animator.views(), width, height);
    for (std::size_t i = 0; i < views.size() && i < names.size(); ++i)
      if (names[i] == "characters") {
        // Inside the room as the framing itself is (scene_cameras.cpp: the box less 0.35 m).
        glides[i].keep_inside(animator.bounds().min + vec3(0.35f), animator.bounds().max - vec3(0.35f));
        views[i].camera = glides[i].follow(views[i].camera, dt);
      }
    renderer.render(views, animator.objects(), animator.frames());
    renderer.read_pixels(frame);
  };
  if (png && job.sheet) {
    constexpr int kColumns = 4, kFrames = 16;
    const int w = std::max(kMinImageSide, job.size.width / kColumns), h = std::max(kMinImageSide, job.size.height / kColumns);
    renderer.resize(w, h);
    std::vector<Image> tiles;
    Progress progress("rendering sheet", kFrames);
    for (int i = 0; i < kFrames; ++i) {
      draw(duration * static_cast<float>(i) / static_cast<float>(kFrames - 1), w, h);
      tiles.push_back(frame);
      progress.update(i + 1);
    }
    write_png(*still, contact_sheet(tiles, kColumns));
    report.frames = kFrames;
    return report;
  }
  renderer.resize(job.size.width, job.size.height);
  if (png) {
    draw(std::min(job.still_time, duration), job.size.width, job.size.height);
    write_png(*still, frame);
    report.frames = 1;
    return report;
  }
  const int frames = frame_count(duration, job.fps);
  Progress progress("rendering " + job.output, frames);
  EncoderThread encoder(*video);
  for (int i = 0; i < frames; ++i) {
    draw(static_cast<float>(i) / static_cast<float>(job.fps), job.size.width, job.size.height, i == 0 ? 0.0f : 1.0f / static_cast<float>(job.fps));
    encoder.submit(frame);
    progress.update(i + 1);
  }
  encoder.finish();
  report.frames = frames;
  return report;
}

}  // namespace gestura
