// The integration methods behind one enum and one table (MethodInfo): adding a
// method is one row in integrator.cpp plus its step function and tests. Names
// are part of the interface: scenes, the CLI and the CSV/bench output use them.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "core/body.hpp"

namespace tumble {

enum class Method {
  euler,
  semi_implicit_euler,
  rk4,
  rk4_seed,
  rk45,
  dop853,
  implicit_midpoint,
  splitting,
  splitting4,
  exact
};

/// One step of size h (s) from time t (s).
using StepFn = BodyState (*)(const RigidBodyModel& m, const BodyState& s, double t, double h);

struct BodyCoords;
class AdaptiveIntegrator;
struct AdaptiveOptions;
/// An adaptive pair's integrator for one body from t0 (embedded_rk.hpp).
using MakeAdaptiveFn = std::unique_ptr<AdaptiveIntegrator> (*)(const RigidBodyModel& m, const BodyState& s0, double t0,
                                                               const AdaptiveOptions& opt);
/// One step of size h (s) in Euler's coordinates (c, q, P, Π), in place, for
/// methods that integrate in them (body_frame.hpp): the Propagator carries these
/// between steps (in place: no 128-byte copy per step).
using CoordsStepFn = void (*)(const RigidBodyModel& m, BodyCoords& x, double t, double h);

/// One step of size h (s) with the splitting sub-flow order given (index into
/// kernel::kSplitAxes), for methods whose best order depends on the start.
using OrderedStepFn = BodyState (*)(const RigidBodyModel& m, const BodyState& s, double t, double h, int order);

/// ns per step, measured by tumble_microbench (scripts/gen_method_costs.sh).
struct StepCost {
  double free;                 ///< torque-free T-handle, as a run steps it
  double forced;               ///< the forced T-handle (triaxial: exact's closed form is elliptic)
  double forced_axisymmetric;  ///< the torqued symmetric top (exact's closed form is trigonometric)
};

/// Everything tumble knows about a method, in one row.
struct MethodInfo {
  Method method;
  std::string_view name;
  std::string_view title;    ///< what a figure calls it ("explicit Euler", "RK4")
  /// One line for people (markdown: `code`, no '|' escaping): what the method
  /// is and what it integrates in. docs/methods.md's method table is generated
  /// from it (`tumble_docs methods docs/methods.md`).
  std::string_view description;
  int order;                 ///< global order (adaptive pairs: of the solution they advance; exact: 0 = exact when torque-free)
  StepFn step;               ///< one fixed step (adaptive pairs: one uncontrolled step)
  CoordsStepFn coords_step;  ///< the same step in Euler's coordinates, or nullptr (steps on the seed's state)
  /// The same step with the sub-flow order a run fixes at its start
  /// (kernel::split_order_for_start), or nullptr (step() alone).
  OrderedStepFn ordered_step;
  /// Adaptive pairs (rk45, dop853): the integrator the Propagator runs, with its
  /// own step control and dense output; nullptr for fixed-step methods.
  MakeAdaptiveFn adaptive;
  bool closed_form_if_free;  ///< Propagator evaluates the closed form at any t when torque-free (exact)
  /// Keeps world L exactly when torque-free and the energy bounded for ever
  /// (a rotation map composed with Strang kicks, or the closed form).
  bool geometric;
  bool auto_candidate;       ///< method = "auto" may pick it
  bool splits_free_rotation; ///< uses the splitting sub-flows (order chosen per body)
  /// Largest h·|ω| (rad per step) the method follows: beyond it a step cannot
  /// resolve the rotation (explicit methods) or aliases it between samples.
  double max_turn_per_step;
  StepCost cost;             ///< ns/step (method_costs.inc, generated)
};

/// The table, in enum order.
std::span<const MethodInfo> method_table();
const MethodInfo& method_info(Method m);

inline constexpr std::array<Method, 10> kAllMethods = {
    Method::euler,      Method::semi_implicit_euler, Method::rk4,        Method::rk4_seed, Method::rk45,
    Method::dop853,     Method::implicit_midpoint,   Method::splitting,  Method::splitting4, Method::exact};

std::string_view method_name(Method m);
std::optional<Method> parse_method(std::string_view name);
/// "euler, semi_implicit_euler, ..." for error messages.
std::string method_list();

/// Global order of accuracy (adaptive pairs: of the solution they advance).
int method_order(Method m);

/// One step of size h (s) from time t (s). For the adaptive pairs this is one
/// uncontrolled step; adaptive integration lives in `Propagator`/embedded_rk.hpp.
BodyState step(Method method, const RigidBodyModel& m, const BodyState& s, double t, double h);

}  // namespace tumble
