#include "core/integrator.hpp"

#include "core/explicit_rk.hpp"
#include "core/free_rotation_exact.hpp"
#include "core/rk45.hpp"
#include "core/rotation_steps.hpp"

namespace tumble {

namespace {
constexpr std::array<std::string_view, 8> kNames = {
    "euler", "semi_implicit_euler", "rk4", "rk45", "implicit_midpoint", "splitting", "splitting4", "exact"};
}

std::string_view method_name(Method m) { return kNames[static_cast<size_t>(m)]; }

std::optional<Method> parse_method(std::string_view name) {
  for (size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) return static_cast<Method>(i);
  return std::nullopt;
}

std::string method_list() {
  std::string s;
  for (auto n : kNames) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

int method_order(Method m) {
  switch (m) {
    case Method::euler:
    case Method::semi_implicit_euler: return 1;
    case Method::implicit_midpoint:
    case Method::splitting: return 2;
    case Method::rk4:
    case Method::splitting4: return 4;
    case Method::rk45: return 5;
    case Method::exact: return 0;  // exact for torque-free motion; 2 with kicks
  }
  return 0;
}

BodyState step(Method method, const RigidBodyModel& m, const BodyState& s, double t, double h) {
  switch (method) {
    case Method::euler: return euler_step(m, s, t, h);
    case Method::semi_implicit_euler: return semi_implicit_euler_step(m, s, t, h);
    case Method::rk4: return rk4_step(m, s, t, h);
    case Method::rk45: return rk45_fixed_step(m, s, t, h);
    case Method::implicit_midpoint: return implicit_midpoint_step(m, s, t, h);
    case Method::splitting: return splitting_step(m, s, t, h);
    case Method::splitting4: return splitting4_step(m, s, t, h);
    case Method::exact: return exact_step(m, s, t, h);
  }
  return s;
}

}  // namespace tumble
