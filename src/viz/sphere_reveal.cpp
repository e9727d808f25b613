#include "viz/sphere_reveal.hpp"

#include <algorithm>

namespace tumble::viz {

SphereReveal sphere_reveal(double since, const std::array<double, 4>& seconds, bool keep_ellipsoid) {
  const double ellipsoid_at = seconds[0], curves_at = ellipsoid_at + seconds[1], separatrix_at = curves_at + seconds[2];
  const double end = separatrix_at + seconds[3];
  SphereReveal r;
  r.curves = since >= curves_at;
  r.separatrix = since >= separatrix_at;
  r.whole_polhode = r.curves && since < end;
  const double in = (since - ellipsoid_at) / kRevealFadeSeconds;
  const double out = keep_ellipsoid ? 1 : 1 - (since - end) / kRevealFadeSeconds;
  if (since < end + (keep_ellipsoid ? 0 : kRevealFadeSeconds))
    r.ellipsoid = static_cast<float>(std::clamp(std::min(in, out), 0.0, 1.0));
  return r;
}

}  // namespace tumble::viz
