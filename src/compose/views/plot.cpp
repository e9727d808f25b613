// The `plot` view kind: a strip chart of chosen series over the whole run
// (viz/strip_chart.hpp), drawn so far, with a playhead; its series named in
// their colours at its head. Its value axis covers the whole run, so every
// frame shares it.
#include <algorithm>
#include <cmath>
#include <string>

#include "compose/panel.hpp"
#include "compose/views/kinds.hpp"
#include "core/observables.hpp"
#include "scene/events.hpp"
#include "scene/frame_clock.hpp"
#include "base/format.hpp"
#include "viz/palette.hpp"
#include "viz/strip_chart.hpp"
#include "viz/text_layout.hpp"

namespace tumble::compose {

namespace {

// How the plot shows each series (the components of the kPlotSeries rows of
// core/observables.hpp): its name in the key and its colour (viz/palette.hpp:
// principal components and angles take their axis' colour; the cloud-axis
// components, which are no principal axis, greys).
struct SeriesLook {
  std::string name;
  std::string shown;
  viz::Color color;
};

viz::Color hue_color(PlotHue hue, std::size_t component) {
  using viz::Meaning;
  static const viz::Color greys[] = {{0.30f, 0.30f, 0.34f, 1}, {0.50f, 0.50f, 0.55f, 1}, {0.68f, 0.68f, 0.72f, 1}};
  switch (hue) {
    case PlotHue::axes: return viz::color_of(static_cast<Meaning>(static_cast<int>(Meaning::axis1) + static_cast<int>(component)));
    case PlotHue::greys: return greys[component];
    case PlotHue::omega: return viz::color_of(Meaning::omega);
    case PlotHue::ink:
    case PlotHue::none: break;
  }
  return viz::color_of(Meaning::ink);
}

const SeriesLook& series_look(const std::string& name) {
  static const std::vector<SeriesLook> looks = [] {
    std::vector<SeriesLook> v;
    for (const Observable& o : observables())
      if (o.use & kPlotSeries)
        for (std::size_t i = 0; i < o.size; ++i) v.push_back({std::string(o.columns[i]), std::string(o.shown[i]), hue_color(o.hue, i)});
    return v;
  }();
  static const SeriesLook unknown{"", "?", viz::color_of(viz::Meaning::ink)};
  for (const SeriesLook& l : looks)
    if (name == l.name) return l;
  return unknown;  // the scene loader lets no other name through
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
    if (vc_.energy_levels && !runs_.empty())
      levels_ = energy_levels(ctx.scene.bodies[body_], ctx.runs[runs_[0]].energy0[body_], vc_.y_log);
    if (vc_.y_log && levels_.size() > 1) points_ = crossings(levels_[1].value);  // the separatrix, when the start is under it
    if (compare && ctx.scene.render.explain.flip_marks)  // a comparison's flips, marked on the time axis too
      marks_ = scene::body_flip_times(ctx.scene, *ctx.scene.render.explain.flip_marks);
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
      if (vc_.shade_speeds) in.shaded.push_back({sm.start, sm.end, scene::speed_text(sm.time_scale)});
    in.marks = marks_;
    in.levels = levels_;
    in.points = points_;
    in.percent = !vc_.y_log && std::all_of(vc_.series.begin(), vc_.series.end(), [](const std::string& n) { return n == "energy_error"; });
    in.frame_h = ctx_.frame_h;
    in.text_scale = ctx_.text_scale();
    for (long j = 0; j <= k; ++j) in.times.push_back(clock.time(j));
    for (std::size_t r : runs_) {
      const scene::Run& run = ctx_.runs[r];
      const long kk = last_frame(run, k);
      for (const std::string& name : vc_.series) {
        const SeriesLook& look = series_look(name);
        viz::Series series{look.shown, {}, look.color};
        if (ctx_.runs.size() > 1)  // one curve per method, in its colour
          series = {vc_.series.size() > 1 ? short_title(run) + " " + look.shown : short_title(run), {}, run_color(run)};
        for (long j = 0; j <= k; ++j)
          series.values.push_back(j <= kk ? value(name, r, run.frames[static_cast<std::size_t>(j)]) : std::nan(""));
        in.series.push_back(std::move(series));
      }
    }
    viz::build_strip_chart(v, in, int(size_.x), int(size_.y), viz::text_px(viz::TextRole::tick, ctx_.frame_h, ctx_.text_scale()));
    return v;
  }

