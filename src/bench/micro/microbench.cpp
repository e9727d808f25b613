// tumble_microbench: per-step cost of every method, many-body throughput of the
// SoA `splitting` kernel, and mass properties of 10⁷ particles against a
// streaming read of the same bytes (the memory-bandwidth bound of one pass).
//   ./tumble_microbench --benchmark_min_time=0.2
#include <benchmark/benchmark.h>

#include <random>

#include "bench/problems.hpp"
#include "bench/soa_splitting.hpp"
#include "core/fixed_stepper.hpp"
#include "core/methods/free_rotation_exact.hpp"
#include "core/integrator.hpp"
#include "core/mass_properties.hpp"
#include "core/propagator.hpp"

namespace {

using namespace tumble;

// The body BM_Step steps: 0 the torque-free T-handle, 1 the forced T-handle,
// 2 the torqued symmetric top (whose closed form is trigonometric, not elliptic).
bench::Problem step_problem(int64_t kind) {
  if (kind == 2) return bench::scene_problems()[2];
  return kind == 1 ? bench::forced_problem() : bench::t_handle_problem();
}

// ns per step for one body, dt = 1 ms; arg 1: step_problem's kind.
void BM_Step(benchmark::State& st) {
  const Method method = kAllMethods[static_cast<size_t>(st.range(0))];
  const bench::Problem p = step_problem(st.range(1));
  BodyState s = p.s0;
  double t = 0;
  const double h = 1e-3;
  for (auto _ : st) {
    s = step(method, p.model, s, t, h);
    t += h;
    benchmark::DoNotOptimize(s);
  }
  static constexpr const char* kKind[] = {" torque-free", " forced", " forced-axisymmetric"};
  st.SetLabel(std::string(method_name(method)) + kKind[st.range(1)]);
  st.SetItemsProcessed(st.iterations());
}
BENCHMARK(BM_Step)->ArgsProduct({benchmark::CreateDenseRange(0, static_cast<int>(kAllMethods.size()) - 1, 1), {0, 1, 2}});

// A whole run as tumble makes it: Propagator::advance_steps over the
// T-handle's 10 s at dt = 1 ms (10 000 steps, the divergence guard included).
// Methods in Euler's coordinates carry (q, Π) between steps here, where
// BM_Step's stateless step() converts from and to (q, L_world) every time.
void BM_Propagate(benchmark::State& st) {
  const Method method = kAllMethods[static_cast<size_t>(st.range(0))];
  const bench::Problem p = bench::t_handle_problem();
  const long n = 10000;
  double err = 0;
  long steps = 0;  // adaptive pairs: accepted steps of their own size; exact: one evaluation
  for (auto _ : st) {
    Propagator prop(p.model, p.s0, StepConfig{method, 1e-3});
    benchmark::DoNotOptimize(prop.advance_steps(n));
    err = bench::errors(p, prop.state()).angle;
    steps = prop.steps();
  }
  st.SetLabel(std::string(method_name(method)) + " T-handle 10 s, dt 1 ms");
  st.counters["steps"] = static_cast<double>(steps);
  st.counters["ns_per_step"] = benchmark::Counter(static_cast<double>(st.iterations() * steps),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  st.counters["error_rad"] = err;
}
BENCHMARK(BM_Propagate)->DenseRange(0, static_cast<int>(kAllMethods.size()) - 1, 1)->Unit(benchmark::kMillisecond);

// The same 10 000 steps through FixedStepper, without the Propagator's
// divergence guard: stepping as a run steps, measured like a peer (odeint's
// do_step loop has no guard either). Fixed-step methods only.
void BM_Stepping(benchmark::State& st) {
  const Method method = kAllMethods[static_cast<size_t>(st.range(0))];
  const bench::Problem p = bench::t_handle_problem();
  const long n = 10000;
  double err = 0;
  for (auto _ : st) {
    const BodyState s = integrate_fixed(method, p.model, p.s0, 0.0, 1e-3, n);
    benchmark::DoNotOptimize(s);
    err = bench::errors(p, s).angle;
  }
  st.SetLabel(std::string(method_name(method)) + " T-handle 10 s, dt 1 ms");
  st.counters["ns_per_step"] = benchmark::Counter(static_cast<double>(st.iterations() * n),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  st.counters["error_rad"] = err;
}
// Chosen from the method table (dop853 took splitting4's old index): no pair, no closed form.
BENCHMARK(BM_Stepping)
    ->Apply([](benchmark::internal::Benchmark* b) {
      for (std::size_t i = 0; i < kAllMethods.size(); ++i)
        if (!method_info(kAllMethods[i]).adaptive && !method_info(kAllMethods[i]).closed_form_if_free) b->Arg(static_cast<int64_t>(i));
    })
    ->Unit(benchmark::kMillisecond);

// The closed form alone: construct FreeRotationExact for the T-handle and
// evaluate orientation(t), t varied over the problem's 10 s so nothing is hoisted.
void BM_ExactConstructEval(benchmark::State& st) {
  const bench::Problem p = bench::t_handle_problem();
  double t = 0;
  for (auto _ : st) {
    const FreeRotationExact ex(p.model.inertia, p.s0.q, p.s0.L);
    benchmark::DoNotOptimize(ex.orientation(t));
    t = t < 10 ? t + 1e-3 : 0;
  }
}
BENCHMARK(BM_ExactConstructEval);

// Scalar core splitting_step over many bodies on one thread: the SoA baseline.
void BM_ScalarSplittingManyBodies(benchmark::State& st) {
  const bench::Problem p = bench::t_handle_problem();
  std::vector<BodyState> bodies(static_cast<size_t>(st.range(0)), p.s0);
  for (auto _ : st) {
    for (auto& b : bodies) b = step(Method::splitting, p.model, b, 0, 1e-3);
    benchmark::ClobberMemory();
  }
  st.SetItemsProcessed(st.iterations() * st.range(0));
}
BENCHMARK(BM_ScalarSplittingManyBodies)->Arg(1000);

// body-steps/s of the SoA kernel on both cores; varied ω so no two bodies match.
void BM_SoaSplitting(benchmark::State& st) {
  const size_t n = static_cast<size_t>(st.range(0));
  const long steps = std::max<long>(1, 10'000'000 / static_cast<long>(n) / 10);
  const RigidBodyModel m = bench::diagonal_model("b", {1, 2, 3});
  bench::BodiesSoA soa;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-10, 10);
  for (size_t i = 0; i < n; ++i) soa.push(m, bench::spinning_state(m, {u(rng), u(rng), u(rng)}));
  for (auto _ : st) soa.advance(1e-3, steps, static_cast<int>(st.range(1)));
  benchmark::DoNotOptimize(soa.state(0));
  st.counters["body_steps_per_s"] =
      benchmark::Counter(static_cast<double>(st.iterations()) * static_cast<double>(n * static_cast<size_t>(steps)),
                         benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SoaSplitting)->ArgsProduct({{1, 1000, 1000000}, {1, 2}})->UseRealTime()->Unit(benchmark::kMillisecond);

const ParticleCloud& big_cloud() {
  static const ParticleCloud cloud = [] {
    ParticleCloud c(10'000'000);
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(-1, 1);
    for (auto& p : c) p = {{u(rng), u(rng), 0.5 * u(rng)}, 1.0 + 0.5 * u(rng)};
    return c;
  }();
  return cloud;
}

void BM_MassProperties10M(benchmark::State& st) {
  const ParticleCloud& c = big_cloud();
  for (auto _ : st) benchmark::DoNotOptimize(compute_mass_properties(c, "cloud"));
  st.SetBytesProcessed(st.iterations() * static_cast<int64_t>(c.size() * sizeof(Particle)));
}
BENCHMARK(BM_MassProperties10M)->Unit(benchmark::kMillisecond)->UseRealTime();

// One streaming read of the same bytes: the floor for one pass over the cloud.
void BM_StreamSameBytes10M(benchmark::State& st) {
  const ParticleCloud& c = big_cloud();
  for (auto _ : st) {
    double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    for (const Particle& p : c) s0 += p.position.x(), s1 += p.position.y(), s2 += p.position.z(), s3 += p.mass;
    benchmark::DoNotOptimize(s0 + s1 + s2 + s3);
  }
  st.SetBytesProcessed(st.iterations() * static_cast<int64_t>(c.size() * sizeof(Particle)));
}
BENCHMARK(BM_StreamSameBytes10M)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
