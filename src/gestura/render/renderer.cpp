#include "gestura/render/renderer.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>

#include "gestura/core/error.hpp"
#include "gestura/body/morph.hpp"
#include "gestura/body/skinning.hpp"
#include "gestura/render/edge_filter.hpp"
#include "gestura/render/gl_program.hpp"

namespace gestura {
namespace {

// Texture units of the three texture buffers the vertex shader reads.
constexpr GLint kMorphDeltaUnit = 1, kMorphWeightUnit = 2;
constexpr GLuint kJointBlockBinding = 0;

// Compiled with "#define MAX_JOINTS n" (n from the GL's uniform block size), "#define MATERIALS m"
// (kMaterialCount) and "#define MAX_OCCLUDERS k" (kMaxOccluders) prepended.
constexpr const char* kVertexShader = R"(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in uint a_material;
layout(location = 3) in uvec4 a_joints;
layout(location = 4) in vec4 a_weights;
layout(location = 5) in uvec2 a_morph_range;   // first entry, entry count
layout(location = 6) in uint a_part;           // BodyPart (render/occluders.hpp)

layout(std140) uniform Joints { mat4 u_joints[MAX_JOINTS]; };  // skinning matrices
uniform samplerBuffer u_morph_deltas;  // 2 texels per entry: (position delta, morph index), (normal delta, 0)
uniform samplerBuffer u_morph_weights; // one weight per morph target
uniform bool u_skin_on_gpu;
uniform bool u_morphs_active;
uniform mat4 u_view_projection;
uniform vec3 u_albedo[MATERIALS];    // per MaterialId, linear
uniform vec4 u_surface[MATERIALS];   // per MaterialId: wrap, scatter, specular, shininess

out vec3 v_world;
out vec3 v_normal;
out vec3 v_albedo;   // interpolated, so material borders blend instead of stair-stepping
out vec4 v_surface;
out vec2 v_occlusion;

uniform int u_occluder_count;
uniform vec4 u_occluder_a[MAX_OCCLUDERS];  // axis start, radius
uniform vec4 u_occluder_b[MAX_OCCLUDERS];  // axis end, body part
const vec3 kKey = vec3(-0.4511, 0.5514, 0.7018);

// Key-light visibility (1 lit, 0 in shadow) and ambient occlusion (0 open .. 1 covered) from the
// capsules of the other body parts. Shadow: where the ray towards the key passes the capsule's axis
// closer than its radius, with a penumbra that widens with the distance travelled. Occlusion: the
// cosine-weighted solid angle of the sphere at the axis point nearest the surface. Per vertex: the
// mesh is fine enough for shading this soft, and per pixel it cost more than the rest of the shader.
void occlusion(vec3 p, vec3 n, uint part, out float lit, out float covered) {
  lit = 1.0;
  covered = 0.0;
  for (int i = 0; i < u_occluder_count; ++i) {
    if (uint(u_occluder_b[i].w) == part) continue;
    vec3 a = u_occluder_a[i].xyz, b = u_occluder_b[i].xyz;
    float r = u_occluder_a[i].w;
    vec3 ab = b - a, pa = a - p;
    float h = clamp(dot(-pa, ab) / max(dot(ab, ab), 1e-8), 0.0, 1.0);
    vec3 to = pa + h * ab;
    float d2 = dot(to, to);
    if (d2 < r * r) continue;  // inside the capsule: it stands for this surface badly here
    float d = sqrt(d2);
    covered += min(0.6, max(dot(n, to / d), 0.0) * r * r / d2);
    vec3 qa = pa - dot(pa, kKey) * kKey, qd = ab - dot(ab, kKey) * kKey;
    float s = clamp(-dot(qa, qd) / max(dot(qd, qd), 1e-8), 0.0, 1.0);
    float t = dot(pa + s * ab, kKey);
    if (t > 0.0) {
      float w = 0.005 + 0.07 * t;
      lit = min(lit, smoothstep(r - w, r + w, length(qa + s * qd)));
    }
  }
  covered = min(covered, 0.75);
}

mat4 joint_matrix(uint j) { return u_joints[j]; }

void main() {
  vec3 p = a_position;
  vec3 n = a_normal;
  if (u_skin_on_gpu) {
    if (u_morphs_active) {
      for (uint e = a_morph_range.x; e < a_morph_range.x + a_morph_range.y; ++e) {
        vec4 d = texelFetch(u_morph_deltas, int(e) * 2);
        float w = texelFetch(u_morph_weights, int(d.w)).r;
        p += w * d.xyz;
        n += w * texelFetch(u_morph_deltas, int(e) * 2 + 1).xyz;
      }
    }
    mat4 m = a_weights.x * joint_matrix(a_joints.x) + a_weights.y * joint_matrix(a_joints.y) +
             a_weights.z * joint_matrix(a_joints.z) + a_weights.w * joint_matrix(a_joints.w);
    p = (m * vec4(p, 1.0)).xyz;
    n = mat3(m) * n;
  }
  v_world = p;
  v_normal = n;
  uint material = min(a_material, uint(MATERIALS - 1));
  v_albedo = u_albedo[material];
  v_surface = u_surface[material];
  float lit = 1.0, covered = 0.0;
  if (u_occluder_count > 0) occlusion(p, normalize(n), a_part, lit, covered);
  v_occlusion = vec2(lit, covered);
  gl_Position = u_view_projection * vec4(p, 1.0);
}
)";

// Skin-like shading: wrap lighting with a reddish scatter band at the terminator (a cheap
// subsurface look), three soft lights fixed to the avatar (warm key front-right, cool fill
// front-left, rim from behind), a hemisphere ambient and a Fresnel edge that lifts silhouettes —
// strongest on dark materials, so a sleeve reads against a shirt of the same cloth.
// Depth: capsules standing for the arms and hands (render/occluders.hpp; evaluated per vertex) cast
// soft shadows from the key light and occlude ambient light on every other part, so a hand in front of the chest
// darkens the chest beside it and the nearer hand darkens the farther one; and surfaces farther from
// the camera than the framed body plane are a little darker (nearer ones are not brightened: hands
// brightened that way lost the shading a hand detector reads them by).
constexpr const char* kFragmentShader = R"(
in vec3 v_world;
in vec3 v_normal;
in vec3 v_albedo;
in vec4 v_surface;
in vec2 v_occlusion;   // key-light visibility, ambient occlusion (vertex shader)

uniform vec3 u_eye;
uniform vec3 u_view_direction;
uniform bool u_orthographic;
uniform float u_focus_distance;       // along the view direction: the framed body plane

out vec4 o_color;

const vec3 kScatterTint = vec3(0.85, 0.22, 0.12);
const vec3 kKey = vec3(-0.4511, 0.5514, 0.7018);  // the key light's direction (the vertex shader's too)

// The scatter band is skipped where no material scatters (cloth, most of the frame): llvmpipe
// shades pixels in groups and skips a branch only when the whole group skips it.
vec3 diffuse(vec3 n, vec3 l, vec3 color, vec3 albedo, vec4 s) {
  float ndl = dot(n, l);
  vec3 response = vec3(max((ndl + s.x) / (1.0 + s.x), 0.0));
  if (s.y > 0.0)
    response += kScatterTint * (s.y * smoothstep(-s.x - 0.1, 0.0, ndl) * (1.0 - smoothstep(0.0, 0.6, ndl)));
  return color * albedo * response;
}

// x^n for the highlights as exp2(n·log2 x) with log2 x from its series about 1 (-(d + d²/2)/ln 2,
// d = 1 - x): exact at the peak, within 0.006 of pow() at n = 8 and 0.001 from n = 20 (the looks use
// 8..300, and weight the result by at most 1.5); llvmpipe's pow() pays a log2 and an exp2 per call, this one exp2.
float highlight(float x, float n) {
  float d = 1.0 - x;
  return exp2(-1.442695 * n * d * (1.0 + 0.5 * d));
}

// Blinn-Phong; only the key and rim lights get highlights (the fill is soft by design).
float specular(vec3 n, vec3 v, vec3 l, vec4 s) {
  return dot(n, l) > 0.0 ? s.z * highlight(max(dot(n, normalize(l + v)), 0.0), s.w) : 0.0;
}

// x^(1/2.2) on 0..1 from two square roots (least-squares fit, within 0.24 of an 8-bit level of
// pow()): llvmpipe's pow() costs a log2 and an exp2 per channel, a square root is one instruction.
vec3 encode_gamma(vec3 x) {
  vec3 r = sqrt(x), q = sqrt(r);
  return 1.0803608 * r - 0.2181301 * x + 0.0519204 * q + 0.0867510 * x * r;
}

void main() {
  vec3 n = normalize(v_normal);
  vec3 v = u_orthographic ? -u_view_direction : normalize(u_eye - v_world);
  if (dot(n, v) < 0.0 && !gl_FrontFacing) n = -n;
  vec3 albedo = v_albedo;
  vec4 s = v_surface;
  float lit = v_occlusion.x, covered = v_occlusion.y;

  const vec3 fill = vec3(0.7814, 0.1116, 0.6140), rim = vec3(0.2516, 0.4528, -0.8554);
  const vec3 key_color = vec3(1.25, 1.18, 1.08), fill_color = vec3(0.32, 0.36, 0.44), rim_color = vec3(0.70, 0.70, 0.75);
  float open = 1.0 - covered;
  float key_light = mix(1.0, lit, 0.65) * (1.0 - 0.5 * covered);
  vec3 c = open * albedo * mix(vec3(0.10, 0.09, 0.09), vec3(0.20, 0.22, 0.26), n.y * 0.5 + 0.5);
  c += key_light * diffuse(n, kKey, key_color, albedo, s) + open * diffuse(n, fill, fill_color, albedo, s) +
       diffuse(n, rim, rim_color, albedo, s);
  if (s.z > 0.0) c += lit * key_color * specular(n, v, kKey, s) + rim_color * specular(n, v, rim, s);
  float facing = 1.0 - max(dot(n, v), 0.0);
  float luminance = dot(albedo, vec3(0.2126, 0.7152, 0.0722));
  float edge = mix(0.55, 0.25, smoothstep(0.02, 0.25, luminance));
  c += facing * facing * facing * edge * mix(albedo, vec3(0.75, 0.80, 0.88), 0.45);
  float depth = dot(v_world - u_eye, u_view_direction);
  c *= clamp(1.0 + 0.3 * (u_focus_distance - depth), 0.85, 1.0);
  c = c / (1.0 + 0.12 * c);   // soft shoulder instead of hard clipping
  o_color = vec4(clamp(encode_gamma(clamp(c, 0.0, 1.0)), 0.0, 1.0), 1.0);
}
)";