 private:
  const PanelContext& ctx_;
  const scene::ViewConfig& vc_;
  std::size_t body_;
  std::vector<std::size_t> runs_;  // the runs plotted
  double lo_ = -1, hi_ = 1;
  std::vector<double> marks_;  // s: the flips' times ([draw] flips)
  std::vector<viz::StripChartInput::Level> levels_;  // energy_levels: L²/2I₁, L²/2I₂, L²/2I₃ as ΔE/E
  std::vector<viz::StripChartInput::Point> points_;  // where a run's energy error first crosses the separatrix
  glm::vec2 size_{1, 1};

  // Each run's first crossing of `level` upwards (energy_error on a log
  // scale): the frame where its energy leaves the start's side of the
  // separatrix, the time between two frames by linear interpolation.
  std::vector<viz::StripChartInput::Point> crossings(double level) const {
    std::vector<viz::StripChartInput::Point> out;
    const scene::FrameClock& clock = ctx_.world.clock();
    if (std::find(vc_.series.begin(), vc_.series.end(), "energy_error") == vc_.series.end()) return out;
    for (std::size_t r : runs_) {
      const scene::Run& run = ctx_.runs[r];
      double prev = std::nan("");
      for (std::size_t j = 0; j < run.frames.size() && static_cast<long>(j) < clock.count(); ++j) {
        const double v = value("energy_error", r, run.frames[j]);
        if (std::isfinite(prev) && prev < level && v >= level) {
          const double t0 = clock.time(long(j) - 1), t1 = clock.time(long(j));
          const double t = t0 + (t1 - t0) * (level - prev) / (v - prev);
          out.push_back({t, level, "crosses it, " + format_number(t, 2) + " s", run_color(run)});
          break;
        }
        prev = v;
      }
    }
    return out;
  }

  // A series' value at a frame of run r; on a log scale log10 |value| (none at 0).
  double value(const std::string& name, std::size_t r, const std::vector<BodyState>& states) const {
    const double v = series_value(name, ctx_.scene.bodies[body_].model, states[body_], ctx_.runs[r].energy0[body_]);
    if (!vc_.y_log) return v;
    return std::abs(v) > 0 ? std::log10(std::abs(v)) : std::nan("");
  }
};

}  // namespace

double series_value(const std::string& name, const RigidBodyModel& m, const BodyState& s, double e0) {
  std::size_t i = 0;
  const Observable* o = find_column(name, &i);
  if (!o || !(o->use & kPlotSeries)) return 0;
  double v[kMaxComponents];
  o->value(m, s, e0, v);
  return v[i];
}

// The energies a free body with the start's |L| can have at most and least,
// and at the separatrix (L²/2I₁, L²/2I₃; L²/2I₂), as ΔE/E of the start's
// energy E0 (its other terms, translation and potential, kept as they were).
std::string short_title(const scene::Run& run) {
  const std::string& t = run.title.empty() ? run.label : run.title;
  return t.substr(0, t.find(','));
}

std::vector<viz::StripChartInput::Level> energy_levels(const scene::Body& b, double e0, bool log10) {
  static const char* const kNotes[3] = {"pure e\u2081 spin", "separatrix", "pure e\u2083 spin"};
  const Eigen::Vector3d l_body = b.initial.q.conjugate() * b.initial.L;
  const double rot0 = 0.5 * l_body.cwiseProduct(l_body).dot(b.model.inv_inertia);
  std::vector<viz::StripChartInput::Level> out;
  for (int k = 0; k < 3; ++k) {
    const double v = (0.5 * b.initial.L.squaredNorm() * b.model.inv_inertia[k] - rot0) / std::max(std::abs(e0), 1e-300);
    if (!log10) out.push_back({v, viz::percent_text(v)});  // linear: the axis reads ΔE/E, in per cent
    else if (v > 1e-12)  // |ΔE/E|: a level below the start's (L²/2I₃) would read as one above
      // named along its line, by what it is and its value, not on the axis (an energy on a ΔE/E axis misreads)
      out.push_back({std::log10(v), "", kNotes[k] + std::string(", ") + (k == 0 ? viz::percent_text(v) : base::format_for_people(v, 1))});
  }
  return out;
}

std::unique_ptr<Panel> make_plot(const PanelContext& ctx, std::size_t index) {
  return std::make_unique<PlotPanel>(ctx, index);
}

}  // namespace tumble::compose
