#include "gestura/render/scene_renderer.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "gestura/body/morph.hpp"
#include "gestura/body/skinning.hpp"
#include "gestura/core/error.hpp"
#include "gestura/render/gl_program.hpp"

namespace gestura {
namespace {

constexpr int kShadowSize = 2048;
constexpr int kMaxDirectional = 4, kMaxPoint = 4;

constexpr const char* kVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_albedo;    // linear
layout(location = 3) in vec4 a_surface;   // wrap, scatter, specular, shininess
uniform mat4 u_model;
uniform mat4 u_view_projection;
out vec3 v_world;
out vec3 v_normal;
out vec3 v_albedo;
out vec4 v_surface;
void main() {
  vec4 w = u_model * vec4(a_position, 1.0);
  v_world = w.xyz;
  v_normal = mat3(u_model) * a_normal;
  v_albedo = a_albedo;
  v_surface = a_surface;
  gl_Position = u_view_projection * w;
}
)";

// Wrap-lit diffuse with a scatter tint for skin (as the avatar renderer), Blinn-Phong highlights,
// directional lights (the first may cast a shadow from a 2048² map, sampled with a 3×3 kernel of
// hardware-compared taps), point lights with inverse-square falloff, and hemisphere ambient light.
constexpr const char* kFragment = R"(#version 330 core
in vec3 v_world;
in vec3 v_normal;
in vec3 v_albedo;
in vec4 v_surface;
uniform vec3 u_eye;
uniform vec3 u_view_direction;
uniform bool u_orthographic;
uniform int u_directional_count;
uniform vec3 u_directional_dir[4];     // toward the light
uniform vec3 u_directional_color[4];   // colour × intensity, linear
uniform int u_point_count;
uniform vec3 u_point_position[4];
uniform vec3 u_point_color[4];
uniform vec3 u_ambient;                // linear, summed
uniform int u_shadow_light;            // index of the shadow-casting directional light, -1 = none
uniform mat4 u_light_view_projection;
uniform sampler2DShadow u_shadow_map;
uniform float u_shadow_texel;
out vec4 o_color;

const vec3 kScatterTint = vec3(0.85, 0.22, 0.12);

float shadow_factor(vec3 n, vec3 l) {
  vec3 p = v_world + n * 0.015 + l * 0.01;   // normal offset against acne
  vec4 c = u_light_view_projection * vec4(p, 1.0);
  vec3 s = c.xyz / c.w * 0.5 + 0.5;
  if (s.x < 0.0 || s.x > 1.0 || s.y < 0.0 || s.y > 1.0 || s.z > 1.0) return 1.0;
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) lit += texture(u_shadow_map, vec3(s.xy + vec2(x, y) * u_shadow_texel, s.z - 0.0015));
  return lit / 9.0;
}

vec3 shade(vec3 n, vec3 v, vec3 l, vec3 color, vec3 albedo, vec4 s) {
  float ndl = dot(n, l);
  float wrapped = max((ndl + s.x) / (1.0 + s.x), 0.0);
  float scatter = s.y * smoothstep(-s.x - 0.1, 0.0, ndl) * (1.0 - smoothstep(0.0, 0.6, ndl));
  vec3 c = color * albedo * (wrapped + kScatterTint * scatter);
  if (s.z > 0.0 && ndl > 0.0) c += color * s.z * pow(max(dot(n, normalize(l + v)), 0.0), s.w);
  return c;
}

void main() {
  vec3 n = normalize(v_normal);
  vec3 v = u_orthographic ? -u_view_direction : normalize(u_eye - v_world);
  if (!gl_FrontFacing) n = -n;   // thin planes and open meshes are lit from the side seen
  vec3 c = v_albedo * u_ambient * mix(0.55, 1.0, n.y * 0.5 + 0.5);
  for (int i = 0; i < u_directional_count; ++i) {
    vec3 l = u_directional_dir[i];
    vec3 contribution = shade(n, v, l, u_directional_color[i], v_albedo, v_surface);
    if (i == u_shadow_light) contribution *= mix(0.25, 1.0, shadow_factor(n, l));
    c += contribution;
  }
  for (int i = 0; i < u_point_count; ++i) {
    vec3 d = u_point_position[i] - v_world;
    float r2 = max(dot(d, d), 0.01);
    c += shade(n, v, d / sqrt(r2), u_point_color[i] / r2, v_albedo, v_surface);
  }
  c = c / (1.0 + 0.12 * c);
  o_color = vec4(pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)), 1.0);
}
)";