void check_gl(const char* what) { gl::check("renderer", what); }

}  // namespace

Antialiasing antialiasing_for_samples(int samples) {
  return samples >= 4 ? Antialiasing::Msaa4 : samples >= 2 ? Antialiasing::Msaa2 : Antialiasing::None;
}

struct Renderer::Gl {
  GLuint program = 0;
  GLint u_view_projection = -1, u_skin_on_gpu = -1, u_morphs_active = -1, u_eye = -1, u_view_direction = -1,
        u_orthographic = -1, u_albedo = -1, u_surface = -1, u_focus_distance = -1, u_occluder_count = -1,
        u_occluder_a = -1, u_occluder_b = -1;
  GLuint gpu_vao = 0, cpu_vao = 0;
  GLuint positions = 0, normals = 0, materials = 0, joints = 0, weights = 0, morph_ranges = 0, indices = 0, parts = 0;
  GLuint skinned_positions = 0, skinned_normals = 0;
  GLuint joint_buffer = 0, delta_buffer = 0, delta_texture = 0, weight_buffer = 0,
         weight_texture = 0;
  GLuint msaa_fbo = 0, msaa_color = 0, msaa_depth = 0, resolve_fbo = 0, resolve_color = 0;
  GLsizei index_count = 0;
};

Renderer::Renderer(const Look& look, Antialiasing antialiasing) : gl_(std::make_unique<Gl>()), look_(look) {
  GLint max_samples = 1;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  const int asked = antialiasing == Antialiasing::Msaa4 ? 4 : antialiasing == Antialiasing::Msaa2 ? 2 : 1;
  samples_ = std::clamp(asked, 1, std::max(1, static_cast<int>(max_samples)));
  edge_filter_ = antialiasing == Antialiasing::EdgeFilter;

  GLint block_bytes = 0;
  glGetIntegerv(GL_MAX_UNIFORM_BLOCK_SIZE, &block_bytes);
  max_gpu_joints_ = std::min<std::size_t>(1024, static_cast<std::size_t>(block_bytes) / sizeof(mat4));
  Gl& g = *gl_;
  g.program = gl::link_program("renderer",
                               "#version 330 core\n#define MAX_JOINTS " + std::to_string(max_gpu_joints_) +
                                   "\n#define MATERIALS " + std::to_string(kMaterialCount) +
                                   "\n#define MAX_OCCLUDERS " + std::to_string(kMaxOccluders) + kVertexShader,
                               std::string("#version 330 core\n") + kFragmentShader);
  auto loc = [&](const char* name) { return glGetUniformLocation(g.program, name); };
  g.u_view_projection = loc("u_view_projection");
  g.u_skin_on_gpu = loc("u_skin_on_gpu");
  g.u_morphs_active = loc("u_morphs_active");
  g.u_eye = loc("u_eye");
  g.u_view_direction = loc("u_view_direction");
  g.u_orthographic = loc("u_orthographic");
  g.u_albedo = loc("u_albedo");
  g.u_surface = loc("u_surface");
  g.u_focus_distance = loc("u_focus_distance");
  g.u_occluder_count = loc("u_occluder_count");
  g.u_occluder_a = loc("u_occluder_a");
  g.u_occluder_b = loc("u_occluder_b");
  glUseProgram(g.program);
  glUniformBlockBinding(g.program, glGetUniformBlockIndex(g.program, "Joints"), kJointBlockBinding);
  glUniform1i(loc("u_morph_deltas"), kMorphDeltaUnit);
  glUniform1i(loc("u_morph_weights"), kMorphWeightUnit);


  GLuint buffers[11];
  glGenBuffers(11, buffers);
  g.positions = buffers[0], g.normals = buffers[1], g.materials = buffers[2], g.joints = buffers[3];
  g.weights = buffers[4], g.morph_ranges = buffers[5], g.indices = buffers[6], g.skinned_positions = buffers[7];
  g.skinned_normals = buffers[8], g.joint_buffer = buffers[9], g.delta_buffer = buffers[10];
  glGenBuffers(1, &g.weight_buffer);
  glGenBuffers(1, &g.parts);
  glGenVertexArrays(1, &g.gpu_vao);
  glGenVertexArrays(1, &g.cpu_vao);
  GLuint textures[2];
  glGenTextures(2, textures);
  g.delta_texture = textures[0], g.weight_texture = textures[1];
  glBindBuffer(GL_UNIFORM_BUFFER, g.joint_buffer);
  glBufferData(GL_UNIFORM_BUFFER, static_cast<GLsizeiptr>(max_gpu_joints_ * sizeof(mat4)), nullptr, GL_STREAM_DRAW);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  check_gl("setting up the renderer");
}

