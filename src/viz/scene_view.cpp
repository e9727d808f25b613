#include "viz/scene_view.hpp"

#include "viz/angle_arc.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/dynamics.hpp"

namespace tumble::viz {

namespace {

glm::dmat3 rotation_of(const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d r = q.toRotationMatrix();
  glm::dmat3 g;
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) g[c][k] = r(k, c);  // glm is column-major: g[col][row]
  return g;
}

double largest_half_extent(const RigidBodyModel& m) { return m.box.half_extents.maxCoeff(); }

// Cloud axes -> world: x_world = origin + q x_cloud.
glm::dmat4 cloud_to_world(const Eigen::Vector3d& origin, const Eigen::Quaterniond& q) {
  glm::dmat4 model(rotation_of(q));
  model[3] = glm::dvec4(to_glm(origin), 1.0);
  return model;
}

}  // namespace

glm::dvec3 axis_tip(const RigidBodyModel& m, const BodyState& s, int i) {
  const double to_face = m.box.center[i] + m.box.half_extents[i];
  const double len = std::max(kAxisOvershoot * to_face, kAxisLeast * largest_half_extent(m));
  Eigen::Vector3d e = Eigen::Vector3d::Zero();
  e[i] = len;
  return to_glm(s.c + s.q * e);
}

double particle_radius(const RigidBodyModel& m) { return 0.012 * std::max(largest_half_extent(m), 1e-3); }

double box_radius(const RigidBodyModel& m) { return (m.box.center.cwiseAbs() + m.box.half_extents).norm(); }

void TrailRecorder::record(double t, const std::vector<BodySnapshot>& bodies) {
  Sample s{t, {}};
  for (const BodySnapshot& b : bodies)
    s.tips.push_back({axis_tip(*b.model, b.state, 0), axis_tip(*b.model, b.state, 1), axis_tip(*b.model, b.state, 2)});
  samples_.push_back(std::move(s));
}

std::vector<PolylineItem> TrailRecorder::polylines(double t, double seconds, std::array<bool, 3> axes,
                                                   std::optional<std::size_t> only) const {
  std::vector<PolylineItem> out;
  if (samples_.empty() || seconds <= 0) return out;
  const size_t nbodies = samples_.back().tips.size();
  for (size_t b = 0; b < nbodies; ++b)
    for (int i = 0; i < 3; ++i) {
      if (only && b != *only) continue;
      if (!axes[static_cast<std::size_t>(i)]) continue;
      PolylineItem p{{}, kAxisColors[i], 2.0f};
      for (const Sample& s : samples_)
        if (s.t <= t + 1e-12 && s.t >= t - seconds - 1e-12 && b < s.tips.size()) p.points.push_back(s.tips[b][i]);
      if (p.points.size() >= 2) out.push_back(std::move(p));
    }
  return out;
}

namespace {

bool has_surface(const BodySnapshot& b, const DrawOptions& opt) {
  return opt.surface && b.look && !b.look->surfaces.empty();
}

}  // namespace

BoxItem body_box(const BodySnapshot& b, const DrawOptions& opt) {
  const RigidBodyModel& m = *b.model;
  const BodyState& s = b.state;
  Color edge = b.color * 0.45f;
  edge.a = 1.0f;
  if (has_surface(b, opt) && b.look->surface_box) {
    // Just outside the surfaces, so its edges do not fight with theirs for depth.
    const auto& [centre, half] = *b.look->surface_box;
    const double grow = 0.01 * std::max(half.maxCoeff(), 1e-6);
    Color none = b.color;
    none.a = 0.0f;
    edge.a = 0.35f;  // an outline recedes behind the surface it frames
    return {to_glm(s.c + s.q * centre), rotation_of(s.q), to_glm(half) + glm::dvec3(grow), none, edge};
  }
  // Around the particle spheres when they are drawn, so its edges and faces are not buried in them.
  const double grow = opt.particles && b.cloud ? particle_radius(m) : 0.0;
  return {to_glm(s.c + s.q * m.box.center), rotation_of(s.q), to_glm(m.box.half_extents) + glm::dvec3(grow), b.color,
          edge};
}

void add_ghosts(View& view, const std::vector<BodySnapshot>& bodies, Color tint) {
  for (const BodySnapshot& b : bodies) {
    if (!b.look) continue;
    const Eigen::Quaterniond qc = cloud_orientation(*b.model, b.state);
    const glm::dmat4 model = cloud_to_world(b.state.c - qc * b.model->com_cloud, qc);
    for (std::size_t i = 0; i < b.look->surfaces.size(); ++i) view.surfaces.push_back({b.look->surfaces[i], model, tint, "ghost", true});
  }
}

