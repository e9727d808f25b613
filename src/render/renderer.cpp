#include "render/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/font_atlas.hpp"
#include "render/fxaa.hpp"
#include "render/gl_functions.hpp"
#include "render/instanced_mesh.hpp"
#include "render/line_pass.hpp"
#include "render/offscreen_target.hpp"
#include "render/shader_program.hpp"
#include "render/sphere_pass.hpp"
#include "render/surface_pass.hpp"
#include "render/text_pass.hpp"
#include "render/view_batches.hpp"
#include "compose/view_layout.hpp"
#include "viz/captions.hpp"
#include "viz/text_layout.hpp"

namespace tumble::render {

using compose::CameraMatrices;
using compose::PixelRect;

namespace {

constexpr float kEdgeWidthPx = 1.5f;
constexpr float kGridWidthPx = 1.0f;
// Tint the top of each view towards a pale sky blue.
constexpr glm::vec3 kSkyTint{0.74f, 0.83f, 0.95f};
constexpr float kSkyAmount = 0.35f;
// Fraction of each view's height (from the bottom) left at the plain background.
constexpr float kFlatBackground = 0.35f;
// Key light from the camera's upper left, so shapes read the same in every view.
const glm::vec3 kLightDir = glm::normalize(glm::vec3(-0.35f, 0.55f, 0.75f));
constexpr float kOpaqueSpecular = 0.28f;

}  // namespace

// Everything GL lives here, so renderer.hpp stays free of GL headers.
class Renderer::Impl {
 public:
  Impl(GlContext& context, int width, int height, int msaa, bool fxaa,
       const std::filesystem::path& resource_dir);
  ~Impl();
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  void render(const viz::DrawList& frame, RawFrame& out);
  void render(const viz::DrawList& frame, io::Image& out) {
    render(frame, raw_);
    finish_frame(raw_, out, post_);
  }
  bool render_overlapped(const viz::DrawList& frame, long index, RawFrame& out);
  bool finish_overlapped(RawFrame& out);
  void set_gpu_paths(GpuPaths paths);
  GpuPaths gpu_paths() const { return paths_; }
  const OffscreenTarget& target() const { return target_; }
  bool fxaa() const { return fxaa_; }

 private:
  void draw_view(const viz::View& view, const PixelRect& rect, const glm::vec3& background);
  void draw_background(const glm::vec3& background);
  void draw_separators(const std::vector<PixelRect>& rects, const glm::vec3& color);
  void draw_meshes(const ViewBatches& batches, const CameraMatrices& cam, bool ghost_arrows);
  void draw_text(const std::vector<viz::TextItem>& items, const PixelRect& rect);
  void set_viewport(const PixelRect& rect);
  void draw(const viz::DrawList& frame);
  void gl_fxaa_pass();
  void describe(RawFrame& out, long index) const {
    out.width = target_.width();
    out.height = target_.height();
    out.fxaa = fxaa_ && !paths_.gl_fxaa;  // else FXAA is in the pixels already
    out.index = index;
  }
  SphereShading sphere_shading() const { return {kLightDir, kOpaqueSpecular, target_.samples() > 0}; }

