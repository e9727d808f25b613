// The measurement behind kernel::split_order and split_order4
// (splitting_kernel.hpp): the orientation error at 10 s (dt = 1 ms) of each of
// the six symmetric sub-flow orders of `splitting` (argument 4: of the base map
// of `splitting4`), torque-free, against the closed form, on 18 bodies × 62
// spins: the old 5 (10 rad/s near each principal axis, two generic), 21 that
// start 0.2°–7° from the intermediate axis (three directions each), and 36 that
// cover both orbit regions of the momentum sphere (Fassò, J. Comput. Phys. 189,
// 2003): circulation about the smallest-moment axis (ρ = |L|²/(2E I_mid) < 1)
// and about the largest (ρ > 1), six orbits each from near the axis to 1e-6
// from the separatrix, each from three start points. Then how far from the
// best order per case the rule and each fixed order are (mean and worst log10
// of error / best error), and oracles: the best single order per body (the most
// any rule that reads only the moments can reach), per body and orbit region,
// and per body and whether Π starts at the intermediate axis (the saddle);
// for `splitting` also an alternative rule for starts off the saddle, the
// order chosen each step from the current Π (the rule near the saddle, the
// alternative elsewhere), the order a run fixes at its start
// (kernel::split_order_for_start), and the rule against the alternative by
// the start's angle from the intermediate axis.
// Arguments (any order): `4`, `max` (the worst error at t = 1, 2, ..., 10 s,
// which no lucky cancellation at 10 s hides, instead of the error at 10 s) and
// `csv` (one row per case instead of the summary).
// Run by scripts/splitting_order_study.sh (the target tumble_splitting_order_study).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/body.hpp"
#include "core/methods/free_rotation_exact.hpp"
#include "core/methods/splitting_kernel.hpp"

using namespace tumble;

