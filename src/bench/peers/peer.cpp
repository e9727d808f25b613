// The peers' common parts: tumble's methods as Steppers, fixed-step runs.
#include "bench/peers/peer.hpp"

#include <cmath>

#include "core/fixed_stepper.hpp"

namespace tumble::bench {

namespace {

class MethodStepper final : public Stepper {
 public:
  MethodStepper(Method method, const RigidBodyModel& m, const BodyState& s0) : s_(method, m, s0) {}
  void step(double h) override {
    s_.step(t_, h);
    t_ += h;
  }
  BodyState state() const override { return s_.state(); }

 private:
  FixedStepper s_;  // as a run steps: rk4 carries Euler's coordinates
  double t_ = 0;
};

}  // namespace

std::unique_ptr<Stepper> method_stepper(Method method, const RigidBodyModel& m, const BodyState& s0) {
  return std::make_unique<MethodStepper>(method, m, s0);
}

BodyState run_stepper(const MakeStepper& make, const RigidBodyModel& m, const BodyState& s0, double T, double dt) {
  const long n = std::max(1L, std::lround(T / dt));
  const double h = T / static_cast<double>(n);
  const std::unique_ptr<Stepper> s = make(m, s0);
  for (long i = 0; i < n; ++i) s->step(h);
  return s->state();
}

PeerConfig stepped_peer(std::string label, MakeStepper make) {
  auto run = [make](const RigidBodyModel& m, const BodyState& s0, double T, double dt) {
    return run_stepper(make, m, s0, T, dt);
  };
  return {std::move(label), "dt", run, std::move(make)};
}

}  // namespace tumble::bench
