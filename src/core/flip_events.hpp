// Dzhanibekov flips found from the motion itself, so explanatory videos can
// anchor their text to them: flip N is the N-th time the
// intermediate principal axis e₂ is perpendicular to L, i.e. the body-frame
// momentum Π₂ = e₂·L changes sign (axis2_L crosses π/2), on a swing where e₂
// turns over: |Π₂| reaches |L|/√2 (e₂ within 45° of ±L) before or after the
// crossing. A spin near e₁ or e₃ also takes e₂ across ⊥ L, twice per wobble,
// but e₂ stays near ⊥ L: that is no flip.
#pragma once

#include <functional>
#include <vector>

#include "core/body.hpp"
#include "core/propagator.hpp"

namespace tumble {

/// Times in (t0, t1] where `f` changes sign: bracketed between samples `dt`
/// apart, then bisected to 1e-12 relative. Exact zeros do not count as a sign,
/// so a function that stays 0 (a pure spin about e₁ or e₃) has none. Sign
/// changes closer together than `dt` can be missed in pairs.
std::vector<double> sign_change_times(const std::function<double(double)>& f, double t0, double t1, double dt);

/// Flip times (s) in (0, t_max] of a body started at `s0` (see above).
/// Torque-free: the closed form (FreeRotationExact), sampled 64 times per body
/// period. With torques: the body stepped by `cfg` and sampled every
/// min(dt, 1 ms), each bracket bisected by stepping again from its left end.
std::vector<double> flip_times(const RigidBodyModel& m, const BodyState& s0, const StepConfig& cfg, double t_max);

}  // namespace tumble