namespace {

/// Body momentum Π (|ω_body| = 10 rad/s) on the orbit with ρ = |L|²/(2E I_mid)
/// = rho, at phase alpha: Π_mid² = alpha × its largest value on that orbit
/// (near the separatrix, alpha → 1 starts next to the intermediate axis).
Eigen::Vector3d momentum_on_orbit(const Eigen::Vector3d& I, double rho, double alpha) {
  const Eigen::Vector3d a = I.cwiseInverse();  // a0 > a1 > a2
  const double e = a[1] / rho;                 // 2E/|Π|² for |Π| = 1
  // Largest Π_mid² on the orbit: where it crosses the plane of the mid axis
  // and the axis it circulates about.
  const double mid_max = rho < 1 ? 1 - (e - a[1]) / (a[0] - a[1]) : 1 - (a[1] - e) / (a[1] - a[2]);
  const double p1 = alpha * mid_max, A = 1 - p1, B = e - a[1] * p1;
  const double p0 = std::max(0.0, (B - a[2] * A) / (a[0] - a[2])), p2 = std::max(0.0, A - p0);
  const Eigen::Vector3d pi(std::sqrt(p0), std::sqrt(p1), -std::sqrt(p2));
  return pi * (10 / a.cwiseProduct(pi).norm());
}

double rho_of(const Eigen::Vector3d& I, const Eigen::Vector3d& L) {
  return L.squaredNorm() / (L.cwiseProduct(I.cwiseInverse()).dot(L) * I[1]);
}

/// Π within 0.6° of the intermediate axis (the saddle).
bool near_saddle(const double inv[3], const Eigen::Vector3d& pi) {
  int s, m, l;
  kernel::axes_by_moment(inv, s, m, l);
  return pi[m] * pi[m] > 0.9999 * pi.squaredNorm();
}

/// err[6]: `splitting` choosing its order each step from the current Π
/// (split_order near the saddle, split_order_off_saddle elsewhere).
constexpr int kPerStep = 6;

struct Case {
  Eigen::Vector3d I, L;
  double rho, err[7];
};

struct Options {
  bool fourth, csv, worst_time;
};

/// The orientation error at 10 s (or the worst at whole seconds) of each order
/// for one body and initial momentum.
Case measure(const Eigen::Vector3d& I, const Eigen::Vector3d& L, const Options& opt) {
  const double cbrt2 = std::cbrt(2.0), w1 = 1.0 / (2.0 - cbrt2), w0 = -cbrt2 * w1;
  const double dt = 1e-3, T = 10;
  const long n = std::lround(T / dt);
  Case c{I, L, rho_of(I, L), {}};
  const Eigen::Vector3d inv = I.cwiseInverse();
  const FreeRotationExact exact(I, Eigen::Quaterniond::Identity(), L);
  for (int o = 0; o < (opt.fourth ? 6 : 7); ++o) {
    kernel::Quat q{1, 0, 0, 0};
    c.err[o] = 0;
    for (long k = 0; k < n; ++k) {
      if (k > 0 && k % (n / 10) == 0 && opt.worst_time)  // the worst error at t = 1, 2, ..., 9 s too
        c.err[o] = std::max(c.err[o], Eigen::Quaterniond(q.w, q.x, q.y, q.z).angularDistance(exact.orientation(k * dt)));
      if (!opt.fourth) {
        const Eigen::Vector3d pi = Eigen::Quaterniond(q.w, q.x, q.y, q.z).conjugate() * L;
        const int order = o < kPerStep                   ? o
                          : near_saddle(inv.data(), pi) ? kernel::split_order(inv.data())
                                                        : kernel::split_order_off_saddle(inv.data());
        q = kernel::splitting_rotation_ordered(order, q, L.data(), inv.data(), dt);
        continue;
      }
      q = kernel::splitting_rotation_ordered(o, q, L.data(), inv.data(), w1 * dt);
      q = kernel::splitting_rotation_ordered(o, q, L.data(), inv.data(), w0 * dt);
      q = kernel::splitting_rotation_ordered(o, q, L.data(), inv.data(), w1 * dt);
    }
    c.err[o] = std::max(c.err[o], Eigen::Quaterniond(q.w, q.x, q.y, q.z).angularDistance(exact.orientation(T)));
  }
  return c;
}

/// The initial momenta of one body: near each axis, two generic, tilted from
/// the intermediate axis, and on orbits of both regions.
std::vector<Eigen::Vector3d> momenta(const Eigen::Vector3d& I) {
  // Position u of the orbit between the pure spin (u = 0) and the separatrix (u = 1).
  const double us[] = {1e-3, 0.3, 0.7, 1 - 1e-2, 1 - 1e-4, 1 - 1e-6};
  const double alphas[] = {0.05, 0.5, 0.95};
  std::vector<Eigen::Vector3d> Ls;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d w = Eigen::Vector3d::Constant(0.01);  // near principal axis i
    w[i] = 10;
    Ls.push_back(I.cwiseProduct(w));
  }
  Ls.push_back(I.cwiseProduct(Eigen::Vector3d(3, 7, -2)));
  Ls.push_back(I.cwiseProduct(Eigen::Vector3d(5, 5, 5)));
  for (double deg : {0.2, 0.4, 1.0, 2.0, 3.0, 5.0, 7.0})  // |Π| = 10 I_mid, tilted towards three directions
    for (double phi : {0.3, 1.2, 2.5}) {
      const double a = deg * M_PI / 180, n = 10 * I[1];
      Ls.push_back(Eigen::Vector3d(n * std::sin(a) * std::cos(phi), n * std::cos(a), n * std::sin(a) * std::sin(phi)));
    }
  for (double u : us)
    for (double alpha : alphas) {
      Ls.push_back(momentum_on_orbit(I, I[0] / I[1] + u * (1 - I[0] / I[1]), alpha));  // about the smallest
      Ls.push_back(momentum_on_orbit(I, I[2] / I[1] + u * (1 - I[2] / I[1]), alpha));  // about the largest
    }
  return Ls;
}