constexpr const char* kDepthVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
uniform mat4 u_view_projection;
void main() { gl_Position = u_view_projection * u_model * vec4(a_position, 1.0); }
)";

constexpr const char* kDepthFragment = R"(#version 330 core
void main() {}
)";

GLuint link(const char* vs_source, const char* fs_source) {
  return gl::link_program("scene renderer", vs_source, fs_source);
}

void check_gl(const char* what) { gl::check("scene renderer", what); }

vec3 linear(const vec3& srgb) { return glm::pow(glm::clamp(srgb, vec3(0.0f), vec3(1.0f)), vec3(2.2f)); }

void attribute(GLuint index, GLuint buffer, GLint size) {
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glEnableVertexAttribArray(index);
  glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, 0, nullptr);
}

}  // namespace

struct SceneRenderer::Gl {
  GLuint program = 0, depth_program = 0;
  GLint u_model = -1, u_view_projection = -1, u_eye = -1, u_view_direction = -1, u_orthographic = -1,
        u_directional_count = -1, u_directional_dir = -1, u_directional_color = -1, u_point_count = -1,
        u_point_position = -1, u_point_color = -1, u_ambient = -1, u_shadow_light = -1, u_light_view_projection = -1,
        u_shadow_map = -1, u_shadow_texel = -1;
  GLint d_model = -1, d_view_projection = -1;
  GLuint env_vao = 0, env_buffers[5] = {};
  GLsizei env_indices = 0;
  GLuint msaa_fbo = 0, msaa_color = 0, msaa_depth = 0, resolve_fbo = 0, resolve_color = 0;
  GLuint shadow_fbo = 0, shadow_texture = 0;
};

struct SceneRenderer::Character {
  Mesh mesh;
  GLuint vao = 0, buffers[5] = {};  // positions, normals (streamed), albedo, surface, indices
  std::vector<vec3> morphed_positions, morphed_normals, skinned_positions, skinned_normals;
  std::vector<float> morph_scratch;
  bool visible = true;
  ~Character() {
    glDeleteBuffers(5, buffers);
    glDeleteVertexArrays(1, &vao);
  }
};