Renderer::~Renderer() {
  Gl& g = *gl_;
  const GLuint buffers[] = {g.positions, g.normals, g.materials, g.joints, g.weights, g.morph_ranges,
                            g.indices, g.skinned_positions, g.skinned_normals, g.joint_buffer, g.delta_buffer,
                            g.weight_buffer, g.parts};
  glDeleteBuffers(static_cast<GLsizei>(std::size(buffers)), buffers);
  const GLuint textures[] = {g.delta_texture, g.weight_texture, g.resolve_color};
  glDeleteTextures(static_cast<GLsizei>(std::size(textures)), textures);
  const GLuint renderbuffers[] = {g.msaa_color, g.msaa_depth};
  glDeleteRenderbuffers(2, renderbuffers);
  const GLuint framebuffers[] = {g.msaa_fbo, g.resolve_fbo};
  glDeleteFramebuffers(2, framebuffers);
  const GLuint vaos[] = {g.gpu_vao, g.cpu_vao};
  glDeleteVertexArrays(2, vaos);
  glDeleteProgram(g.program);
}

void Renderer::upload(const Mesh& mesh) {
  const std::size_t n = mesh.vertex_count();
  if (n == 0 || mesh.indices.empty()) throw Error("renderer: the mesh is empty");
  look_ = look_for(look_, mesh);  // the avatar's own colours, where the user gave none
  if (mesh.normals.size() != n || mesh.materials.size() != n || mesh.joints.size() != n || mesh.weights.size() != n)
    throw Error("renderer: mesh arrays differ in length (positions " + std::to_string(n) + ", normals " +
                std::to_string(mesh.normals.size()) + ", materials " + std::to_string(mesh.materials.size()) +
                ", joints " + std::to_string(mesh.joints.size()) + ", weights " + std::to_string(mesh.weights.size()) + ")");
  if (mesh.indices.size() % 3 != 0) throw Error("renderer: index count is not a multiple of 3");
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= n) throw Error("renderer: index " + std::to_string(i) + " refers to vertex " +
                                          std::to_string(mesh.indices[i]) + " of " + std::to_string(n));
  mesh_ = mesh;
  compute_bounds();
  joint_limit_ = 0;
  for (const JointIndices& j : mesh.joints)
    joint_limit_ = std::max<std::size_t>(joint_limit_, 1u + std::max(std::max(j.x, j.y), std::max(j.z, j.w)));

  // Sparse morph deltas regrouped per vertex: (offset, count) per vertex into an entry list.
  std::vector<glm::uvec2> ranges(n, glm::uvec2(0));
  for (std::size_t m = 0; m < mesh.morphs.size(); ++m) {
    const MorphTarget& t = mesh.morphs[m];
    if (t.position_deltas.size() != t.vertices.size() || (!t.normal_deltas.empty() && t.normal_deltas.size() != t.vertices.size()))
      throw Error("renderer: morph '" + t.name + "' has delta arrays of the wrong length");
    for (std::uint32_t v : t.vertices) {
      if (v >= n) throw Error("renderer: morph '" + t.name + "' refers to vertex " + std::to_string(v) + " of " + std::to_string(n));
      ++ranges[v].y;
    }
  }
  std::uint32_t offset = 0;
  for (glm::uvec2& r : ranges) r.x = offset, offset += r.y, r.y = 0;
  std::vector<vec4> entries(std::max<std::size_t>(2, 2 * static_cast<std::size_t>(offset)), vec4(0.0f));
  for (std::size_t m = 0; m < mesh.morphs.size(); ++m) {
    const MorphTarget& t = mesh.morphs[m];
    for (std::size_t k = 0; k < t.vertices.size(); ++k) {
      glm::uvec2& r = ranges[t.vertices[k]];
      const std::size_t e = 2 * (r.x + r.y++);
      entries[e] = vec4(t.position_deltas[k], static_cast<float>(m));
      entries[e + 1] = vec4(t.normal_deltas.empty() ? vec3(0.0f) : t.normal_deltas[k], 0.0f);
    }
  }

  Gl& g = *gl_;
  auto fill = [](GLenum target, GLuint buffer, std::size_t bytes, const void* data, GLenum usage) {
    glBindBuffer(target, buffer);
    glBufferData(target, static_cast<GLsizeiptr>(bytes), data, usage);
  };
  fill(GL_ARRAY_BUFFER, g.positions, n * sizeof(vec3), mesh.positions.data(), GL_STATIC_DRAW);
  fill(GL_ARRAY_BUFFER, g.normals, n * sizeof(vec3), mesh.normals.data(), GL_STATIC_DRAW);
  fill(GL_ARRAY_BUFFER, g.materials, n, mesh.materials.data(), GL_STATIC_DRAW);
  fill(GL_ARRAY_BUFFER, g.joints, n * sizeof(JointIndices), mesh.joints.data(), GL_STATIC_DRAW);
  fill(GL_ARRAY_BUFFER, g.weights, n * sizeof(vec4), mesh.weights.data(), GL_STATIC_DRAW);
  fill(GL_ARRAY_BUFFER, g.morph_ranges, n * sizeof(glm::uvec2), ranges.data(), GL_STATIC_DRAW);
  const std::vector<std::uint8_t> trunk(n, static_cast<std::uint8_t>(BodyPart::Trunk));
  fill(GL_ARRAY_BUFFER, g.parts, n, trunk.data(), GL_STATIC_DRAW);
  occluders_.clear();
  fill(GL_ARRAY_BUFFER, g.skinned_positions, n * sizeof(vec3), nullptr, GL_STREAM_DRAW);
  fill(GL_ARRAY_BUFFER, g.skinned_normals, n * sizeof(vec3), nullptr, GL_STREAM_DRAW);
  fill(GL_TEXTURE_BUFFER, g.delta_buffer, entries.size() * sizeof(vec4), entries.data(), GL_STATIC_DRAW);
  glActiveTexture(GL_TEXTURE0 + kMorphDeltaUnit);
  glBindTexture(GL_TEXTURE_BUFFER, g.delta_texture);
  glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, g.delta_buffer);

  auto float_attribute = [](GLuint index, GLuint buffer, GLint size) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, 0, nullptr);
  };
  auto int_attribute = [](GLuint index, GLuint buffer, GLint size, GLenum type) {
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glEnableVertexAttribArray(index);
    glVertexAttribIPointer(index, size, type, 0, nullptr);
  };
  glBindVertexArray(g.gpu_vao);
  float_attribute(0, g.positions, 3);
  float_attribute(1, g.normals, 3);
  int_attribute(2, g.materials, 1, GL_UNSIGNED_BYTE);
  int_attribute(3, g.joints, 4, GL_UNSIGNED_SHORT);
  float_attribute(4, g.weights, 4);
  int_attribute(5, g.morph_ranges, 2, GL_UNSIGNED_INT);
  int_attribute(6, g.parts, 1, GL_UNSIGNED_BYTE);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(g.cpu_vao);
  float_attribute(0, g.skinned_positions, 3);
  float_attribute(1, g.skinned_normals, 3);
  int_attribute(2, g.materials, 1, GL_UNSIGNED_BYTE);
  int_attribute(6, g.parts, 1, GL_UNSIGNED_BYTE);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.indices);
  glBindVertexArray(0);
  g.index_count = static_cast<GLsizei>(mesh.indices.size());

  scratch_positions_.resize(n);
  scratch_normals_.resize(n);
  skinned_positions_.resize(n);
  skinned_normals_.resize(n);
  check_gl("uploading the mesh");
}

