// The makers of the view kinds, one file each (compose/views/*.cpp), and what
// they share; the table kViewKinds (view_kinds.cpp) names each kind's maker.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compose/panel.hpp"
#include "viz/strip_chart.hpp"

namespace tumble::compose {

std::unique_ptr<Panel> make_world(const PanelContext& ctx, std::size_t index);
std::unique_ptr<Panel> make_body_frame(const PanelContext& ctx, std::size_t index);
std::unique_ptr<Panel> make_momentum_sphere(const PanelContext& ctx, std::size_t index);
std::unique_ptr<Panel> make_plot(const PanelContext& ctx, std::size_t index);
std::unique_ptr<Panel> make_poinsot(const PanelContext& ctx, std::size_t index);

/// The key of a view of bodies: axes, L and ω as drawn, then each body (or `only` that one) by name.
/// `arrows`: arrows keyed by arrow swatches, trails by faded lines (viz::bodies_key).
std::vector<viz::KeyEntry> bodies_key(const PanelContext& ctx, std::optional<std::size_t> only, bool arrows = false);
/// A body's colour as its key entry (and a path drawn for it) shows it: its surface colour, darkened.
viz::Color body_key_color(const scene::Body& b);
/// The key entry of the box outline drawn around a surface (none when no such box is drawn).
std::optional<viz::KeyEntry> box_key(const PanelContext& ctx);

/// The energies a free body with `b`'s starting |L| can have: L²/2I₁ (a pure e₁ spin, the most), L²/2I₂ (the
/// separatrix), L²/2I₃ (a pure e₃ spin, the least), as ΔE/E of the start's energy `e0` (J); log10: log10 |ΔE/E|.
std::vector<viz::StripChartInput::Level> energy_levels(const scene::Body& b, double e0, bool log10);

/// Value of plot series `name` (scene::plot_series_names) for body `m` in state `s`; `e0` = energy at t = 0 (J).
double series_value(const std::string& name, const RigidBodyModel& m, const BodyState& s, double e0);

/// A method's colour in a comparison (its cell's title and readout, its plot
/// curve): none of the axes', L's or ω's; ink for the exact solution and others.
viz::Color run_color(const scene::Run& run);

/// A run's name as its cell titles it, less the order ("explicit Euler, order 1" -> "explicit Euler"):
/// a plot's curve, a sphere's path and the cell then read alike.
std::string short_title(const scene::Run& run);

/// The index of the body `[[views]]` table `index` names (the first when it names none).
std::size_t view_body(const PanelContext& ctx, std::size_t index);

}  // namespace tumble::compose
