// method = "auto" checked the bench way: for a sweep of tolerances, what auto
// picks on a forced body, what it predicted, and what the pick then really
// costs (median CPU) and really errs (against rk45 at rtol 1e-13).
#include <cmath>
#include <sstream>

#include "bench/studies.hpp"
#include "core/method_choice.hpp"
#include "core/propagator.hpp"

namespace tumble::bench {

namespace {

// Well away from the separatrix, so the rk45 reference is good to ~1e-12 rad
// (the forced T-handle amplifies every error ~1e7 and would hide auto's picks).
struct AutoProblem {
  RigidBodyModel model;
  BodyState s0;
  ChoiceRequest request;
};

AutoProblem thruster() {
  ForceSet f;
  f.terms.push_back(UniformGravity{Eigen::Vector3d(0, 0, -9.81)});
  f.terms.push_back(PointForce{Eigen::Vector3d(0, 0, 2), Eigen::Vector3d(1, 0, 0), Frame::body});
  f.terms.push_back(ConstantTorque{Eigen::Vector3d(0, 0.3, 0), Frame::body});
  AutoProblem p{diagonal_model("thruster", {1, 2, 3}, f), {}, {10, 1.0 / 30, 1e-6}};
  p.s0 = spinning_state(p.model, {0.5, 3, 0.2});
  return p;
}

BodyState run_like_a_scene(const AutoProblem& p, const StepConfig& cfg) {
  Propagator prop(p.model, p.s0, cfg);
  const ChoiceRequest& r = p.request;
  for (double k = 1; k * r.sample_interval < r.duration; ++k) prop.advance_to(k * r.sample_interval);
  return prop.advance_to(r.duration);
}

}  // namespace

std::string auto_problem_description() {
  return "moments (1, 2, 3) kg m^2, 1 kg, omega_body (0.5, 3, 0.2) rad/s, gravity (0, 0, -9.81) m/s^2, body-fixed "
         "2 N along z at (1, 0, 0) m, body torque (0, 0.3, 0) N m, 10 s sampled at 30 fps; reference rk45 at rtol 1e-13";
}

std::vector<AutoRow> auto_study(const Settings& st, std::ostream& log) {
  const AutoProblem p = thruster();
  StepConfig ref_cfg;
  ref_cfg.method = Method::rk45;
  ref_cfg.rtol = 1e-13;
  ref_cfg.atol = 1e-16;
  const BodyState reference = Propagator(p.model, p.s0, ref_cfg).advance_to(p.request.duration);
  const std::vector<double> tolerances =
      st.quick ? std::vector<double>{1e-3, 1e-6} : std::vector<double>{1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9};
  std::vector<AutoRow> rows;
  for (double tol : tolerances) {
    ChoiceRequest req = p.request;
    req.tolerance = tol;
    MethodChoice c;
    const double pilot = median_cpu_seconds([&] { c = choose_method(p.model, p.s0, req); }, st.min_batch_s, st.repeats);
    AutoRow row;
    row.tolerance = tol;
    row.method = std::string(method_name(c.config.method));
    const bool adaptive = method_info(c.config.method).adaptive;
    row.param_name = adaptive ? "rtol" : "dt";
    row.param = adaptive ? c.config.rtol : c.config.dt;
    row.predicted_error = c.error;
    row.predicted_cpu_s = c.cost_s;
    row.pilot_cpu_s = pilot;
    AutoProblem q = p;
    q.request = req;
    BodyState end;
    row.cpu_s = median_cpu_seconds([&] { end = run_like_a_scene(q, c.config); }, st.min_batch_s, st.repeats);
    row.error = end_state_error(p.model, end, reference);
    rows.push_back(row);
    log << "  auto at tolerance " << tol << ": " << row.method << " (" << row.param_name << " " << row.param
        << "), error " << row.error << " rad\n";
  }
  return rows;
}

void write_auto_csv(const std::filesystem::path& file, const std::vector<AutoRow>& rows) {
  std::ostringstream o;
  o.precision(6);
  o << "tolerance,method,param_name,param,predicted_error,error,predicted_cpu_s,cpu_s,pilot_cpu_s\n";
  for (const AutoRow& r : rows)
    o << r.tolerance << "," << r.method << "," << r.param_name << "," << r.param << "," << r.predicted_error << ","
      << r.error << "," << r.predicted_cpu_s << "," << r.cpu_s << "," << r.pilot_cpu_s << "\n";
  write_text(file, o.str());
}

}  // namespace tumble::bench