void Renderer::set_occluders(const OccluderSet& occluders) {
  if (gl_->index_count == 0) throw Error("renderer: upload() a mesh before set_occluders()");
  occluders_.clear();
  std::vector<std::uint8_t> parts(mesh_.vertex_count(), static_cast<std::uint8_t>(BodyPart::Trunk));
  for (std::size_t v = 0; v < parts.size(); ++v) {
    int best = 0;
    for (int k = 1; k < 4; ++k)
      if (mesh_.weights[v][k] > mesh_.weights[v][best]) best = k;
    const std::size_t j = mesh_.joints[v][best];
    if (j < occluders.joint_part.size()) parts[v] = static_cast<std::uint8_t>(occluders.joint_part[j]);
  }
  glBindBuffer(GL_ARRAY_BUFFER, gl_->parts);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(parts.size()), parts.data(), GL_STATIC_DRAW);
  for (const Occluder& o : occluders.capsules)
    if (occluders_.size() < kMaxOccluders && o.joint >= 0)
      occluders_.push_back(o);
  check_gl("uploading the occluders");
}

void Renderer::compute_bounds() {
  std::size_t joints = 0;
  for (const JointIndices& j : mesh_.joints) joints = std::max<std::size_t>(joints, 1u + std::max(std::max(j.x, j.y), std::max(j.z, j.w)));
  std::vector<vec3> lo(joints, vec3(std::numeric_limits<float>::max())), hi(joints, vec3(-std::numeric_limits<float>::max()));
  auto each_influence = [&](auto&& visit) {
    for (std::size_t v = 0; v < mesh_.vertex_count(); ++v)
      for (int k = 0; k < 4; ++k)
        if (mesh_.weights[v][k] != 0.0f) visit(static_cast<std::size_t>(mesh_.joints[v][k]), mesh_.positions[v]);
  };
  each_influence([&](std::size_t j, const vec3& p) { lo[j] = glm::min(lo[j], p), hi[j] = glm::max(hi[j], p); });
  joint_spheres_.assign(joints, vec4(0.0f, 0.0f, 0.0f, -1.0f));
  for (std::size_t j = 0; j < joints; ++j)
    if (lo[j].x <= hi[j].x) joint_spheres_[j] = vec4((lo[j] + hi[j]) * 0.5f, 0.0f);
  each_influence([&](std::size_t j, const vec3& p) {
    joint_spheres_[j].w = std::max(joint_spheres_[j].w, glm::length(p - vec3(joint_spheres_[j])));
  });
  morph_reach_.assign(mesh_.morphs.size(), 0.0f);
  for (std::size_t m = 0; m < mesh_.morphs.size(); ++m)
    for (const vec3& d : mesh_.morphs[m].position_deltas) morph_reach_[m] = std::max(morph_reach_[m], glm::length(d));
}

