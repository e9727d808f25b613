#include "bench/soa_splitting.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

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

struct Quat {
  double w, x, y, z;
};

// Hamilton product a ⊗ b.
inline Quat mul(const Quat& a, const Quat& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y + a.y * b.w + a.z * b.x - a.x * b.z, a.w * b.z + a.z * b.w + a.x * b.y - a.y * b.x};
}

// Flow of Tᵢ = Πᵢ²/(2Iᵢ) over τ: Π turns by -θ about axis i, θ = τ Πᵢ/Iᵢ; returns
// the body-frame rotation (half angle) the orientation picks up.
inline Quat axis_flow(int i, double inv_i, double tau, double pi[3]) {
  const double half = 0.5 * tau * pi[i] * inv_i;
  const double ch = std::cos(half), sh = std::sin(half);
  const double c = ch * ch - sh * sh, s = 2 * ch * sh;
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const double pj = pi[j], pk = pi[k];
  pi[j] = c * pj + s * pk;
  pi[k] = -s * pj + c * pk;
  Quat r{ch, 0, 0, 0};
  (i == 0 ? r.x : i == 1 ? r.y : r.z) = sh;
  return r;
}

}  // namespace

void BodiesSoA::advance_range(size_t begin, size_t end, double h, long steps) {
  constexpr size_t kTile = 256;  // 17 doubles × 256 = 35 KB: stays in L1/L2 across steps
  for (size_t t0 = begin; t0 < end; t0 += kTile) {
    const size_t t1 = std::min(end, t0 + kTile);
    for (long n = 0; n < steps; ++n)
      for (size_t b = t0; b < t1; ++b) {
        const double inv_m = 1.0 / mass_[b];
        cx_[b] += h * Px_[b] * inv_m, cy_[b] += h * Py_[b] * inv_m, cz_[b] += h * Pz_[b] * inv_m;
        // Π = q̄ L (rotate world L into the principal frame).
        const double w = qw_[b], x = qx_[b], y = qy_[b], z = qz_[b];
        const double L[3] = {Lx_[b], Ly_[b], Lz_[b]};
        const double ux = -y * L[2] + z * L[1], uy = -z * L[0] + x * L[2], uz = -x * L[1] + y * L[0];
        const double tx = 2 * ux, ty = 2 * uy, tz = 2 * uz;
        double pi[3] = {L[0] + w * tx + (-y * tz + z * ty), L[1] + w * ty + (-z * tx + x * tz),
                        L[2] + w * tz + (-x * ty + y * tx)};
        const double inv[3] = {ix_[b], iy_[b], iz_[b]};
        Quat r = axis_flow(0, inv[0], 0.5 * h, pi);
        r = mul(r, axis_flow(1, inv[1], 0.5 * h, pi));
        r = mul(r, axis_flow(2, inv[2], h, pi));
        r = mul(r, axis_flow(1, inv[1], 0.5 * h, pi));
        r = mul(r, axis_flow(0, inv[0], 0.5 * h, pi));
        const Quat q = mul({w, x, y, z}, r);
        const double inv_norm = 1.0 / std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
        qw_[b] = q.w * inv_norm, qx_[b] = q.x * inv_norm, qy_[b] = q.y * inv_norm, qz_[b] = q.z * inv_norm;
      }
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
