// One colour per meaning, in every view and in the plot (docs/colours.md
// holds the same table for readers; tests/viz/palette_test checks they agree).
// The principal axes follow the moments' order in Okabe & Ito's (2008)
// colour-blind-safe hues: e₁ (smallest moment) vermillion, e₂ bluish green,
// e₃ blue, which differ under every simulated deficiency as red and green did
// not; drawn arrows also carry their names at their tips, so colour is never
// the only key. L is black, the fixed vector of every figure, and Π, which is
// L seen from the body, takes its colour. docs/colours.md gives the simulated
// colour-blind differences (scripts/colour_blind_check.py).
#pragma once

#include <array>
#include <string_view>

#include "viz/draw_list.hpp"

namespace tumble::viz {

enum class Meaning {
  axis1, axis2, axis3,   ///< principal axes e₁, e₂, e₃ (I₁ < I₂ < I₃) and ω₁, ω₂, ω₃ in the plot
  L,                     ///< angular momentum (world), and the invariable plane's normal
  omega,                 ///< angular velocity ω
  momentum_point,        ///< Π = Rᵀ L on the momentum sphere: L's colour
  polhode,               ///< this body's polhode (and its energy ellipsoid)
  herpolhode,            ///< ω's tip on the invariable plane
  separatrix,            ///< the level 2E = |L|²/I₂ through ±e₂
  other_levels,          ///< polhodes of other energies
  plane,                 ///< the invariable plane
  ellipsoid,             ///< Poinsot's inertia ellipsoid
  energy_ellipsoid,      ///< the energy ellipsoid on the momentum sphere
  ink,                   ///< text, frames, playhead
  count
};

struct MeaningColor {
  Meaning meaning;
  std::string_view name;      ///< as in docs/colours.md
  std::string_view colour;    ///< the colour's common name
  Color rgba;
};

/// The table, in Meaning order.
inline const std::array<MeaningColor, static_cast<std::size_t>(Meaning::count)> kPalette = {{
    {Meaning::axis1, "e1", "vermillion", {0.84f, 0.37f, 0.0f, 1}},
    {Meaning::axis2, "e2", "bluish green", {0.0f, 0.62f, 0.45f, 1}},
    {Meaning::axis3, "e3", "blue", {0.10f, 0.35f, 0.85f, 1}},
    {Meaning::L, "L", "black", {0.05f, 0.05f, 0.07f, 1}},
    {Meaning::omega, "omega", "purple", {0.60f, 0.20f, 0.75f, 1}},
    {Meaning::momentum_point, "momentum_point", "black", {0.05f, 0.05f, 0.07f, 1}},
    {Meaning::polhode, "polhode", "crimson", {0.85f, 0.10f, 0.25f, 1}},
    {Meaning::herpolhode, "herpolhode", "dark brown", {0.42f, 0.24f, 0.04f, 1}},
    {Meaning::separatrix, "separatrix", "sky blue", {0.34f, 0.71f, 0.91f, 1}},
    {Meaning::other_levels, "other_levels", "light grey", {0.55f, 0.56f, 0.60f, 1}},
    {Meaning::plane, "plane", "grey", {0.45f, 0.47f, 0.52f, 1}},
    {Meaning::ellipsoid, "ellipsoid", "slate", {0.38f, 0.44f, 0.62f, 1}},
    {Meaning::energy_ellipsoid, "energy_ellipsoid", "yellow", {0.93f, 0.78f, 0.18f, 1}},
    {Meaning::ink, "ink", "near-black", {0.12f, 0.13f, 0.16f, 1}},
}};

/// The colour of `m`, with opacity `alpha`.
inline Color color_of(Meaning m, float alpha = 1.0f) {
  Color c = kPalette[static_cast<std::size_t>(m)].rgba;
  c.a = alpha;
  return c;
}

}  // namespace tumble::viz
