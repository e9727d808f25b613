#include "bench/soa_splitting.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

#include "core/methods/splitting_kernel.hpp"

namespace tumble::bench {

void BodiesSoA::push(const RigidBodyModel& m, const BodyState& s) {
  qw_.push_back(s.q.w()), qx_.push_back(s.q.x()), qy_.push_back(s.q.y()), qz_.push_back(s.q.z());
  Lx_.push_back(s.L.x()), Ly_.push_back(s.L.y()), Lz_.push_back(s.L.z());
  cx_.push_back(s.c.x()), cy_.push_back(s.c.y()), cz_.push_back(s.c.z());
  Px_.push_back(s.P.x()), Py_.push_back(s.P.y()), Pz_.push_back(s.P.z());
  mass_.push_back(m.mass);
  ix_.push_back(m.inv_inertia.x()), iy_.push_back(m.inv_inertia.y()), iz_.push_back(m.inv_inertia.z());
}

BodyState BodiesSoA::state(size_t i) const {
  BodyState s;
  s.q = Eigen::Quaterniond(qw_[i], qx_[i], qy_[i], qz_[i]);
  s.L = {Lx_[i], Ly_[i], Lz_[i]};
  s.c = {cx_[i], cy_[i], cz_[i]};
  s.P = {Px_[i], Py_[i], Pz_[i]};
  return s;
}

namespace {

// One step of bodies [b0, b1) on raw arrays. `kTier` ≥ 1: every sub-flow angle
// is known to be small, so the kernel needs no libm call and the loop vectorises.
// `kOrder` ≥ 0: every body takes that sub-flow order (kernel::kSplitAxes); -1:
// each its own (kernel::split_order), body by body.
// __restrict: the arrays never overlap, which spares the vectoriser alias checks.
template <int kTier, int kOrder>  // kTier 2: every angle ≤ kTinyAngle, 1: ≤ kSmallAngle, 0: any
void step_block(size_t b0, size_t b1, double h, double* __restrict qw, double* __restrict qx,
                double* __restrict qy, double* __restrict qz, double* __restrict cx, double* __restrict cy,
                double* __restrict cz, const double* __restrict Lx, const double* __restrict Ly,
                const double* __restrict Lz, const double* __restrict Px, const double* __restrict Py,
                const double* __restrict Pz, const double* __restrict mass, const double* __restrict ix,
                const double* __restrict iy, const double* __restrict iz) {
  constexpr int A = kernel::kSplitAxes[kOrder < 0 ? 0 : kOrder][0], B = kernel::kSplitAxes[kOrder < 0 ? 0 : kOrder][1],
                C = kernel::kSplitAxes[kOrder < 0 ? 0 : kOrder][2];
  for (size_t b = b0; b < b1; ++b) {
    // c += hP/M, as core's strang step writes it.
    cx[b] += h * Px[b] / mass[b], cy[b] += h * Py[b] / mass[b], cz[b] += h * Pz[b] / mass[b];
    const double l[3] = {Lx[b], Ly[b], Lz[b]}, inv[3] = {ix[b], iy[b], iz[b]};
    const kernel::Quat q0{qw[b], qx[b], qy[b], qz[b]};
    kernel::Quat q;
    if constexpr (kOrder < 0) q = kernel::splitting_rotation_ordered(kernel::split_order(inv), q0, l, inv, h);
    else if constexpr (kTier == 2) q = kernel::splitting_rotation_small<A, B, C, true>(q0, l, inv, h);
    else if constexpr (kTier == 1) q = kernel::splitting_rotation_small<A, B, C>(q0, l, inv, h);
    else q = kernel::splitting_rotation<false, A, B, C>(q0, l, inv, h);
    qw[b] = q.w, qx[b] = q.x, qy[b] = q.y, qz[b] = q.z;
  }
}

using StepBlock = decltype(&step_block<0, 0>);

// The tier for a tile whose bodies all take sub-flow order kOrder.
template <int kOrder>
StepBlock tier_for(double largest) {
  return largest <= 0.99 * kernel::kTinyAngle    ? step_block<2, kOrder>
         : largest <= 0.99 * kernel::kSmallAngle ? step_block<1, kOrder>
                                                 : step_block<0, kOrder>;
}

}  // namespace

void BodiesSoA::advance_range(size_t begin, size_t end, double h, long steps) {
  constexpr size_t kTile = 256;  // 17 doubles × 256 = 35 KB: stays in L1/L2 across steps
  for (size_t t0 = begin; t0 < end; t0 += kTile) {
    const size_t t1 = std::min(end, t0 + kTile);
    // Every sub-flow angle is ≤ |L| sub_flow_angle_factor (|Π| = |L|, L fixed);
    // with a margin for rounding, the whole tile may skip the libm branch. The
    // vectorised tiers need one sub-flow order for the tile (split_order gives
    // 5 or 3); a mixed tile goes body by body.
    double largest = 0;
    const double inv0[3] = {ix_[t0], iy_[t0], iz_[t0]};
    const int order = kernel::split_order(inv0);
    bool uniform = order == 5 || order == 3;
    for (size_t b = t0; b < t1; ++b) {
      const double l = std::sqrt(Lx_[b] * Lx_[b] + Ly_[b] * Ly_[b] + Lz_[b] * Lz_[b]);
      const double inv[3] = {ix_[b], iy_[b], iz_[b]};
      uniform = uniform && kernel::split_order(inv) == order;
      const int* abc = kernel::kSplitAxes[order];
      const double a = std::max({0.5 * inv[abc[0]], 0.5 * inv[abc[1]], inv[abc[2]]});
      largest = std::max(largest, l * std::abs(h) * a);
    }
    // The same tiers as the scalar kernel's per-body choice, so the bits agree.
    const StepBlock step = !uniform ? step_block<0, -1> : order == 5 ? tier_for<5>(largest) : tier_for<3>(largest);
    for (long n = 0; n < steps; ++n)
      step(t0, t1, h, qw_.data(), qx_.data(), qy_.data(), qz_.data(), cx_.data(), cy_.data(), cz_.data(),
           Lx_.data(), Ly_.data(), Lz_.data(), Px_.data(), Py_.data(), Pz_.data(), mass_.data(), ix_.data(),
           iy_.data(), iz_.data());
  }
}

void BodiesSoA::advance(double h, long steps, int threads) {
  const size_t n = size();
  // Threads only pay off with enough bodies to amortise their start (~20 µs).
  const int nt = n * static_cast<size_t>(steps) < 20'000 ? 1 : std::max(1, threads);
  if (nt == 1) return advance_range(0, n, h, steps);
  std::vector<std::thread> pool;
  const size_t chunk = (n + static_cast<size_t>(nt) - 1) / static_cast<size_t>(nt);
  for (int t = 1; t < nt; ++t) {
    const size_t b = std::min(n, static_cast<size_t>(t) * chunk), e = std::min(n, b + chunk);
    pool.emplace_back([this, b, e, h, steps] { advance_range(b, e, h, steps); });
  }
  advance_range(0, std::min(n, chunk), h, steps);
  for (auto& th : pool) th.join();
}

}  // namespace tumble::bench