void Renderer::resize(int width, int height) {
  if (width == width_ && height == height_) return;
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_size);
  if (width <= 0 || height <= 0 || width > max_size || height > max_size)
    throw Error("renderer: cannot render " + std::to_string(width) + "x" + std::to_string(height) +
                " (this GL allows 1.." + std::to_string(max_size) + " per side)");
  Gl& g = *gl_;
  if (g.msaa_fbo == 0) {
    glGenFramebuffers(1, &g.msaa_fbo);
    glGenFramebuffers(1, &g.resolve_fbo);
    glGenRenderbuffers(1, &g.msaa_color);
    glGenRenderbuffers(1, &g.msaa_depth);
    glGenTextures(1, &g.resolve_color);
  }
  // One sample: plain (not multisampled) storage. Asked for one sample, Mesa gives its smallest
  // multisampled count instead (4 on llvmpipe).
  const bool single = samples_ == 1;
  glBindFramebuffer(GL_FRAMEBUFFER, g.msaa_fbo);
  glBindRenderbuffer(GL_RENDERBUFFER, g.msaa_color);
  if (single) glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  else glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, g.msaa_color);
  glBindRenderbuffer(GL_RENDERBUFFER, g.msaa_depth);
  if (single) glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  else glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples_, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, g.msaa_depth);
  glBindRenderbuffer(GL_RENDERBUFFER, g.msaa_color);
  GLint allocated = 0;
  glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &allocated);
  allocated_samples_ = std::max(1, static_cast<int>(allocated));
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
    throw Error("renderer: the " + std::to_string(width) + "x" + std::to_string(height) + " render target is incomplete");
  width_ = width, height_ = height;
  resolved_background_ = vec3(-1.0f);  // the new resolve texture holds nothing yet
  resolved_rect_ = {};
  resolve_pending_ = {};
}

