// Dzhanibekov flips of the closed-form solution: the reference for the flip
// counts of the stability map and the first-flip study.
#pragma once

#include <vector>

#include "core/body.hpp"

namespace tumble::bench {

/// Times (s) where Π₂ of the exact torque-free motion changes sign in [0, t_max],
/// located by dense sampling (2000 samples per body period).
std::vector<double> exact_flip_times(const RigidBodyModel& m, const BodyState& s0, double t_max);

/// A duration near `target` (s) that ends midway between two exact flips, so a
/// small phase error cannot change the flip count.
double mid_flip_duration(const std::vector<double>& flips, double target);

}  // namespace tumble::bench
