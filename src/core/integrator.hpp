// The integration methods behind one enum (MuJoCo style). Names are part of the
// interface: scenes, the CLI and the CSV/bench output use them.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "core/body.hpp"

namespace tumble {

enum class Method { euler, semi_implicit_euler, rk4, rk45, implicit_midpoint, splitting, splitting4, exact };

inline constexpr std::array<Method, 8> kAllMethods = {
    Method::euler,      Method::semi_implicit_euler, Method::rk4,        Method::rk45,
    Method::implicit_midpoint, Method::splitting,    Method::splitting4, Method::exact};

std::string_view method_name(Method m);
std::optional<Method> parse_method(std::string_view name);
/// "euler, semi_implicit_euler, ..." for error messages.
std::string method_list();

/// Global order of accuracy (rk45: of its 5th-order solution).
int method_order(Method m);

/// One step of size h (s) from time t (s). For `rk45` this is one uncontrolled
/// Dormand–Prince step; adaptive integration lives in `Propagator`/`Rk45`.
BodyState step(Method method, const RigidBodyModel& m, const BodyState& s, double t, double h);

}  // namespace tumble
