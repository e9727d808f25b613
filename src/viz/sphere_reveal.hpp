// The momentum sphere built up step by step, as a lecturer draws it: the
// sphere |Π| = |L| (|L| conserved) with Π on it, then the energy ellipsoid
// Σ Π_i²/I_i = 2E (E conserved), then the curves where the two meet (the
// polhodes, which Π must follow), and last the separatrix through ±e₂.
#pragma once

#include <array>
#include <optional>

namespace tumble::viz {

/// What the sphere shows so far (all of it once the build-up is over).
struct SphereReveal {
  bool curves = true;      ///< the level curves (polhodes) of other energies and Π's own
  bool separatrix = true;  ///< the separatrix and its saddles ±e₂
  /// Π's whole polhode even where the view draws only its path so far (a
  /// trail): during the build-up, from the curves' step, before Π has moved.
  bool whole_polhode = false;
  /// The build-up's share of the energy ellipsoid's opacity, 0 … 1 (faded in
  /// at its step, out after the last); none: the view's own setting.
  std::optional<float> ellipsoid;
};

/// Video s over which the ellipsoid fades in at its step, and out after the build-up.
inline constexpr double kRevealFadeSeconds = 0.8;

/// The reveal `since` video s after the build-up starts, its four steps
/// (sphere, ellipsoid, curves, separatrix) lasting `seconds` each. Before the
/// start (since < 0) only the sphere shows; past the end, everything, the
/// ellipsoid fading out (`keep_ellipsoid`: staying) to the view's own setting.
SphereReveal sphere_reveal(double since, const std::array<double, 4>& seconds, bool keep_ellipsoid = false);

}  // namespace tumble::viz