std::vector<Case> measure_all(const Options& opt) {
  const std::vector<Eigen::Vector3d> bodies = {
      {1, 2, 3},   {1, 1.1, 5},   {1, 4.9, 5}, {2, 3, 4.5},   {1, 1.5, 2},   {1, 3, 3.3},
      {1, 1.8, 2.2}, {0.2, 1, 1.1}, {1, 1.05, 2}, {1, 1.2, 5}, {1, 1.4, 5},   {1, 1.8, 5},
      {1, 2.6, 5}, {1, 1.2, 2},   {1, 1.3, 2}, {1, 1.1, 1.5}, {1, 1.3, 10},  {1, 2, 10}};
  std::vector<Case> cases;
  for (const Eigen::Vector3d& I : bodies)
    for (const Eigen::Vector3d& L : momenta(I)) cases.push_back(measure(I, L, opt));
  return cases;
}

std::string label(int o) {
  const int* a = kernel::kSplitAxes[o];
  return std::to_string(a[0] + 1) + std::to_string(a[1] + 1) + std::to_string(a[2] + 1);
}

int moments_rule(const Case& c, bool fourth) {
  const Eigen::Vector3d inv = c.I.cwiseInverse();
  return fourth ? kernel::split_order4(inv.data()) : kernel::split_order(inv.data());
}

// Π starts within 0.6° of the intermediate axis (the saddle), as in the
// reference problem (Π = L: every case starts at q = 1).
bool at_saddle(const Case& c) { return near_saddle(c.I.cwiseInverse().eval().data(), c.L); }

void print_csv(const std::vector<Case>& cases, bool fourth) {
  std::printf("I1,I2,I3,rho,L1,L2,L3,best");
  for (int o = 0; o < 6; ++o) std::printf(",e%s", label(o).c_str());
  std::printf(",rule,at_saddle%s\n", fourth ? "" : ",per_step");
  for (const Case& c : cases) {
    const int best = static_cast<int>(std::min_element(c.err, c.err + 6) - c.err);
    std::printf("%g,%g,%g,%.9g,%.6g,%.6g,%.6g,%s", c.I[0], c.I[1], c.I[2], c.rho, c.L[0], c.L[1], c.L[2],
                label(best).c_str());
    for (int o = 0; o < 6; ++o) std::printf(",%.3e", c.err[o]);
    std::printf(",%s,%d", label(moments_rule(c, fourth)).c_str(), at_saddle(c) ? 1 : 0);
    if (!fourth) std::printf(",%.3e", c.err[kPerStep]);
    std::printf("\n");
  }
}

double regret_of(const Case& c, int o) { return std::log10(c.err[o] / *std::min_element(c.err, c.err + 6)); }

/// Mean and worst regret of an order chooser over the cases with region r
/// (0: ρ < 1, 1: ρ > 1, 2: all).
template <class Choose>
std::pair<double, double> regret(const std::vector<Case>& cases, Choose&& choose, int r) {
  double sum = 0, worst = 0;
  int k = 0;
  for (const Case& c : cases) {
    if (r != 2 && (c.rho > 1) != (r == 1)) continue;
    const double d = regret_of(c, choose(c));
    sum += d, worst = std::max(worst, d), ++k;
  }
  return std::pair{sum / k, worst};
}

/// Oracle: per body and class of case (classify), the order with the least
/// summed regret: the best any rule that reads only those can do.
template <class Classify>
auto oracle(const std::vector<Case>& cases, Classify classify) {
  std::map<std::vector<double>, std::vector<double>> sums;
  for (const Case& c : cases) {
    std::vector<double>& s = sums[{c.I[0], c.I[1], c.I[2], classify(c)}];
    s.resize(6);
    for (int o = 0; o < 6; ++o) s[o] += regret_of(c, o);
  }
  return [sums, classify](const Case& c) {
    const std::vector<double>& s = sums.at({c.I[0], c.I[1], c.I[2], classify(c)});
    return static_cast<int>(std::min_element(s.begin(), s.end()) - s.begin());
  };
}