void Renderer::render(std::span<const View> views, std::span<const mat4> skinning, std::span<const float> morph_weights,
                      SkinningDevice device) {
  if (width_ == 0) throw Error("renderer: resize() before render()");
  if (gl_->index_count == 0) throw Error("renderer: upload() a mesh before render()");
  if (skinning.size() < joint_limit_)
    throw Error("renderer: the mesh uses " + std::to_string(joint_limit_) + " joints but only " +
                std::to_string(skinning.size()) + " skinning matrices were given");
  if (morph_weights.size() > mesh_.morphs.size())
    throw Error("renderer: " + std::to_string(morph_weights.size()) + " morph weights for " +
                std::to_string(mesh_.morphs.size()) + " morph targets");
  Gl& g = *gl_;
  glUseProgram(g.program);
  const bool morphs_active = std::any_of(morph_weights.begin(), morph_weights.end(), [](float w) { return w != 0.0f; });
  if (device == SkinningDevice::Gpu) {
    if (joint_limit_ > max_gpu_joints_)
      throw Error("renderer: the mesh uses " + std::to_string(joint_limit_) + " joints; GPU skinning here holds " +
                  std::to_string(max_gpu_joints_) + " (use the CPU skinning path)");
    const std::size_t used = std::min(skinning.size(), max_gpu_joints_);
    glBindBuffer(GL_UNIFORM_BUFFER, g.joint_buffer);
    glBufferSubData(GL_UNIFORM_BUFFER, 0, static_cast<GLsizeiptr>(used * sizeof(mat4)), skinning.data());
    glBindBufferBase(GL_UNIFORM_BUFFER, kJointBlockBinding, g.joint_buffer);
    std::vector<float> weights(std::max<std::size_t>(1, mesh_.morphs.size()), 0.0f);
    std::copy(morph_weights.begin(), morph_weights.end(), weights.begin());
    glBindBuffer(GL_TEXTURE_BUFFER, g.weight_buffer);
    glBufferData(GL_TEXTURE_BUFFER, static_cast<GLsizeiptr>(weights.size() * sizeof(float)), weights.data(), GL_STREAM_DRAW);
    glActiveTexture(GL_TEXTURE0 + kMorphWeightUnit);
    glBindTexture(GL_TEXTURE_BUFFER, g.weight_texture);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_R32F, g.weight_buffer);
    glActiveTexture(GL_TEXTURE0 + kMorphDeltaUnit);
    glBindTexture(GL_TEXTURE_BUFFER, g.delta_texture);
    glUniform1i(g.u_skin_on_gpu, 1);
    glUniform1i(g.u_morphs_active, morphs_active ? 1 : 0);
    glBindVertexArray(g.gpu_vao);
  } else {
    morph_scratch_.assign(mesh_.morphs.size(), 0.0f);
    std::copy(morph_weights.begin(), morph_weights.end(), morph_scratch_.begin());
    std::span<const vec3> rest_positions = mesh_.positions, rest_normals = mesh_.normals;
    if (morphs_active) {
      apply_morphs(mesh_.positions, mesh_.morphs, morph_scratch_, scratch_positions_);
      apply_morph_normals(mesh_.normals, mesh_.morphs, morph_scratch_, scratch_normals_);
      rest_positions = scratch_positions_, rest_normals = scratch_normals_;
    }
    skin_positions_normals(skinning, mesh_.joints, mesh_.weights, rest_positions, rest_normals, skinned_positions_,
                           skinned_normals_);
    const auto bytes = static_cast<GLsizeiptr>(skinned_positions_.size() * sizeof(vec3));
    glBindBuffer(GL_ARRAY_BUFFER, g.skinned_positions);
    glBufferData(GL_ARRAY_BUFFER, bytes, skinned_positions_.data(), GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, g.skinned_normals);
    glBufferData(GL_ARRAY_BUFFER, bytes, skinned_normals_.data(), GL_STREAM_DRAW);
    glUniform1i(g.u_skin_on_gpu, 0);
    glUniform1i(g.u_morphs_active, 0);
    glBindVertexArray(g.cpu_vao);
  }
  vec3 albedo[kMaterialCount];  // sRGB colours to linear once per frame, not per fragment
  for (int m = 0; m < kMaterialCount; ++m) albedo[m] = glm::pow(look_.colors[static_cast<std::size_t>(m)], vec3(2.2f));
  glUniform3fv(g.u_albedo, kMaterialCount, &albedo[0].x);
  vec4 surfaces[kMaterialCount];
  for (int m = 0; m < kMaterialCount; ++m) {
    const SurfaceResponse& s = look_.surfaces[static_cast<std::size_t>(m)];
    surfaces[m] = vec4(s.wrap, s.scatter, shown_specular(static_cast<MaterialId>(m), s, look_.colors[static_cast<std::size_t>(m)]), s.shininess);
  }
  glUniform4fv(g.u_surface, kMaterialCount, &surfaces[0].x);
  // The capsules where the pose puts them (skinning = posed model × inverse bind).
  vec4 occluder_a[kMaxOccluders], occluder_b[kMaxOccluders];
  int occluder_count = 0;
  for (const Occluder& o : occluders_) {
    if (static_cast<std::size_t>(o.joint) >= skinning.size()) continue;
    const mat4& m = skinning[static_cast<std::size_t>(o.joint)];
    const float scale = std::cbrt(std::max(1e-12f, std::abs(glm::determinant(mat3(m)))));
    occluder_a[occluder_count] = vec4(vec3(m * vec4(o.a, 1.0f)), o.radius * scale);
    occluder_b[occluder_count] = vec4(vec3(m * vec4(o.b, 1.0f)), static_cast<float>(o.part));
    ++occluder_count;
  }
  glUniform1i(g.u_occluder_count, occluder_count);
  if (occluder_count > 0) {
    glUniform4fv(g.u_occluder_a, occluder_count, &occluder_a[0].x);
    glUniform4fv(g.u_occluder_b, occluder_count, &occluder_b[0].x);
  }

  // The MSAA target is cleared whole (llvmpipe's fast path; scissored clears draw quads), but only
  // the part of the image the posed mesh can cover — plus what the previous frame covered, to wipe
  // it — is resolved: the resolve blit costs more than drawing the figure on llvmpipe.
  const PixelRect covered = covered_rect(views, skinning, morph_weights);
  PixelRect resolve = covered;
  if (look_.background != resolved_background_) resolve = {0, 0, width_, height_};
  else if (!resolved_rect_.empty()) resolve = resolve.empty() ? resolved_rect_ : resolve.unite(resolved_rect_);
  resolved_background_ = look_.background;
  resolved_rect_ = covered;

  glBindFramebuffer(GL_FRAMEBUFFER, g.msaa_fbo);
  glDisable(GL_SCISSOR_TEST);
  glClearColor(look_.background.x, look_.background.y, look_.background.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  for (const View& view : views) {
    const Viewport& vp = view.viewport;
    const PixelRect pane = PixelRect::of(vp, height_).intersect(covered);
    if (pane.empty()) continue;
    glViewport(vp.x, height_ - vp.y - vp.height, vp.width, vp.height);
    glScissor(pane.x0, pane.y0, pane.width(), pane.height());
    const mat4 view_projection = view.camera.projection * view.camera.view;
    glUniformMatrix4fv(g.u_view_projection, 1, GL_FALSE, &view_projection[0][0]);
    glUniform3fv(g.u_eye, 1, &view.camera.eye.x);
    const vec3 direction = glm::normalize(view.camera.target - view.camera.eye);
    glUniform3fv(g.u_view_direction, 1, &direction.x);
    glUniform1f(g.u_focus_distance, glm::dot(view.camera.target - view.camera.eye, direction));
    glUniform1i(g.u_orthographic, view.camera.orthographic ? 1 : 0);
    glDrawElements(GL_TRIANGLES, g.index_count, GL_UNSIGNED_INT, nullptr);
  }
  glDisable(GL_SCISSOR_TEST);
  // Resolved later, when needed: a one-sample video frame is read straight from the drawing target,
  // and the blit (about 1.5 ms of llvmpipe CPU per 720p frame) is saved.
  if (!resolve.empty()) resolve_pending_ = resolve_pending_.empty() ? resolve : resolve_pending_.unite(resolve);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("drawing");
}