SceneRenderer::SceneRenderer(int msaa_samples) : gl_(std::make_unique<Gl>()) {
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  samples_ = std::clamp(msaa_samples, 1, std::max(1, static_cast<int>(max_samples)));
  Gl& g = *gl_;
  g.program = link(kVertex, kFragment);
  g.depth_program = link(kDepthVertex, kDepthFragment);
  auto loc = [&](const char* name) { return glGetUniformLocation(g.program, name); };
  g.u_model = loc("u_model");
  g.u_view_projection = loc("u_view_projection");
  g.u_eye = loc("u_eye");
  g.u_view_direction = loc("u_view_direction");
  g.u_orthographic = loc("u_orthographic");
  g.u_directional_count = loc("u_directional_count");
  g.u_directional_dir = loc("u_directional_dir");
  g.u_directional_color = loc("u_directional_color");
  g.u_point_count = loc("u_point_count");
  g.u_point_position = loc("u_point_position");
  g.u_point_color = loc("u_point_color");
  g.u_ambient = loc("u_ambient");
  g.u_shadow_light = loc("u_shadow_light");
  g.u_light_view_projection = loc("u_light_view_projection");
  g.u_shadow_map = loc("u_shadow_map");
  g.u_shadow_texel = loc("u_shadow_texel");
  g.d_model = glGetUniformLocation(g.depth_program, "u_model");
  g.d_view_projection = glGetUniformLocation(g.depth_program, "u_view_projection");

  glGenVertexArrays(1, &g.env_vao);
  glGenBuffers(5, g.env_buffers);
  // The shadow map: a depth texture compared in the sampler.
  glGenFramebuffers(1, &g.shadow_fbo);
  glGenTextures(1, &g.shadow_texture);
  glBindTexture(GL_TEXTURE_2D, g.shadow_texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, kShadowSize, kShadowSize, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glBindFramebuffer(GL_FRAMEBUFFER, g.shadow_fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, g.shadow_texture, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) throw Error("scene renderer: the shadow map is incomplete");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glEnable(GL_DEPTH_TEST);
  lights_ = default_lights();
  check_gl("setting up the scene renderer");
}

SceneRenderer::~SceneRenderer() {
  characters_.clear();
  Gl& g = *gl_;
  glDeleteBuffers(5, g.env_buffers);
  glDeleteVertexArrays(1, &g.env_vao);
  const GLuint textures[] = {g.resolve_color, g.shadow_texture};
  glDeleteTextures(2, textures);
  const GLuint renderbuffers[] = {g.msaa_color, g.msaa_depth};
  glDeleteRenderbuffers(2, renderbuffers);
  const GLuint framebuffers[] = {g.msaa_fbo, g.resolve_fbo, g.shadow_fbo};
  glDeleteFramebuffers(3, framebuffers);
  glDeleteProgram(g.program);
  glDeleteProgram(g.depth_program);
}

void SceneRenderer::set_environment(const SceneGeometry& geometry) {
  Gl& g = *gl_;
  const std::size_t n = geometry.positions.size();
  std::vector<vec3> albedo(n);
  std::vector<vec4> surface(n);
  for (std::size_t i = 0; i < n; ++i) {
    albedo[i] = linear(geometry.colors[i]);
    const float spec = geometry.specular[i];
    surface[i] = vec4(0.1f, 0.0f, spec, 8.0f + 56.0f * spec);
  }
  auto fill = [](GLenum target, GLuint buffer, std::size_t bytes, const void* data) {
    glBindBuffer(target, buffer);
    glBufferData(target, static_cast<GLsizeiptr>(bytes), data, GL_STATIC_DRAW);
  };
  glBindVertexArray(g.env_vao);
  fill(GL_ARRAY_BUFFER, g.env_buffers[0], n * sizeof(vec3), geometry.positions.data());
  attribute(0, g.env_buffers[0], 3);
  fill(GL_ARRAY_BUFFER, g.env_buffers[1], n * sizeof(vec3), geometry.normals.data());
  attribute(1, g.env_buffers[1], 3);
  fill(GL_ARRAY_BUFFER, g.env_buffers[2], n * sizeof(vec3), albedo.data());
  attribute(2, g.env_buffers[2], 3);
  fill(GL_ARRAY_BUFFER, g.env_buffers[3], n * sizeof(vec4), surface.data());
  attribute(3, g.env_buffers[3], 4);
  fill(GL_ELEMENT_ARRAY_BUFFER, g.env_buffers[4], geometry.indices.size() * sizeof(std::uint32_t), geometry.indices.data());
  glBindVertexArray(0);
  g.env_indices = static_cast<GLsizei>(geometry.indices.size());
  object_transforms_ = geometry.object_transforms;
  object_first_ = geometry.object_first;
  object_count_ = geometry.object_count;
  bounds_ = Aabb{};
  for (std::size_t o = 0; o < geometry.object_names.size(); ++o)
    for (std::uint32_t k = geometry.object_first[o]; k < geometry.object_first[o] + geometry.object_count[o]; ++k)
      bounds_.grow(vec3(geometry.object_transforms[o] * vec4(geometry.positions[geometry.indices[k]], 1.0f)));
  check_gl("uploading the environment");
}

void SceneRenderer::set_lights(std::span<const SceneLight> lights, const vec3& background) {
  lights_.assign(lights.begin(), lights.end());
  if (lights_.empty()) lights_ = default_lights();
  background_ = background;
}

int SceneRenderer::add_character(const Mesh& mesh, const Look& look) {
  const std::size_t n = mesh.vertex_count();
  if (n == 0 || mesh.normals.size() != n || mesh.materials.size() != n || mesh.joints.size() != n || mesh.weights.size() != n)
    throw Error("scene renderer: a character mesh whose arrays differ in length");
  auto c = std::make_unique<Character>();
  c->mesh = mesh;
  std::vector<vec3> albedo(n);
  std::vector<vec4> surface(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t m = std::min<std::size_t>(mesh.materials[i], kMaterialCount - 1);
    albedo[i] = linear(look.colors[m]);
    const SurfaceResponse& s = look.surfaces[m];
    surface[i] = vec4(s.wrap, s.scatter, shown_specular(static_cast<MaterialId>(m), s, look.colors[m]), s.shininess);
  }
  glGenVertexArrays(1, &c->vao);
  glGenBuffers(5, c->buffers);
  glBindVertexArray(c->vao);
  glBindBuffer(GL_ARRAY_BUFFER, c->buffers[0]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(n * sizeof(vec3)), mesh.positions.data(), GL_STREAM_DRAW);
  attribute(0, c->buffers[0], 3);
  glBindBuffer(GL_ARRAY_BUFFER, c->buffers[1]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(n * sizeof(vec3)), mesh.normals.data(), GL_STREAM_DRAW);
  attribute(1, c->buffers[1], 3);
  glBindBuffer(GL_ARRAY_BUFFER, c->buffers[2]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(n * sizeof(vec3)), albedo.data(), GL_STATIC_DRAW);
  attribute(2, c->buffers[2], 3);
  glBindBuffer(GL_ARRAY_BUFFER, c->buffers[3]);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(n * sizeof(vec4)), surface.data(), GL_STATIC_DRAW);
  attribute(3, c->buffers[3], 4);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, c->buffers[4]);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  c->morphed_positions.resize(n);
  c->morphed_normals.resize(n);
  c->skinned_positions.resize(n);
  c->skinned_normals.resize(n);
  characters_.push_back(std::move(c));
  check_gl("uploading a character");
  return static_cast<int>(characters_.size()) - 1;
}

