#pragma once
// Draws a skinned, morphable Mesh. Needs a current OpenGL 3.3 core context (HeadlessGlContext or
// WindowGlContext) for its whole life; the same drawing code serves both.
//
// Upload the mesh once, then per frame render() with the joints' skinning matrices (model-space
// joint matrix × inverse bind matrix, one per joint) and morph weights (one per mesh morph target,
// missing = 0). Two skinning paths:
//   Gpu — bind-pose vertices stay on the GPU; the vertex shader blends four joint matrices
//         (from a uniform block, up to max_gpu_joints()) after adding the sparse morph deltas (a texture buffer
//         of (delta, morph index) entries per vertex, weights in another texture buffer).
//   Cpu — morphs and linear blend skinning on the CPU (body/morph, body/skinning), the result
//         streamed to the GPU every frame (comparison and fallback beyond max_gpu_joints()).
// Frames go to an offscreen target (4× MSAA by default, or one sample; see Antialiasing), resolved
// to a texture; read_pixels() reads it back (and runs the edge filter if asked), present() blits
// it into the window.
#include <cstdint>
#include <memory>
#include <span>

#include "gestura/body/mesh.hpp"
#include "gestura/render/camera.hpp"
#include "gestura/render/edge_filter.hpp"
#include "gestura/render/image.hpp"
#include "gestura/render/look.hpp"
#include "gestura/render/occluders.hpp"

namespace gestura {

// Where the vertices are skinned (body/skinning.hpp's SkinningPath picks the CPU kernel).
enum class SkinningDevice : std::uint8_t { Gpu, Cpu };

// A pixel rectangle in GL's convention (origin bottom-left), half-open [x0, x1) × [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width() const { return x1 - x0; }
  int height() const { return y1 - y0; }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  static PixelRect of(const Viewport& viewport, int image_height);
  PixelRect intersect(const PixelRect& other) const;  // empty rect when they do not overlap
  PixelRect unite(const PixelRect& other) const;      // bounding rectangle of both
};

struct View {
  Camera camera;
  Viewport viewport;  // pixels in the render target, origin top-left
};

// How edges are smoothed. Msaa4 / Msaa2: the GL's multisampling (llvmpipe has only 4 samples, so
// Msaa2 is 4 there); on llvmpipe a 4-sample frame costs about twice a one-sample frame (bench R1).
// EdgeFilter: one sample per pixel; read_pixels() then smooths the image's edges on the CPU
// (render/edge_filter.hpp, FXAA-like), where a GL pass cost llvmpipe as much as multisampling.
// present() shows the frame unfiltered. None: one sample, stair-stepped edges.
enum class Antialiasing : std::uint8_t { Msaa4, Msaa2, EdgeFilter, None };

// The antialiasing `--msaa N` names: 4 and 2 samples, or 1 (none).
Antialiasing antialiasing_for_samples(int samples);

class Renderer {
 public:
  explicit Renderer(const Look& look = Look{}, Antialiasing antialiasing = Antialiasing::Msaa4);  // throws gestura::Error on GL failure
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Copies the mesh (kept for the CPU path) and uploads it. Throws gestura::Error when the mesh's
  // arrays disagree in size or an index is out of range.
  void upload(const Mesh& mesh);
  // The capsules that shade the body (soft shadows, ambient occlusion) for the uploaded mesh; an
  // upload clears them. Without them nothing is shaded that way. Throws before an upload.
  void set_occluders(const OccluderSet& occluders);
  void set_look(const Look& look) { look_ = look; }
  const Look& look() const { return look_; }

  // (Re)allocates the offscreen target; throws gestura::Error beyond the GL's limits.
  void resize(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }

  // Draws all views into the offscreen target. The resolve into the texture happens when something
  // needs it (present(), resolved_texture(), a multisampled read_pixels()); a one-sample target is
  // read back directly. Throws gestura::Error when a
  // vertex refers to a joint beyond skinning.size() or more weights than morphs are given.
  void render(std::span<const View> views, std::span<const mat4> skinning, std::span<const float> morph_weights,
              SkinningDevice device = SkinningDevice::Gpu);
  // Waits for the GPU and copies the resolved frame into `out` (resized), rows top to bottom.
  void read_pixels(Image& out);
  // Reads what present() put into the window's back buffer (a screenshot of the window itself).
  void read_window_pixels(Image& out, int framebuffer_width, int framebuffer_height);
  // Blits the resolved frame into the default framebuffer (the window), scaled to fit.
  void present(int framebuffer_width, int framebuffer_height);
  std::size_t max_gpu_joints() const { return max_gpu_joints_; }
  // The GL texture holding the resolved frame (rows bottom to top), for a UI that shows it as an
  // image (the studio's preview panel); 0 before the first resize().
  unsigned resolved_texture() const;  // resolves what is pending first
  // Samples per pixel of the drawing target as the GL allocated it (after resize()).
  int samples() const { return allocated_samples_; }
  // Blocks until the GL has finished drawing (for measuring draw time alone).
  void finish();

 private:
  struct Gl;
  void read_framebuffer(unsigned framebuffer, int width, int height, Image& out);
  void compute_bounds();
  void resolve() const;  // blits what is pending (resolve_pending_) into the resolve texture
  PixelRect covered_rect(std::span<const View> views, std::span<const mat4> skinning,
                         std::span<const float> morph_weights) const;
  std::unique_ptr<Gl> gl_;
  Look look_;
  Mesh mesh_;
  int samples_;               // per pixel in the drawing target (1: not multisampled)
  bool edge_filter_ = false;  // one sample, then the edge filter
  int allocated_samples_ = 0;
  int width_ = 0, height_ = 0;
  std::size_t joint_limit_ = 0;
  std::size_t max_gpu_joints_ = 0;
  std::vector<vec4> joint_spheres_;  // per joint: bind-pose sphere (centre, radius) of its vertices; radius < 0 = none
  std::vector<float> morph_reach_;   // per morph: its largest position offset
  std::vector<Occluder> occluders_;
  vec3 resolved_background_{-1.0f};  // the colour the resolved image's untouched area holds
  PixelRect resolved_rect_;          // where the last frame drew in the drawing target
  mutable PixelRect resolve_pending_;        // what the resolve texture lacks of the drawing target (frames not yet resolved)
  std::vector<vec3> scratch_positions_, scratch_normals_, skinned_positions_, skinned_normals_;
  std::vector<float> morph_scratch_;  // the caller's weights padded to one per morph target
  EdgeFilterScratch edge_scratch_;
};

}  // namespace gestura