template <class Choose>
void row(const std::vector<Case>& cases, const std::string& name, Choose&& choose) {
  std::printf("%-40s", name.c_str());
  for (int r = 0; r < 3; ++r) {
    const auto [mean, worst] = regret(cases, choose, r);
    std::printf("  %.3f %5.2f", mean, worst);
  }
  std::printf("\n");
}

/// The rule against the alternative by the start's angle from the intermediate axis (I_mid = I[1]).
void print_by_angle(const std::vector<Case>& cases) {
  std::printf("\nby the start's angle from the intermediate axis: cases, mean regret of the rule | alternative\n");
  const double edges[] = {0, 0.15, 0.6, 1.5, 4, 8, 20, 90.1};
  for (int b = 0; b + 1 < 8; ++b) {
    double sr = 0, sa = 0;
    int k = 0;
    for (const Case& c : cases) {
      const double deg = std::acos(std::min(1.0, std::abs(c.L[1]) / c.L.norm())) * 180 / M_PI;
      if (deg < edges[b] || deg >= edges[b + 1]) continue;
      sr += regret_of(c, moments_rule(c, false)), sa += regret_of(c, kernel::split_order_off_saddle(c.I.cwiseInverse().eval().data())), ++k;
    }
    if (k > 0) std::printf("  [%g, %g) deg  %4d  %.3f | %.3f\n", edges[b], edges[b + 1], k, sr / k, sa / k);
  }
  std::printf("\n");
}

void print_summary(const std::vector<Case>& cases, bool fourth) {
  std::printf("%zu cases (%d with rho < 1, circulation about the smallest moment's axis; %d start at the saddle)\n",
              cases.size(), static_cast<int>(std::count_if(cases.begin(), cases.end(), [](const Case& c) { return c.rho < 1; })),
              static_cast<int>(std::count_if(cases.begin(), cases.end(), at_saddle)));
  std::printf("log10(error / best order's error): mean, worst; over rho < 1 | rho > 1 | all\n");
  row(cases, std::string("rule split_order") + (fourth ? "4" : ""), [fourth](const Case& c) { return moments_rule(c, fourth); });
  row(cases, "oracle: best order per body", oracle(cases, [](const Case&) { return 0.0; }));
  row(cases, "oracle: best per body and orbit region", oracle(cases, [](const Case& c) { return double(c.rho > 1); }));
  row(cases, "oracle: best per body and start at saddle", oracle(cases, [](const Case& c) { return double(at_saddle(c)); }));
  if (!fourth) {
    row(cases, "alternative: 12321, elongated 13231", [](const Case& c) { return kernel::split_order_off_saddle(c.I.cwiseInverse().eval().data()); });
    row(cases, "per step: rule at the saddle, else alt.", [](const Case&) { return kPerStep; });
    row(cases, "per run: split_order_for_start (1 deg)", [](const Case& c) {
      return kernel::split_order_for_start(c.I.cwiseInverse().eval().data(), c.L.data());  // Π = L at q = 1
    });
    print_by_angle(cases);
  }
  for (int o = 0; o < 6; ++o) {
    const int* a = kernel::kSplitAxes[o];
    row(cases, "fixed " + label(o) + std::to_string(a[1] + 1) + std::to_string(a[0] + 1), [o](const Case&) { return o; });
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  const auto has = [&](const char* a) { return std::find(args.begin(), args.end(), a) != args.end(); };
  const Options opt{has("4"), has("csv"), has("max")};
  const std::vector<Case> cases = measure_all(opt);
  if (opt.csv)
    print_csv(cases, opt.fourth);
  else
    print_summary(cases, opt.fourth);
}