void SceneRenderer::resize(int width, int height) {
  if (width == width_ && height == height_) return;
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  if (width <= 0 || height <= 0 || width > max_size || height > max_size)
    throw Error("scene renderer: cannot render " + std::to_string(width) + "x" + std::to_string(height));
  Gl& g = *gl_;
  if (g.msaa_fbo == 0) {
    glGenFramebuffers(1, &g.msaa_fbo);
    glGenFramebuffers(1, &g.resolve_fbo);
    glGenRenderbuffers(1, &g.msaa_color);
    glGenRenderbuffers(1, &g.msaa_depth);
    glGenTextures(1, &g.resolve_color);
  }
  glBindRenderbuffer(GL_RENDERBUFFER, g.msaa_color);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, g.msaa_depth);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, width, height);
  glBindFramebuffer(GL_FRAMEBUFFER, g.msaa_fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, g.msaa_color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, g.msaa_depth);
  const GLenum msaa_status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindTexture(GL_TEXTURE_2D, g.resolve_color);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, g.resolve_fbo);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, g.resolve_color, 0);
  const GLenum resolve_status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("allocating the render target");
  if (msaa_status != GL_FRAMEBUFFER_COMPLETE || resolve_status != GL_FRAMEBUFFER_COMPLETE)
    throw Error("scene renderer: the render target is incomplete");
  width_ = width, height_ = height;
}

void SceneRenderer::draw_geometry(bool depth_only, std::span<const mat4> object_transforms) {
  Gl& g = *gl_;
  const GLint model = depth_only ? g.d_model : g.u_model;
  if (g.env_indices > 0) {
    glBindVertexArray(g.env_vao);
    for (std::size_t o = 0; o < object_first_.size(); ++o) {
      if (object_count_[o] == 0) continue;
      const mat4& m = o < object_transforms.size() ? object_transforms[o] : object_transforms_[o];
      glUniformMatrix4fv(model, 1, GL_FALSE, &m[0][0]);
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(object_count_[o]), GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(static_cast<std::uintptr_t>(object_first_[o]) * sizeof(std::uint32_t)));
    }
  }
  const mat4 identity(1.0f);
  glUniformMatrix4fv(model, 1, GL_FALSE, &identity[0][0]);
  for (const auto& c : characters_) {
    if (!c->visible) continue;
    glBindVertexArray(c->vao);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(c->mesh.indices.size()), GL_UNSIGNED_INT, nullptr);
  }
  glBindVertexArray(0);
}