  GlContext& context_;
  const GlFunctions& gl_;
  FontAtlas font_;
  OffscreenTarget target_;
  ShaderProgram mesh_program_, background_program_;
  InstancedMesh cube_, cylinder_, cone_;
  SpherePass spheres_;
  SurfacePass surfaces_;
  LinePass lines_;
  TextPass text_;
  bool fxaa_;    // FXAA on the read-back frame, smooth lines, text marked in alpha
  Fxaa post_;    // its scratch, for render(..., Image&)
  RawFrame raw_;
  GlObject empty_vao_;  // core profile needs a bound VAO even for attribute-less draws
  GpuPaths paths_;
  std::optional<ShaderProgram> fxaa_program_;  // made when gl_fxaa is first used
  std::filesystem::path shader_dir_;
  long queued_index_[2] = {-1, -1};  // frame numbers of the overlapped reads, oldest first
};

Renderer::Renderer(GlContext& context, int width, int height, scene::Antialias aa, int msaa,
                   const std::filesystem::path& resource_dir)
    : impl_(std::make_unique<Impl>(context, width, height, aa == scene::Antialias::msaa ? msaa : 0,
                                   aa == scene::Antialias::fxaa, resource_dir)) {}

Renderer::~Renderer() = default;

io::Image Renderer::render(const viz::DrawList& frame) {
  io::Image img;
  impl_->render(frame, img);
  return img;
}

void Renderer::render(const viz::DrawList& frame, io::Image& out) { impl_->render(frame, out); }
void Renderer::render(const viz::DrawList& frame, RawFrame& out) { impl_->render(frame, out); }
bool Renderer::render_overlapped(const viz::DrawList& frame, long index, RawFrame& out) {
  return impl_->render_overlapped(frame, index, out);
}
bool Renderer::finish_overlapped(RawFrame& out) { return impl_->finish_overlapped(out); }
void Renderer::set_gpu_paths(GpuPaths paths) { impl_->set_gpu_paths(paths); }
GpuPaths Renderer::gpu_paths() const { return impl_->gpu_paths(); }

int Renderer::width() const { return impl_->target().width(); }
int Renderer::height() const { return impl_->target().height(); }
int Renderer::samples() const { return impl_->target().samples(); }
bool Renderer::fxaa() const { return impl_->fxaa(); }

Renderer::Impl::Impl(GlContext& context, int width, int height, int msaa, bool fxaa,
                     const std::filesystem::path& resource_dir)
    : context_((context.make_current(), context)),  // current before any GL call
      gl_(context.gl()),
      font_(find_font_file(resource_dir)),
      target_(gl_, width, height, msaa),
      mesh_program_(gl_, resource_dir / "shaders", "mesh"),
      background_program_(gl_, resource_dir / "shaders", "background"),
      cube_(gl_, unit_cube()),
      cylinder_(gl_, unit_cylinder(20)),
      cone_(gl_, unit_cone(24)),
      spheres_(gl_, resource_dir / "shaders"),
      surfaces_(gl_, resource_dir / "shaders"),
      lines_(gl_, resource_dir / "shaders"),
      text_(gl_, resource_dir / "shaders", font_),
      fxaa_(fxaa),
      empty_vao_(make_vertex_array(gl_)),
      paths_(default_gpu_paths(context)),
      shader_dir_(resource_dir / "shaders") {}

// GL objects are freed by their members; they need our context current.
Renderer::Impl::~Impl() {
  try {
    context_.make_current();
  } catch (...) {  // nothing sensible to do in a destructor
  }
}

void Renderer::Impl::set_viewport(const PixelRect& rect) {
  const int gl_y = target_.height() - (rect.y + rect.height);  // GL counts from the bottom
  gl_.Viewport(rect.x, gl_y, rect.width, rect.height);
  gl_.Scissor(rect.x, gl_y, rect.width, rect.height);
}

void Renderer::Impl::render(const viz::DrawList& frame, RawFrame& out) {
  draw(frame);
  target_.read_rgba(out.rgba);
  describe(out, -1);
}

bool Renderer::Impl::render_overlapped(const viz::DrawList& frame, long index, RawFrame& out) {
  if (!paths_.overlapped_readback) {
    render(frame, out);
    out.index = index;
    return true;
  }
  draw(frame);
  target_.start_read();
  queued_index_[target_.reads_queued() - 1] = index;
  return target_.reads_queued() == 2 && finish_overlapped(out);
}

bool Renderer::Impl::finish_overlapped(RawFrame& out) {
  context_.make_current();
  if (!target_.finish_read(out.rgba)) return false;
  describe(out, queued_index_[0]);
  queued_index_[0] = queued_index_[1];
  return true;
}

void Renderer::Impl::set_gpu_paths(GpuPaths paths) {
  if (target_.reads_queued() > 0) throw std::logic_error("Renderer: set_gpu_paths with overlapped frames unfinished");
  paths_ = paths;
}

void Renderer::Impl::gl_fxaa_pass() {
  if (!fxaa_program_) {
    try {
      fxaa_program_.emplace(gl_, shader_dir_, "fxaa");
    } catch (const std::runtime_error&) {
      // No `precise` (GL_ARB_gpu_shader5, GL 4 hardware): the CPU FXAA on the
      // encoder threads does it, as on llvmpipe.
      paths_.gl_fxaa = false;
      return;
    }
  }
  target_.begin_post_pass();
  gl_.Disable(GL_DEPTH_TEST);
  gl_.Disable(GL_BLEND);
  gl_.Disable(GL_SCISSOR_TEST);
  fxaa_program_->use();
  fxaa_program_->set("u_frame", 0);
  gl_.BindVertexArray(empty_vao_.id());
  gl_.DrawArrays(GL_TRIANGLES, 0, 3);
}

void Renderer::Impl::draw(const viz::DrawList& frame) {
  context_.make_current();
  target_.bind_for_drawing();
  lines_.set_frame_height(target_.height());
  gl_.Disable(GL_SCISSOR_TEST);
  // Without MSAA's samples, lines get smooth coverage (Mesa's anti-aliased
  // line stage); set every frame, another renderer may share the context.
  if (fxaa_) gl_.Enable(GL_LINE_SMOOTH);
  else gl_.Disable(GL_LINE_SMOOTH);
  // One full clear (llvmpipe's fast path) gives every view its flat lower
  // background and depth; views then only paint their sky gradient.
  const glm::vec3 background(frame.background);
  gl_.ClearColor(background.r, background.g, background.b, 1.0f);
  gl_.DepthMask(GL_TRUE);
  gl_.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

  gl_.Enable(GL_SCISSOR_TEST);
  gl_.Enable(GL_BLEND);
  gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  const int count = static_cast<int>(frame.views.size());
  std::vector<PixelRect> rects;
  for (int i = 0; i < count; ++i) {
    rects.push_back(compose::view_rect(frame.views[i], i, count, frame.columns, target_.width(), target_.height()));
    if (rects.back().width > 0 && rects.back().height > 0) {
      draw_view(frame.views[i], rects.back(), background);
    }
  }
  const PixelRect full{0, 0, target_.width(), target_.height()};
  set_viewport(full);
  if (count == 0) draw_background(background);
  draw_separators(rects, background * 0.82f);
  draw_text(frame.texts, full);
  gl_.Disable(GL_SCISSOR_TEST);
  if (fxaa_ && paths_.gl_fxaa) gl_fxaa_pass();
}

void Renderer::Impl::draw_background(const glm::vec3& background) {
  gl_.Disable(GL_DEPTH_TEST);
  // Opaque: with blending on, llvmpipe reads back every sample it covers.
  gl_.Disable(GL_BLEND);
  background_program_.use();
  background_program_.set("u_flat", kFlatBackground);
  background_program_.set("u_bottom", background);
  background_program_.set("u_top", glm::mix(background, kSkyTint * std::max(background.r, 0.5f),
                                             kSkyAmount));
  gl_.BindVertexArray(empty_vao_.id());
  gl_.DrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  gl_.Enable(GL_BLEND);
}

// 1 px lines in the gaps view_rect leaves left of / above non-edge views.
void Renderer::Impl::draw_separators(const std::vector<PixelRect>& rects, const glm::vec3& color) {
  const float w = float(target_.width()), h = float(target_.height());
  auto ndc = [&](float x_px, float y_px) {
    return glm::vec3(x_px / w * 2.0f - 1.0f, 1.0f - y_px / h * 2.0f, 0.0f);
  };
  const glm::vec4 c(color, 1.0f);
  std::vector<LineVertex> lines;
  for (const PixelRect& r : rects) {
    const float x = float(r.x), y = float(r.y), bottom = float(r.y + r.height);
    if (r.x > 0) {
      lines.push_back({ndc(x - 0.5f, y - 1.0f), c});
      lines.push_back({ndc(x - 0.5f, bottom), c});
    }
    if (r.y > 0) {
      lines.push_back({ndc(x - 1.0f, y - 0.5f), c});
      lines.push_back({ndc(float(r.x + r.width), y - 0.5f), c});
    }
  }
  gl_.Disable(GL_DEPTH_TEST);
  lines_.draw(lines, glm::mat4(1.0f), 1.0f);
}

void Renderer::Impl::draw_view(const viz::View& view, const PixelRect& rect,
                         const glm::vec3& background) {
  set_viewport(rect);
  draw_background(background);
  // The 3D passes see and are clipped to the content rectangle; the text the whole view.
  const PixelRect content = compose::content_rect(view, rect);
  if (content.width <= 0 || content.height <= 0) return draw_text(view.texts, rect);
  set_viewport(content);

  const CameraMatrices cam = compose::camera_matrices(view.camera, content.aspect());
  const glm::mat4 view_proj = cam.proj * cam.view;
  const ViewBatches batches = build_view_batches(view);

  gl_.Enable(GL_DEPTH_TEST);
  gl_.DepthFunc(GL_LEQUAL);
  // The grid is a faint backdrop: depth-tested, but it must not hide what
  // lies just below the plane through its own translucency.
  gl_.DepthMask(GL_FALSE);
  lines_.draw(batches.grid, view_proj, kGridWidthPx);
  gl_.DepthMask(GL_TRUE);

  surfaces_.draw(view.surfaces, cam.view, cam.proj, kLightDir);
  spheres_.draw(view.particles, view.camera, cam.view, cam.proj, content.height, sphere_shading());
  // A solid of particles or an opaque mesh hides the arrows inside it: show
  // them faintly (a translucent surface alone, the momentum sphere's energy
  // ellipsoid, hides nothing, and its opaque ball must keep hiding the far side).
  const bool solid = std::any_of(view.surfaces.begin(), view.surfaces.end(),
                                 [](const viz::SurfaceItem& s) { return s.color.a >= 1.0f; });
  draw_meshes(batches, cam, !view.particles.empty() || solid);

  gl_.DepthMask(GL_FALSE);  // trails and edges are translucent overlays
  for (const Polyline& p : batches.polylines)
    if (!p.over_glass) lines_.draw(p.strip, view_proj, p.width_px, GL_LINE_STRIP);
  lines_.draw(batches.box_edges, view_proj, kEdgeWidthPx);
  gl_.DepthMask(GL_TRUE);
  // Translucent surfaces last, over the curves behind them; then the curves on their near side.
  surfaces_.draw_translucent(view.surfaces, cam.view, cam.proj, kLightDir);
  gl_.DepthMask(GL_FALSE);
  for (const Polyline& p : batches.polylines)
    if (p.over_glass) lines_.draw(p.strip, view_proj, p.width_px, GL_LINE_STRIP);
  gl_.DepthMask(GL_TRUE);

  gl_.Disable(GL_DEPTH_TEST);
  set_viewport(rect);
  draw_text(view.texts, rect);
}

void Renderer::Impl::draw_meshes(const ViewBatches& batches, const CameraMatrices& cam, bool ghost_arrows) {
  mesh_program_.use();
  mesh_program_.set("u_view", cam.view);
  mesh_program_.set("u_proj", cam.proj);
  const glm::vec3 light_dir = kLightDir;
  mesh_program_.set("u_light_dir", light_dir);

  // Opaque pass.
  mesh_program_.set("u_specular", kOpaqueSpecular);
  cylinder_.upload(batches.arrow_shafts);
  cylinder_.draw();
  cone_.upload(batches.arrow_heads);
  cone_.draw();
  spheres_.draw(batches.spheres, cam.view, cam.proj, sphere_shading());

  if (ghost_arrows) {
    // The hidden parts of the arrows again, where something opaque lies in
    // front (depth test GREATER), blended faintly; their own back faces culled.
    constexpr float kGhostAlpha = 0.35f;
    auto faded = [&](std::vector<MeshInstance> v) {
      for (MeshInstance& m : v) m.color.a *= kGhostAlpha;
      return v;
    };
    mesh_program_.use();
    gl_.DepthMask(GL_FALSE);
    gl_.DepthFunc(GL_GREATER);
    gl_.Enable(GL_CULL_FACE);
    gl_.CullFace(GL_BACK);
    cylinder_.upload(faded(batches.arrow_shafts));
    cylinder_.draw();
    cone_.upload(faded(batches.arrow_heads));
    cone_.draw();
    gl_.Disable(GL_CULL_FACE);
    gl_.DepthFunc(GL_LEQUAL);
    gl_.DepthMask(GL_TRUE);
  }

  // Translucent boxes: no depth writes; inner (back) faces first, then the
  // outer faces, which is exact for one convex box and close enough for few.
  if (batches.boxes.empty()) return;
  mesh_program_.use();
  mesh_program_.set("u_specular", 0.18f);
  gl_.DepthMask(GL_FALSE);
  gl_.Enable(GL_CULL_FACE);
  cube_.upload(batches.boxes);
  gl_.CullFace(GL_FRONT);
  cube_.draw();
  gl_.CullFace(GL_BACK);
  cube_.draw();
  gl_.Disable(GL_CULL_FACE);
  gl_.DepthMask(GL_TRUE);
}

void Renderer::Impl::draw_text(const std::vector<viz::TextItem>& items, const PixelRect& rect) {
  std::vector<TextVertex> quads;
  for (const viz::TextItem& t : items) {
    if (t.backdrop.a > 0) font_.rect(t.backdrop_px, t.backdrop, quads);
    const float size = compose::fitted_text_px(t, static_cast<float>(rect.width), viz::text_width(t.text, t.size_px));
    font_.layout(t.text, t.position_px, size, t.color, quads);
  }
  if (quads.empty()) return;
  gl_.Disable(GL_DEPTH_TEST);
  // For FXAA, text lowers the frame's alpha (everything else leaves it at 1):
  // FXAA leaves those pixels as the glyph atlas anti-aliased them.
  if (fxaa_) gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
  text_.draw(quads, {float(rect.width), float(rect.height)});
  if (fxaa_) gl_.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
}

}  // namespace tumble::render
