// The measurement behind kernel::split_order and split_order4
// (splitting_kernel.hpp): the orientation error at 10 s (dt = 1 ms) of each of
// the six symmetric sub-flow orders of `splitting` (argument 4: of the base map
// of `splitting4`), torque-free, against the closed form, on 18 bodies ×
// 5 spins; then how far from the best order per case the rule and each fixed
// order are (mean and worst log10 of error / best error). Built and run by
// scripts/splitting_order_study.sh.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/body.hpp"
#include "core/free_rotation_exact.hpp"
#include "core/splitting_kernel.hpp"

using namespace tumble;

int main(int argc, char** argv) {
  const bool fourth = argc > 1 && std::string(argv[1]) == "4";
  const double cbrt2 = std::cbrt(2.0), w1 = 1.0 / (2.0 - cbrt2), w0 = -cbrt2 * w1;
  const std::vector<Eigen::Vector3d> bodies = {
      {1, 2, 3},   {1, 1.1, 5},   {1, 4.9, 5}, {2, 3, 4.5},   {1, 1.5, 2},   {1, 3, 3.3},
      {1, 1.8, 2.2}, {0.2, 1, 1.1}, {1, 1.05, 2}, {1, 1.2, 5}, {1, 1.4, 5},   {1, 1.8, 5},
      {1, 2.6, 5}, {1, 1.2, 2},   {1, 1.3, 2}, {1, 1.1, 1.5}, {1, 1.3, 10},  {1, 2, 10}};
  std::vector<Eigen::Vector3d> spins;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d w = Eigen::Vector3d::Constant(0.01);  // near principal axis i
    w[i] = 10;
    spins.push_back(w);
  }
  spins.push_back({3, 7, -2});
  spins.push_back({5, 5, 5});
  const double dt = 1e-3, T = 10;
  const long n = std::lround(T / dt);
  double regret_rule = 0, worst_rule = 0, regret_fixed[6] = {}, worst_fixed[6] = {};
  int cases = 0, rule_best = 0;
  std::printf("moments, omega_body: error (rad) per order (outer middle inner, 1-based) | rule's order\n");
  for (const Eigen::Vector3d& I : bodies)
    for (const Eigen::Vector3d& w : spins) {
      const Eigen::Vector3d inv = I.cwiseInverse(), L = I.cwiseProduct(w);
      const Eigen::Quaterniond exact = FreeRotationExact(I, Eigen::Quaterniond::Identity(), L).orientation(T);
      double err[6];
      std::printf("(%g, %g, %g), (%g, %g, %g):", I.x(), I.y(), I.z(), w.x(), w.y(), w.z());
      for (int o = 0; o < 6; ++o) {
        kernel::Quat q{1, 0, 0, 0};
        for (long k = 0; k < n; ++k) {
          if (!fourth) {
            q = kernel::splitting_rotation_ordered(o, q, L.data(), inv.data(), dt);
            continue;
          }
          q = kernel::splitting_rotation_ordered(o, q, L.data(), inv.data(), w1 * dt);
          q = kernel::splitting_rotation_ordered(o, q, L.data(), inv.data(), w0 * dt);
          q = kernel::splitting_rotation_ordered(o, q, L.data(), inv.data(), w1 * dt);
        }
        err[o] = Eigen::Quaterniond(q.w, q.x, q.y, q.z).angularDistance(exact);
        const int* a = kernel::kSplitAxes[o];
        std::printf(" %d%d%d %.2e", a[0] + 1, a[1] + 1, a[2] + 1, err[o]);
      }
      const double best = *std::min_element(err, err + 6);
      const int rule = fourth ? kernel::split_order4(inv.data()) : kernel::split_order(inv.data());
      const double r = std::log10(err[rule] / best);
      regret_rule += r;
      worst_rule = std::max(worst_rule, r);
      rule_best += r == 0;
      for (int o = 0; o < 6; ++o) {
        regret_fixed[o] += std::log10(err[o] / best);
        worst_fixed[o] = std::max(worst_fixed[o], std::log10(err[o] / best));
      }
      ++cases;
      const int* a = kernel::kSplitAxes[rule];
      std::printf(" | %d%d%d\n", a[0] + 1, a[1] + 1, a[2] + 1);
    }
  std::printf("\nlog10(error / best order's error) over %d cases: mean, worst\n", cases);
  std::printf("rule (split_order%s) %.3f  %.2f  (best on %d)\n", fourth ? "4" : "", regret_rule / cases, worst_rule, rule_best);
  for (int o = 0; o < 6; ++o) {
    const int* a = kernel::kSplitAxes[o];
    std::printf("fixed %d%d%d%d%d       %.3f  %.2f\n", a[0] + 1, a[1] + 1, a[2] + 1, a[1] + 1, a[0] + 1,
                regret_fixed[o] / cases, worst_fixed[o]);
  }
}
