// The `plot` view kind: a strip chart of chosen series over the whole run
// (viz/strip_chart.hpp), drawn so far, with a playhead; its series named in
// their colours at its head. Its value axis covers the whole run, so every
// frame shares it.
#include <algorithm>
#include <cmath>

#include "compose/panel.hpp"
#include "compose/views/kinds.hpp"
#include "core/dynamics.hpp"
#include "scene/frame_clock.hpp"
#include "viz/palette.hpp"
#include "viz/strip_chart.hpp"
#include "viz/text_layout.hpp"

namespace tumble::compose {

namespace {

// How the plot shows each series of scene::plot_series_names(): its name in
// the key and its colour (viz/palette.hpp: principal components and angles
// take their axis' colour; the cloud-axis components, which are no principal
// axis, greys).
struct SeriesLook {
  const char* name;
  const char* shown;
  viz::Color color;
};
const std::vector<SeriesLook>& series_looks() {
  using viz::Meaning;
  static const std::vector<SeriesLook> looks = {
      {"w1", "\u03c9\u2081", viz::color_of(Meaning::axis1)},
      {"w2", "\u03c9\u2082", viz::color_of(Meaning::axis2)},
      {"w3", "\u03c9\u2083", viz::color_of(Meaning::axis3)},
      {"wbx", "\u03c9x (cloud axes)", {0.30f, 0.30f, 0.34f, 1}},
      {"wby", "\u03c9y (cloud axes)", {0.50f, 0.50f, 0.55f, 1}},
      {"wbz", "\u03c9z (cloud axes)", {0.68f, 0.68f, 0.72f, 1}},
      {"|w|", "|\u03c9|", viz::color_of(Meaning::omega)},
      {"energy_error", "\u0394E/E", viz::color_of(Meaning::ink)},
      {"axis1_L", "\u2220(e\u2081, L)", viz::color_of(Meaning::axis1)},
      {"axis2_L", "\u2220(e\u2082, L)", viz::color_of(Meaning::axis2)},
      {"axis3_L", "\u2220(e\u2083, L)", viz::color_of(Meaning::axis3)}};
  return looks;
}

const SeriesLook& series_look(const std::string& name) {
  for (const SeriesLook& l : series_looks())
    if (name == l.name) return l;
  return series_looks()[7];
}

// A plot of one body's run, or in a [compare] scene of every stepping run
// (the exact solution has no error to plot), one curve per run and series.
class PlotPanel : public Panel {
 public:
  PlotPanel(const PanelContext& ctx, std::size_t index)
      : ctx_(ctx), vc_(ctx.scene.render.explain.views[index]), body_(view_body(ctx, index)) {
    const bool compare = !ctx.scene.render.compare_methods.empty();
    for (std::size_t r = 0; r < ctx.runs.size() && (compare || r == 0); ++r)
      if (!compare || ctx.runs[r].label != "exact") runs_.push_back(r);
    double lo = 1e300, hi = -1e300;
    for (std::size_t r : runs_)
      for (const auto& states : ctx.runs[r].frames)
        for (const std::string& name : vc_.series) {
          const double v = value(name, r, states);
          if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
        }
    if (!(hi >= lo)) lo = -1, hi = 1;
    const double pad = 0.08 * std::max(hi - lo, 1e-12 + 1e-9 * std::abs(hi));
    lo_ = lo - pad, hi_ = hi + pad;
    if (vc_.y_range) lo_ = (*vc_.y_range)[0], hi_ = (*vc_.y_range)[1];  // the scene's own value axis
    if (vc_.y_range && vc_.y_log) lo_ = std::log10(lo_), hi_ = std::log10(hi_);
  }
  std::string name() const override { return "plot"; }
  void fit(glm::vec2 size) override { size_ = size; }

  viz::View content(long k) const override {
    viz::View v;
    if (runs_.empty()) return v;
    const scene::FrameClock& clock = ctx_.world.clock();
    viz::StripChartInput in;
    in.t0 = 0, in.t1 = ctx_.scene.simulation.duration, in.lo = lo_, in.hi = hi_;
    in.playhead = clock.time(k);
    in.log10 = vc_.y_log;
    in.direct_labels = ctx_.runs.size() > 1;
    for (const scene::SlowMotion& sm : ctx_.scene.render.explain.slow_motion)
      in.shaded.push_back({sm.start, sm.end, scene::speed_text(sm.time_scale)});
    in.frame_h = ctx_.frame_h;
    for (long j = 0; j <= k; ++j) in.times.push_back(clock.time(j));
    for (std::size_t r : runs_) {
      const scene::Run& run = ctx_.runs[r];
      const long kk = last_frame(run, k);
      for (const std::string& name : vc_.series) {
        const SeriesLook& look = series_look(name);
        viz::Series series{look.shown, {}, look.color};
        if (ctx_.runs.size() > 1)  // one curve per method, in its colour
          series = {vc_.series.size() > 1 ? run.label + " " + look.shown : run.label, {}, run_color(run)};
        for (long j = 0; j <= k; ++j)
          series.values.push_back(j <= kk ? value(name, r, run.frames[static_cast<std::size_t>(j)]) : std::nan(""));
        in.series.push_back(std::move(series));
      }
    }
    viz::build_strip_chart(v, in, int(size_.x), int(size_.y), viz::text_px(viz::TextRole::tick, ctx_.frame_h));
    return v;
  }

 private:
  const PanelContext& ctx_;
  const scene::ViewConfig& vc_;
  std::size_t body_;
  std::vector<std::size_t> runs_;  // the runs plotted
  double lo_ = -1, hi_ = 1;
  glm::vec2 size_{1, 1};

  // A series' value at a frame of run r; on a log scale log10 |value| (none at 0).
  double value(const std::string& name, std::size_t r, const std::vector<BodyState>& states) const {
    const double v = series_value(name, ctx_.scene.bodies[body_].model, states[body_], ctx_.runs[r].energy0[body_]);
    if (!vc_.y_log) return v;
    return std::abs(v) > 0 ? std::log10(std::abs(v)) : std::nan("");
  }
};

}  // namespace

double series_value(const std::string& name, const RigidBodyModel& m, const BodyState& s, double e0) {
  if (name == "w1" || name == "w2" || name == "w3") return omega_principal(m, s)[name[1] - '1'];
  if (name == "wbx" || name == "wby" || name == "wbz") return omega_body(m, s)[name[2] - 'x'];
  if (name == "|w|") return omega_world(m, s).norm();
  if (name == "energy_error") return (total_energy(m, s) - e0) / std::max(std::abs(e0), 1e-300);
  if (name.size() == 7 && name.rfind("axis", 0) == 0) return principal_axis_angles_to_L(s)[name[4] - '1'];
  return 0;
}

std::unique_ptr<Panel> make_plot(const PanelContext& ctx, std::size_t index) {
  return std::make_unique<PlotPanel>(ctx, index);
}

}  // namespace tumble::compose
