// What is observed of a body, one row per quantity: its name, unit, frame,
// components (the CSV columns and plot series), how it is computed from the
// body's model and state, where it appears, and how a plot shows it. The
// trajectory CSV, `tumble simulate`'s CSV, the Python arrays and the plot
// view's series all read this table; a new observable is one row.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string_view>

#include "core/body.hpp"

namespace tumble {

/// The frame an observable's components are given in.
enum class ObservableFrame { scalar, world, cloud, principal };

/// Where an observable appears (bits of Observable::use).
enum ObservableUse : unsigned {
  kTrajectoryColumns = 1u << 0,  ///< the trajectory CSV (frames, goldens) and `tumble simulate`'s
  kSimulateColumns = 1u << 1,    ///< `tumble simulate`'s CSV only, after the trajectory's columns
  kPythonArray = 1u << 2,        ///< an array of tumble.Trajectory (and scene::Trajectory)
  kPlotSeries = 1u << 3,         ///< a series of the plot view, one per component
};

/// The colour family a plot draws an observable's components in (compose maps
/// it to viz's palette): principal axes' colours, greys for the cloud's axes,
/// ω's colour, or ink.
enum class PlotHue { none, axes, greys, omega, ink };

inline constexpr std::size_t kMaxComponents = 4;

struct Observable {
  std::string_view name;  ///< the Python array's name and the docs'
  std::string_view unit;  ///< SI: "m", "rad/s", "J", "1" (a ratio), "" (none: q)
  ObservableFrame frame;
  std::size_t size;                                   ///< components
  std::array<std::string_view, kMaxComponents> columns;  ///< per component: CSV column and plot series name
  unsigned use;                                       ///< ObservableUse bits
  /// The components of a body of model m in state s; e0 = its energy at t = 0 (J).
  void (*value)(const RigidBodyModel& m, const BodyState& s, double e0, double* out);
  PlotHue hue = PlotHue::none;
  std::array<std::string_view, kMaxComponents> shown = {};  ///< per component: the plot key's text
  std::string_view note = {};  ///< for people (Python's docstring): what the unit and frame do not say
};

/// Every observable, in CSV column order (the trajectory's, then simulate's)
/// and plot series order.
std::span<const Observable> observables();

/// The observable and component a column or series name stands for; nullptr when none.
const Observable* find_column(std::string_view column, std::size_t* component = nullptr);

}  // namespace tumble
