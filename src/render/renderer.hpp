// Draws a viz::DrawList into an offscreen framebuffer (MSAA or FXAA) and returns the
// pixels. Meshes, shaders and the font atlas are created once per Renderer.
// No GL headers leak from here: the GL state lives in Renderer::Impl.
#pragma once

#include <filesystem>
#include <memory>
#include <string_view>

#include "render/fxaa.hpp"
#include "render/gl_context.hpp"
#include "io/image.hpp"
#include "render/resource_dir.hpp"
#include "scene/frame_settings.hpp"
#include "viz/draw_list.hpp"

namespace tumble::render {

/// Where the GPU does more than draw. Both on for a hardware GPU; off on
/// llvmpipe, where each measured slower (docs/rendering.md, "Using the whole machine")
/// and the CPU FXAA keeps the bytes the goldens hold.
struct GpuPaths {
  bool overlapped_readback = false;  ///< two PBOs: a frame's read-back overlaps the next one's drawing
  bool gl_fxaa = false;              ///< FXAA as a GL pass (shaders/fxaa.frag), not on the encoder threads
  bool operator==(const GpuPaths&) const = default;
};

/// On for a hardware GPU (GlContext::hardware_gpu), else off; env
/// TUMBLE_GPU_PATHS overrides: "auto", "none", or a comma list of "pbo" and
/// "fxaa". Throws std::invalid_argument naming the variable on other values.
GpuPaths default_gpu_paths(const GlContext& context);
/// The paths env TUMBLE_GPU_PATHS asks for on a GPU of that kind; throws
/// std::invalid_argument naming the variable, so it can be checked before work.
GpuPaths gpu_paths_from_env(bool hardware_gpu);
GpuPaths parse_gpu_paths(std::string_view text, bool hardware_gpu);

class Renderer {
 public:
  /// `context` must outlive the renderer. `aa` is the frame settings'
  /// anti-aliasing: msaa with `msaa` samples (2 or 4, clamped to
  /// GL_MAX_SAMPLES; 0 is none), fxaa (FXAA on the read-back frame and smooth
  /// lines; text is left as drawn, already anti-aliased) or none. Shaders come from
  /// `resource_dir`/shaders, the font from `resource_dir`/fonts or the system
  /// DejaVu. Throws std::runtime_error on missing resources, shader errors or
  /// an incomplete framebuffer.
  Renderer(GlContext& context, int width, int height, scene::Antialias aa = scene::Antialias::msaa, int msaa = 4,
           const std::filesystem::path& resource_dir = find_resource_dir());
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Renders all views (grid of `columns`, row-major; each its 3D items in its
  /// content rectangle, then its texts) plus the frame overlay texts. Makes
  /// the context current on the calling thread.
  io::Image render(const viz::DrawList& frame);
  /// Same, into `out`, reusing its pixel storage (cheaper in a frame loop).
  void render(const viz::DrawList& frame, io::Image& out);
  /// Same, stopping at the read-back: finish_frame(out, ...) makes the image
  /// (with FXAA when it is on), e.g. on a FrameEncoder thread while the next
  /// frame draws. The bytes equal render(frame, image)'s.
  void render(const viz::DrawList& frame, RawFrame& out);

  /// The frame loop's form: draws `frame` (the caller's frame number
  /// `index`) and hands back in `out` a frame ready to finish, with its
  /// `index`: with overlapped read-back the frame before (false for the
  /// first), else this one. finish_overlapped(out) hands back the last one
  /// (false when none is left). Same bytes as render(frame, out).
  bool render_overlapped(const viz::DrawList& frame, long index, RawFrame& out);
  bool finish_overlapped(RawFrame& out);

  /// Defaults to default_gpu_paths(context). Finish the overlapped frames first.
  void set_gpu_paths(GpuPaths paths);
  GpuPaths gpu_paths() const;

  int width() const;
  int height() const;
  int samples() const;  ///< MSAA samples after clamping (0 = off)
  bool fxaa() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tumble::render