void add_bodies(View& view, const std::vector<BodySnapshot>& bodies, const DrawOptions& opt,
                const TrailRecorder* trails, double t) {
  for (const BodySnapshot& b : bodies) {
    const RigidBodyModel& m = *b.model;
    const BodyState& s = b.state;
    const double size = std::max(largest_half_extent(m), 1e-3);
    if (opt.box.value_or(!has_surface(b, opt))) view.boxes.push_back(body_box(b, opt));
    static const char* const kAxisNames[3] = {"e\u2081", "e\u2082", "e\u2083"};
    if (opt.axes)
      for (int i = 0; i < 3; ++i)
        view.arrows.push_back({to_glm(s.c), axis_tip(m, s, i) - to_glm(s.c), 0.03 * opt.arrow_width * size,
                               kAxisColors[i], std::string("e") + char('1' + i), kAxisNames[i], 2});
    const Eigen::Quaterniond qc = cloud_orientation(m, s);
    const glm::dmat4 model = cloud_to_world(s.c - qc * m.com_cloud, qc);
    if (has_surface(b, opt))
      for (std::size_t i = 0; i < b.look->surfaces.size(); ++i)
        view.surfaces.push_back({b.look->surfaces[i], model, b.look->surface_colors[i]});
    if (opt.particles && b.look && b.look->particles) {
      view.particles.push_back({b.look->particles, model});  // the shell, kept on the GPU
    } else if (opt.particles && b.cloud) {
      Color pc = b.color * 0.75f;
      pc.a = 1.0f;
      for (const Particle& p : *b.cloud)
        view.points.push_back({to_glm(s.c + qc * (p.position - m.com_cloud)), particle_radius(m), pc});
    }
    // L and ω show direction only (their magnitudes have other units than
    // length), at fixed multiples of the body's size, longer than the body so
    // that neither hides in it: L as a line through the body (it is fixed in
    // space: the line stays put while the body turns about it), ω past the axes.
    if (opt.angular_momentum && s.L.norm() > 0) {
      const glm::dvec3 l = to_glm(s.L.normalized());
      const double len = opt.arrow_length * size;
      view.arrows.push_back({to_glm(s.c) - kLBehind * len * l, (kLBehind + kLReach) * len * l,
                             0.025 * opt.arrow_width * size, kLColor, "L", "L", 0});
    }
    if (opt.omega) {
      const Eigen::Vector3d w = omega_world(m, s);
      if (w.norm() > 0)
        view.arrows.push_back({to_glm(s.c), to_glm(kOmegaReach * opt.arrow_length * size * w.normalized()), 0.02 * opt.arrow_width * size,
                               kOmegaColor, "omega", "\u03c9", 1});
      // The angle from L to ω as an arc at 0.7 of ω's length: seen even where ω lies along L in the picture.
      if (opt.angle_arc && opt.angular_momentum && w.norm() > 0 && s.L.norm() > 0)
        if (PolylineItem arc = angle_arc(to_glm(s.c), to_glm(s.L), to_glm(w), 0.7 * kOmegaReach * opt.arrow_length * size,
                                         kOmegaColor, 3.0f * static_cast<float>(opt.arrow_width));
            !arc.points.empty())
          view.polylines.push_back(std::move(arc));
    }
  }
  if (trails && opt.trail_seconds > 0)
    for (PolylineItem& p : trails->polylines(t, opt.trail_seconds, opt.trail_axes)) view.polylines.push_back(std::move(p));
}

Camera auto_camera(const std::vector<glm::dvec3>& centres, const std::vector<double>& radii, double fov_y_deg,
                   double aspect) {
  Camera cam;
  cam.fov_y_deg = fov_y_deg;
  if (centres.empty()) return cam;
  glm::dvec3 lo(1e300), hi(-1e300);
  for (size_t i = 0; i < centres.size(); ++i) {
    lo = glm::min(lo, centres[i] - glm::dvec3(radii[i]));
    hi = glm::max(hi, centres[i] + glm::dvec3(radii[i]));
  }
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double radius = std::max(0.5 * glm::length(hi - lo), 1e-3);
  // Distance so the bounding sphere fits the narrower of the two fields of view.
  const double half_v = 0.5 * fov_y_deg * std::numbers::pi / 180.0;
  const double half_h = std::atan(std::tan(half_v) * aspect);
  // 0.9: the sphere bounds the whole run; at any one moment the bodies fill less.
  const double dist = radius / std::sin(std::min(half_v, half_h)) * 0.9;
  const glm::dvec3 dir = glm::normalize(glm::dvec3(0.55, -1.0, 0.45));
  cam.target = centre;
  cam.position = centre + dist * dir;
  cam.up = {0, 0, 1};
  cam.near_m = std::max(1e-3, dist - 3 * radius);
  cam.far_m = dist + 3 * radius;
  return cam;
}

}  // namespace tumble::viz