void SceneRenderer::render(std::span<const View> views, std::span<const mat4> object_transforms,
                           std::span<const CharacterFrame> characters) {
  if (width_ == 0) throw Error("scene renderer: resize() before render()");
  if (characters.size() != characters_.size())
    throw Error("scene renderer: " + std::to_string(characters.size()) + " character frames for " +
                std::to_string(characters_.size()) + " characters");
  if (!object_transforms.empty() && object_transforms.size() != object_first_.size())
    throw Error("scene renderer: " + std::to_string(object_transforms.size()) + " object transforms for " +
                std::to_string(object_first_.size()) + " objects");
  Gl& g = *gl_;

  // Skin every character into world space and stream it.
  Aabb bounds = bounds_;
  for (std::size_t i = 0; i < characters_.size(); ++i) {
    Character& c = *characters_[i];
    const CharacterFrame& f = characters[i];
    c.visible = f.visible;
    if (!f.visible) continue;
    if (f.skinning.size() < 1) throw Error("scene renderer: a character frame without skinning matrices");
    std::span<const vec3> rest_p = c.mesh.positions, rest_n = c.mesh.normals;
    const bool morphs = std::any_of(f.morph_weights.begin(), f.morph_weights.end(), [](float w) { return w != 0.0f; });
    if (morphs) {
      c.morph_scratch.assign(c.mesh.morphs.size(), 0.0f);
      std::copy_n(f.morph_weights.begin(), std::min(f.morph_weights.size(), c.morph_scratch.size()), c.morph_scratch.begin());
      apply_morphs(c.mesh.positions, c.mesh.morphs, c.morph_scratch, c.morphed_positions);
      apply_morph_normals(c.mesh.normals, c.mesh.morphs, c.morph_scratch, c.morphed_normals);
      rest_p = c.morphed_positions, rest_n = c.morphed_normals;
    }
    skin_positions_normals(f.skinning, c.mesh.joints, c.mesh.weights, rest_p, rest_n, c.skinned_positions, c.skinned_normals);
    const auto bytes = static_cast<GLsizeiptr>(c.skinned_positions.size() * sizeof(vec3));
    glBindBuffer(GL_ARRAY_BUFFER, c.buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, bytes, c.skinned_positions.data(), GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, c.buffers[1]);
    glBufferData(GL_ARRAY_BUFFER, bytes, c.skinned_normals.data(), GL_STREAM_DRAW);
    // A character's bounds from its pelvis-ish joints is enough for the shadow volume.
    bounds.grow(vec3(f.skinning[0][3]) + vec3(1.2f));
    bounds.grow(vec3(f.skinning[0][3]) - vec3(1.2f));
  }

  // Lights: directional and point lists, ambient summed, the shadow caster chosen.
  vec3 dir[kMaxDirectional], dir_color[kMaxDirectional], point_pos[kMaxPoint], point_color[kMaxPoint], ambient(0.0f);
  int ndir = 0, npoint = 0, shadow = -1;
  for (const SceneLight& l : lights_) {
    const vec3 c = linear(l.color) * l.intensity;
    if (l.kind == LightKind::Ambient) ambient += c;
    else if (l.kind == LightKind::Directional && ndir < kMaxDirectional) {
      if (l.shadows && shadow < 0) shadow = ndir;
      dir[ndir] = -glm::normalize(l.direction), dir_color[ndir++] = c;
    } else if (l.kind == LightKind::Point && npoint < kMaxPoint) {
      point_pos[npoint] = l.position, point_color[npoint++] = c * 4.0f;  // intensity 1 ≈ daylight at 2 m
    }
  }

  mat4 light_vp(1.0f);
  if (shadow >= 0 && !bounds.empty()) {
    const vec3 centre = bounds.centre();
    const float radius = glm::length(bounds.max - bounds.min) * 0.5f + 0.5f;
    const vec3 l = dir[shadow];
    const vec3 up = std::abs(l.y) > 0.95f ? vec3(0, 0, 1) : vec3(0, 1, 0);
    const mat4 view = glm::lookAt(centre + l * radius * 2.0f, centre, up);
    const mat4 proj = glm::ortho(-radius, radius, -radius, radius, 0.1f, radius * 4.0f);
    light_vp = proj * view;
    glBindFramebuffer(GL_FRAMEBUFFER, g.shadow_fbo);
    glViewport(0, 0, kShadowSize, kShadowSize);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUseProgram(g.depth_program);
    glUniformMatrix4fv(g.d_view_projection, 1, GL_FALSE, &light_vp[0][0]);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 2.0f);
    glDisable(GL_CULL_FACE);
    draw_geometry(true, object_transforms);
    glDisable(GL_POLYGON_OFFSET_FILL);
  }

  glBindFramebuffer(GL_FRAMEBUFFER, g.msaa_fbo);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(background_.x, background_.y, background_.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glUseProgram(g.program);
  glUniform1i(g.u_directional_count, ndir);
  if (ndir) glUniform3fv(g.u_directional_dir, ndir, &dir[0].x), glUniform3fv(g.u_directional_color, ndir, &dir_color[0].x);
  glUniform1i(g.u_point_count, npoint);
  if (npoint) glUniform3fv(g.u_point_position, npoint, &point_pos[0].x), glUniform3fv(g.u_point_color, npoint, &point_color[0].x);
  glUniform3fv(g.u_ambient, 1, &ambient.x);
  glUniform1i(g.u_shadow_light, shadow);
  glUniformMatrix4fv(g.u_light_view_projection, 1, GL_FALSE, &light_vp[0][0]);
  glUniform1f(g.u_shadow_texel, 1.0f / static_cast<float>(kShadowSize));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, g.shadow_texture);
  glUniform1i(g.u_shadow_map, 0);
  glDisable(GL_CULL_FACE);  // planes and imported meshes may be single-sided
  for (const View& view : views) {
    const Viewport& vp = view.viewport;
    glViewport(vp.x, height_ - vp.y - vp.height, vp.width, vp.height);
    const mat4 view_projection = view.camera.projection * view.camera.view;
    glUniformMatrix4fv(g.u_view_projection, 1, GL_FALSE, &view_projection[0][0]);
    glUniform3fv(g.u_eye, 1, &view.camera.eye.x);
    const vec3 direction = glm::normalize(view.camera.target - view.camera.eye);
    glUniform3fv(g.u_view_direction, 1, &direction.x);
    glUniform1i(g.u_orthographic, view.camera.orthographic ? 1 : 0);
    draw_geometry(false, object_transforms);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, g.msaa_fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g.resolve_fbo);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("drawing the scene");
}

