// tumble.render_frame and tumble.render: the render pipeline (src/run)
// headless. render_frame's pixels are those `tumble render --frames k:k`
// writes; render() is `tumble render` into a folder.
#include <csignal>
#include <iostream>
#include <memory>
#include <optional>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#ifdef TUMBLE_HAVE_RENDER
#include "io/atomic_file.hpp"
#include "run/frame_renderer.hpp"
#include "run/render_folder.hpp"
#include "scene/frame_clock.hpp"
#endif

namespace tumble::py_bind {

#ifdef TUMBLE_HAVE_RENDER
namespace {

/// The frame index of simulated time `t` (s) or of `frame`, one of them given.
long frame_index(const scene::Scene& s, std::optional<double> t, std::optional<long> frame) {
  if (t.has_value() == frame.has_value()) throw InputError("render_frame: give t (s) or frame (index), one of them");
  if (frame) return *frame;
  const scene::FrameClock clock = scene::frame_clock(s, s.render.output.fps);
  const long k = clock.frame_at(*t);
  if (k < 0)
    throw InputError("render_frame: t = " + std::to_string(*t) + " s is not a frame time (frames at k/fps, fps = " +
                     std::to_string(s.render.output.fps) + "); give frame=k");
  return k;
}

/// The scene's frame settings with the call's size and anti-aliasing, checked as the options are.
scene::FrameSettings frame_settings(const scene::Scene& s, std::optional<int> width, std::optional<int> height,
                                    const std::optional<std::string>& aa) {
  scene::FrameSettings f = s.render.output;
  f.width = width.value_or(f.width);
  f.height = height.value_or(f.height);
  for (int v : {f.width, f.height})
    if (v < scene::kMinFramePx || v > scene::kMaxFramePx)
      throw InputError("width and height: expected " + std::to_string(scene::kMinFramePx) + ".." +
                       std::to_string(scene::kMaxFramePx) + " px, found " + std::to_string(v));
  if (aa && !scene::parse_aa_case(*aa, f))
    throw InputError("aa: expected " + scene::aa_case_choices() + ", found '" + *aa + "'");
  return f;
}

render::GlBackend backend(const std::string& gl) {
  try {
    return gl.empty() ? render::default_gl_backend() : render::parse_gl_backend(gl);
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("gl: ") + e.what());
  }
}

/// An (H, W, 3) uint8 array owning the image's bytes (moved, not copied).
py::array_t<std::uint8_t> image_array(io::Image&& img) {
  auto* owned = new std::vector<std::uint8_t>(std::move(img.rgb));
  py::capsule free_when_done(owned, [](void* p) { delete static_cast<std::vector<std::uint8_t>*>(p); });
  return py::array_t<std::uint8_t>({img.height, img.width, 3}, owned->data(), free_when_done);
}

/// The pipeline's listener for Python: notes to stderr as the CLI's, and Ctrl-C
/// (Python's pending KeyboardInterrupt) as the stop request between frames.
class PyListener : public run::Listener {
 public:
  void note(const std::string& line) override {
    py::gil_scoped_acquire gil;
    py::print("tumble: " + line, py::arg("file") = py::module_::import("sys").attr("stderr"));
  }
  void begin(long, const std::string&) override {}
  void advance(long) override {}
  void end() override {}
  void arm_stop() override {}
  int stop() const override {
    if (error_) return SIGINT;
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() == 0) return 0;
    error_ = std::make_unique<py::error_already_set>();  // takes the KeyboardInterrupt
    return SIGINT;
  }
  /// Raises what stop() took, if anything.
  void rethrow() {
    if (error_) throw std::move(*error_);
  }

 private:
  mutable std::unique_ptr<py::error_already_set> error_;
};

}  // namespace

void add_render(py::module_& m) {
  m.def(
      "render_frame",
      [](const scene::Scene& s, std::optional<double> t, std::optional<long> frame, std::optional<int> width,
         std::optional<int> height, const std::optional<std::string>& aa, const std::string& gl) {
        const long k = frame_index(s, t, frame);
        const scene::FrameSettings f = frame_settings(s, width, height, aa);
        const render::GlBackend b = backend(gl);
        std::vector<io::Image> images;
        {
          py::gil_scoped_release nogil;
          const std::unique_ptr<render::GlContext> ctx = render::create_gl_context(b);
          const run::SceneFrames frames(s, k);
          check_signals();
          images = frames.render(*ctx, {k}, f);
        }
        return image_array(std::move(images.at(0)));
      },
      py::arg("scene"), py::arg("t") = py::none(), py::kw_only(), py::arg("frame") = py::none(),
      py::arg("width") = py::none(), py::arg("height") = py::none(), py::arg("aa") = py::none(), py::arg("gl") = "",
      "Renders the frame showing simulated time t (s), or frame index `frame`, headless: an (H, W, 3) uint8 "
      "array, the pixels of `tumble render`'s PNG of that frame. width, height default to the scene's; aa: "
      "'fxaa', 'none', 'msaa2', 'msaa4'; gl: 'osmesa' or 'egl' (default: env TUMBLE_GL, else osmesa).");

  m.def(
      "render",
      [](const scene::Scene& s, const std::filesystem::path& out_dir, const std::string& frames,
         std::optional<int> width, std::optional<int> height, const std::optional<std::string>& aa,
         const std::optional<std::string>& video, bool resume, bool force, const std::string& gl) {
        scene::Scene copy = s;  // the request's scene holds the options
        static_cast<scene::FrameSettings&>(copy.render.output) = frame_settings(s, width, height, aa);
        if (video) {
          const auto v = scene::parse_video_format(*video);
          if (!v) throw InputError("video: expected " + scene::video_format_choices() + ", found '" + *video + "'");
          copy.render.output.video = *v;
        }
        const run::RenderRequest req{copy, out_dir, frames, resume, force, false, backend(gl), copy.path.string()};
        PyListener listener;
        run::Outcome outcome;
        {
          py::gil_scoped_release nogil;
          outcome = run::render_scene(req, listener);
        }
        listener.rethrow();
        if (outcome.kind == run::Outcome::failed) throw io::IoError(outcome.summary);
        if (outcome.kind == run::Outcome::diverged) throw Diverged(outcome.summary, 0, 0);
        return outcome.summary;
      },
      py::arg("scene"), py::arg("out_dir"), py::kw_only(), py::arg("frames") = "", py::arg("width") = py::none(),
      py::arg("height") = py::none(), py::arg("aa") = py::none(), py::arg("video") = py::none(),
      py::arg("resume") = false, py::arg("force") = false, py::arg("gl") = "",
      "Does what `tumble render` does: frames (PNG), manifest.json and the video (video='mp4', 'gif' or 'none') in "
      "out_dir; frames='A:B' renders a range. Returns the summary line. Ctrl-C stops between frames "
      "(KeyboardInterrupt; the folder says incomplete, resume=True goes on).");
}
#else
void add_render(py::module_&) {}
#endif

}  // namespace tumble::py_bind