PixelRect PixelRect::of(const Viewport& vp, int image_height) {
  return {vp.x, image_height - vp.y - vp.height, vp.x + vp.width, image_height - vp.y};
}

PixelRect PixelRect::unite(const PixelRect& o) const {
  return {std::min(x0, o.x0), std::min(y0, o.y0), std::max(x1, o.x1), std::max(y1, o.y1)};
}

PixelRect PixelRect::intersect(const PixelRect& o) const {
  PixelRect r{std::max(x0, o.x0), std::max(y0, o.y0), std::min(x1, o.x1), std::min(y1, o.y1)};
  if (r.empty()) r = {};
  return r;
}

// A bound of the skinned, morphed mesh: every vertex lies in the sphere of each joint influencing
// it (at bind), a skinned vertex is a convex blend of its rigidly moved copies, so the boxes of the
// moved spheres (radii scaled by the matrices' largest axis, grown by the largest morph offsets)
// contain it. Projected per view into a pixel rectangle (the whole pane when anything is behind
// the eye), with a 2-pixel margin for MSAA edges.
PixelRect Renderer::covered_rect(std::span<const View> views, std::span<const mat4> skinning,
                                 std::span<const float> morph_weights) const {
  float morph_reach = 0.0f;
  for (std::size_t m = 0; m < morph_weights.size(); ++m) morph_reach += std::abs(morph_weights[m]) * morph_reach_[m];
  vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (std::size_t j = 0; j < joint_spheres_.size(); ++j) {
    const vec4 sphere = joint_spheres_[j];
    if (sphere.w < 0.0f) continue;
    const mat4& m = skinning[j];
    const float scale = std::max({glm::length(vec3(m[0])), glm::length(vec3(m[1])), glm::length(vec3(m[2]))});
    const vec3 centre = vec3(m * vec4(vec3(sphere), 1.0f));
    const float radius = (sphere.w + morph_reach) * scale;
    lo = glm::min(lo, centre - radius);
    hi = glm::max(hi, centre + radius);
  }
  PixelRect all{};
  for (const View& view : views) {
    const PixelRect pane = PixelRect::of(view.viewport, height_).intersect({0, 0, width_, height_});
    const mat4 view_projection = view.camera.projection * view.camera.view;
    float x0 = std::numeric_limits<float>::max(), y0 = x0, x1 = -x0, y1 = -x0;
    bool behind = !(lo.x <= hi.x) || !is_finite(lo) || !is_finite(hi);
    for (int corner = 0; corner < 8 && !behind; ++corner) {
      const vec4 clip = view_projection * vec4((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z, 1.0f);
      if (clip.w <= 1e-6f) {
        behind = true;
        break;
      }
      const float nx = clip.x / clip.w, ny = clip.y / clip.w;
      x0 = std::min(x0, nx), x1 = std::max(x1, nx), y0 = std::min(y0, ny), y1 = std::max(y1, ny);
    }
    PixelRect r = pane;
    if (!behind) {
      const auto px = [&](float ndc, int origin, float size) {
        return static_cast<float>(origin) + (std::clamp(ndc, -2.0f, 2.0f) * 0.5f + 0.5f) * size;
      };
      const Viewport& vp = view.viewport;
      const PixelRect full = PixelRect::of(vp, height_);
      r = PixelRect{static_cast<int>(std::floor(px(x0, full.x0, static_cast<float>(vp.width)))) - 2,
                    static_cast<int>(std::floor(px(y0, full.y0, static_cast<float>(vp.height)))) - 2,
                    static_cast<int>(std::ceil(px(x1, full.x0, static_cast<float>(vp.width)))) + 2,
                    static_cast<int>(std::ceil(px(y1, full.y0, static_cast<float>(vp.height)))) + 2}
              .intersect(pane);
    }
    if (r.empty()) continue;
    all = all.empty() ? r : all.unite(r);
  }
  return all;
}

void Renderer::resolve() const {
  if (resolve_pending_.empty()) return;
  const PixelRect& r = resolve_pending_;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, gl_->msaa_fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, gl_->resolve_fbo);
  glBlitFramebuffer(r.x0, r.y0, r.x1, r.y1, r.x0, r.y0, r.x1, r.y1, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  resolve_pending_ = {};
  check_gl("resolving the frame");
}

unsigned Renderer::resolved_texture() const {
  resolve();
  return gl_->resolve_color;
}

void Renderer::read_pixels(Image& out) {
  if (samples_ == 1 && allocated_samples_ == 1) {
    read_framebuffer(gl_->msaa_fbo, width_, height_, out);  // nothing to resolve: read the drawing target
  } else {
    resolve();
    read_framebuffer(gl_->resolve_fbo, width_, height_, out);
  }
  // Edges exist only where the figure is: outside its rectangle the image is background.
  if (edge_filter_ && !resolved_rect_.empty())
    smooth_edges(out, {resolved_rect_.x0, height_ - resolved_rect_.y1, resolved_rect_.x1, height_ - resolved_rect_.y0},
                 edge_scratch_);
}

void Renderer::read_window_pixels(Image& out, int framebuffer_width, int framebuffer_height) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  read_framebuffer(0, framebuffer_width, framebuffer_height, out);
}

void Renderer::read_framebuffer(unsigned framebuffer, int width, int height, Image& out) {
  if (out.width != width || out.height != height) out = Image(width, height);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, out.rgba.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  check_gl("reading pixels back");
  // GL rows run bottom to top; images top to bottom.
  const std::size_t row = static_cast<std::size_t>(width) * 4;
  std::vector<std::uint8_t> tmp(row);
  for (int y = 0; y < height / 2; ++y) {
    std::uint8_t* a = out.pixel(0, y);
    std::uint8_t* b = out.pixel(0, height - 1 - y);
    std::memcpy(tmp.data(), a, row);
    std::memcpy(a, b, row);
    std::memcpy(b, tmp.data(), row);
  }
}

void Renderer::present(int framebuffer_width, int framebuffer_height) {
  resolve();
  glBindFramebuffer(GL_READ_FRAMEBUFFER, gl_->resolve_fbo);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  glClearColor(look_.background.x, look_.background.y, look_.background.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, framebuffer_width, framebuffer_height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Renderer::finish() { glFinish(); }

}  // namespace gestura
