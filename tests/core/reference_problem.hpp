// The reference problem: principal moments exactly (1, 2, 3) kg·m²,
// identity orientation, ω_body = (0.01, 10, 0.01) rad/s, no forces, 10 s.
#pragma once

#include "core/body.hpp"
#include "core/mass_properties.hpp"

namespace tumble::testing {

/// 1 kg at (±1, 0, 0) m and 0.5 kg at (0, ±1, 0) m: J = diag(1, 2, 3) exactly.
inline ParticleCloud reference_cloud() {
  return {{{1, 0, 0}, 1.0}, {{-1, 0, 0}, 1.0}, {{0, 1, 0}, 0.5}, {{0, -1, 0}, 0.5}};
}

inline RigidBodyModel reference_model() {
  return make_model("reference", compute_mass_properties(reference_cloud(), "reference"), ForceSet{});
}

inline BodyState reference_state(const RigidBodyModel& m) {
  InitialConditions ic;
  ic.omega = {0.01, 10, 0.01};
  return make_state(m, ic);
}

}  // namespace tumble::testing
