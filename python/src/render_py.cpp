// tumble.render_frame and tumble.render: the render pipeline (src/run)
// headless. render_frame's pixels are those `tumble render --frames k:k`
// writes; render() is `tumble render` into a folder.
#include <algorithm>
#include <cmath>
#include <csignal>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#ifdef TUMBLE_HAVE_RENDER
#include "base/format.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "render/resource_dir.hpp"
#include "run/frame_renderer.hpp"
#include "run/render_folder.hpp"
#include "scene/frame_clock.hpp"
#endif

namespace tumble::py_bind {

#ifdef TUMBLE_HAVE_RENDER
namespace {

/// A Python string literal of `s` (single quotes, backslashes and quotes escaped).
std::string py_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += (c == '\\' || c == '\'') ? std::string("\\") + c : std::string(1, c);
  return out + "'";
}

/// The scene file's hash and everything Python may have edited since: what a
/// render folder records as its scene, so a resume continues only this scene.
std::string edited_hash(const scene::Scene& s) {
  std::ostringstream o;
  o.precision(17);
  o << s.content_hash << "|python";
  for (const scene::Body& b : s.bodies) {
    const InitialConditions& ic = b.initial_conditions;
    o << '|' << b.name << ' ' << ic.position.transpose() << ' ' << ic.velocity.transpose() << ' '
      << ic.orientation.coeffs().transpose() << ' ' << ic.omega.transpose() << ' ' << static_cast<int>(ic.omega_frame)
      << ' ' << b.color.transpose();
  }
  const scene::SimulationConfig& sim = s.simulation;
  o << '|' << sim.automatic << ' ' << method_name(sim.step.method) << ' ' << sim.step.dt << ' ' << sim.duration << ' '
    << sim.fps << ' ' << sim.step.rtol << ' ' << sim.step.atol << ' ' << sim.tolerance.value_or(0) << ' '
    << s.render.explain.time_scale;
  return scene::fnv1a_hex(o.str());
}

/// The call that runs a render again, from the command line's flags for it
/// (" --frames A:B", " --resume", " --frames-out none").
std::string python_rerun(const std::string& dir, const std::string& flags) {
  std::istringstream in(flags);
  std::string args = "tumble.render(scene, " + py_quote(dir), flag;
  while (in >> flag) {
    if (flag == "--resume") args += ", resume=True";
    else if (flag == "--force") args += ", force=True";
    else if (flag == "--frames" && in >> flag) args += ", frames=" + py_quote(flag);
    else if (flag == "--frames-out" && in >> flag) continue;  // Python keeps the frames
  }
  return args + ") with this same scene object, edits and all";
}

/// The frame index of `frame`, or of the frame nearest to simulated time `t`
/// (s; the one whose shown time is closest), one of them given, in range.
long frame_index(const scene::Scene& s, std::optional<double> t, std::optional<long> frame) {
  if (t.has_value() == frame.has_value())
    throw InputError("tumble.render_frame(): error: give t= (s) or frame= (an index), one of them");
  const scene::FrameClock clock = scene::frame_clock(s, s.render.output.fps);
  const long last = clock.count() - 1;
  const std::string frames = std::to_string(clock.count()) + " frames at " + format_number(clock.fps()) + " fps";
  if (frame) {
    if (*frame < 0 || *frame > last)
      throw InputError("tumble.render_frame(frame=" + std::to_string(*frame) + "): error: expected a frame index in 0.." +
                       std::to_string(last) + " (" + frames + ")");
    return *frame;
  }
  const double duration = s.simulation.duration;
  if (!(*t >= 0 && *t <= duration * (1 + 1e-12)))
    throw InputError("tumble.render_frame(t=" + format_number(*t) + "): error: expected a time in [0, " +
                     format_number(duration) + "] s, the scene's duration");
  if (const long k = clock.frame_at(*t); k >= 0) return k;
  const long k = std::clamp(std::lround(clock.video_time(*t) * clock.fps()), 0L, last);
  // The neighbour that shows the time closest to t.
  long best = k;
  for (long j : {k - 1, k + 1})
    if (j >= 0 && j <= last && std::abs(clock.time(j) - *t) < std::abs(clock.time(best) - *t)) best = j;
  return best;
}

/// The scene's frame settings with the call's size and anti-aliasing (and
/// video), read by the scene loader as --width, --height, --aa, --msaa are.
scene::OutputConfig frame_settings(const scene::Scene& s, const char* call, std::optional<int> width,
                                   std::optional<int> height, const std::optional<std::string>& aa,
                                   const std::optional<std::string>& video = std::nullopt) {
  std::vector<scene::Override> o;
  if (width) o.push_back(arg_override(call, "width", "output.width", static_cast<long long>(*width)));
  if (height) o.push_back(arg_override(call, "height", "output.height", static_cast<long long>(*height)));
  if (aa) {
    // 'msaa2', 'msaa4' (and 'msaa0', as golden files name it): msaa with that many samples.
    const bool samples = aa->size() == 5 && aa->rfind("msaa", 0) == 0;
    const bool none = *aa == "msaa0";
    o.push_back(arg_override(call, "aa", "output.aa", samples ? std::string(none ? "none" : "msaa") : *aa));
    if (samples && !none) o.push_back(arg_override(call, "aa", "output.msaa", static_cast<long long>((*aa)[4] - '0')));
  }
  if (video) o.push_back(arg_override(call, "video", "output.video", *video));
  return scene::override_settings(s, o, std::string("tumble.") + call + "()").output;
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

/// tumble.resources and tumble.render.
static void add_render_folder(py::module_& m) {
  m.def(
      "resources",
      [] {
        const std::filesystem::path dir = render::find_resource_dir();
        py::dict d;
        d["shaders"] = (dir / "shaders").string();
        d["font"] = render::find_font_file(dir).string();
        return d;
      },
      "Where the renderer finds its shaders and font: {'shaders': folder, 'font': file}. An installed module "
      "(cmake --install) carries its shaders beside it, so this holds from any folder.");

  m.def(
      "render",
      [](const scene::Scene& s, const std::filesystem::path& out_dir, const std::string& frames,
         std::optional<int> width, std::optional<int> height, const std::optional<std::string>& aa,
         const std::optional<std::string>& video, bool resume, bool force, const std::string& gl) {
        scene::Scene copy = s;  // the request's scene holds the options
        copy.render.output = frame_settings(s, "render", width, height, aa, video);
        // The folder's scene hash covers the Python edits: a resume continues only this scene, as edited.
        copy.content_hash = edited_hash(copy);
        run::RenderRequest req{copy, out_dir, frames, resume, force, false, backend(gl), copy.path.string()};
        req.rerun = [dir = out_dir.string()](const std::string& flags) { return python_rerun(dir, flags); };
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
      "(KeyboardInterrupt; the folder says incomplete): the same call with resume=True on the same scene, edits "
      "and all, goes on. The folder's scene hash covers the Python edits, so a resume with other edits, or "
      "`tumble render --resume` on the unedited file, is refused rather than mixing frames.");
}

void add_render(py::module_& m) {
  m.def(
      "render_frame",
      [](const scene::Scene& s, std::optional<double> t, std::optional<long> frame, std::optional<int> width,
         std::optional<int> height, const std::optional<std::string>& aa, const std::string& gl) {
        const long k = frame_index(s, t, frame);
        const scene::FrameSettings f = frame_settings(s, "render_frame", width, height, aa);
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
      "Renders frame index `frame`, or the frame nearest to simulated time t (s, any time in [0, duration]: the "
      "frame whose shown time is closest, k = round(t·fps) in a plain scene), headless: an (H, W, 3) uint8 array, "
      "the pixels of `tumble render`'s PNG of that frame. width, height default to the scene's; aa: 'fxaa', "
      "'none', 'msaa' (the scene's samples), 'msaa2', 'msaa4'; gl: 'osmesa' or 'egl' (default: env TUMBLE_GL, "
      "else osmesa). Sizes and aa are checked by the scene loader as --width, --height, --aa are.");

  add_render_folder(m);
}
#else
void add_render(py::module_&) {}
#endif

}  // namespace tumble::py_bind