void SceneRenderer::read_pixels(Image& out) {
  if (out.width != width_ || out.height != height_) out = Image(width_, height_);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, gl_->resolve_fbo);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, out.rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  check_gl("reading pixels back");
  const std::size_t row = static_cast<std::size_t>(width_) * 4;
  std::vector<std::uint8_t> tmp(row);
  for (int y = 0; y < height_ / 2; ++y) {
    std::memcpy(tmp.data(), out.pixel(0, y), row);
    std::memcpy(out.pixel(0, y), out.pixel(0, height_ - 1 - y), row);
    std::memcpy(out.pixel(0, height_ - 1 - y), tmp.data(), row);
  }
}

void SceneRenderer::read_window_pixels(Image& out, int framebuffer_width, int framebuffer_height) {
  if (out.width != framebuffer_width || out.height != framebuffer_height) out = Image(framebuffer_width, framebuffer_height);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, framebuffer_width, framebuffer_height, GL_RGBA, GL_UNSIGNED_BYTE, out.rgba.data());
  const std::size_t row = static_cast<std::size_t>(framebuffer_width) * 4;
  std::vector<std::uint8_t> tmp(row);
  for (int y = 0; y < framebuffer_height / 2; ++y) {
    std::memcpy(tmp.data(), out.pixel(0, y), row);
    std::memcpy(out.pixel(0, y), out.pixel(0, framebuffer_height - 1 - y), row);
    std::memcpy(out.pixel(0, framebuffer_height - 1 - y), tmp.data(), row);
  }
  check_gl("reading the window back");
}

unsigned SceneRenderer::resolved_texture() const { return gl_->resolve_color; }

void SceneRenderer::present(int framebuffer_width, int framebuffer_height) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, gl_->resolve_fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glClearColor(background_.x, background_.y, background_.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, framebuffer_width, framebuffer_height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace gestura
