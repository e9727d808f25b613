#include "compose/world_views.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>

#include "base/format.hpp"
#include "core/dynamics.hpp"
#include "viz/captions.hpp"
#include "viz/particle_set.hpp"
#include "viz/surfaces.hpp"
#include "viz/text_layout.hpp"

namespace tumble::compose {

namespace {

viz::Color rgba(const Eigen::Vector3d& c, float a) {
  return {static_cast<float>(c.x()), static_cast<float>(c.y()), static_cast<float>(c.z()), a};
}
using viz::to_glm;

std::vector<viz::BodySnapshot> snapshots(const scene::Scene& s, const std::vector<BodyState>& states,
                                         const std::vector<viz::BodyLook>* looks = nullptr) {
  std::vector<viz::BodySnapshot> out;
  for (size_t i = 0; i < s.bodies.size() && i < states.size(); ++i)
    out.push_back({&s.bodies[i].model, &s.bodies[i].cloud, states[i], rgba(s.bodies[i].color, 0.38f),
                   looks ? &(*looks)[i] : nullptr, s.bodies[i].label});
  return out;
}

// Body names beside the bodies: screen text, so they always face the camera.
// Each names its body's box on screen (subject_px): viz::settle_labels keeps it beside, not on, the box.
void add_labels(viz::View& v, const std::vector<viz::BodySnapshot>& snaps, const viz::DrawOptions& draw, int width_px,
                int height_px, float font_px) {
  const float fw = static_cast<float>(width_px), fh = static_cast<float>(height_px);
  for (const viz::BodySnapshot& b : snaps) {
    const glm::dvec3 above = to_glm(b.state.c) + glm::normalize(v.camera.up) * (1.1 * viz::box_radius(*b.model));
    glm::vec2 px;
    const auto box = viz::screen_box(v.camera, fw, fh, viz::box_corners(viz::body_box(b, draw)));
    if (!box || !viz::project_to_viewport(v.camera, width_px, height_px, above, px)) continue;  // none for what is out of view
    const std::string& shown = b.label.empty() ? b.model->name : b.label;  // the display name
    const float x = viz::centred_x(shown, font_px * 1.1f, px.x);
    v.texts.push_back({shown, {x, px.y - 1.2f * font_px}, font_px * 1.1f, {0.1f, 0.1f, 0.14f, 1.0f},
                       "label:" + b.model->name});
    v.texts.back().subject_px = {box->x0, box->y0, box->x1, box->y1};
  }
}

}  // namespace

// Once per body: mesh surfaces, the particles that can be seen, part colours.
viz::BodyLook body_look(const scene::Body& b, bool particles) {
  viz::BodyLook look;
  for (const scene::MeshSource& m : b.meshes) {
    if (m.surface.triangles.empty()) continue;
    look.surfaces.push_back(viz::make_surface(m.surface));
    look.surface_colors.push_back(rgba(m.color, 1.0f));
  }
  for (const scene::ShapeSource& sh : b.shapes) {
    look.surfaces.push_back(viz::solid_surface(sh.shape));
    look.surface_colors.push_back(rgba(sh.color, 1.0f));
  }
  if (!look.surfaces.empty())
    look.surface_box = viz::principal_extent(look.surfaces, b.model.cloud_from_principal.toRotationMatrix(), b.model.com_cloud);
  if (!particles) return look;
  std::vector<viz::Color> colors;
  colors.reserve(b.cloud.size());
  for (std::size_t i = 0; i < b.cloud.size(); ++i) {
    Eigen::Vector3d c = b.color;
    for (const scene::ColorSpan& span : b.part_colors)
      if (i >= span.begin && i < span.end) c = span.color;
    colors.push_back(rgba(0.75 * c, 1.0f));
  }
  look.particles = viz::make_particle_set(b.cloud, colors, static_cast<float>(viz::particle_radius(b.model)));
  return look;
}

namespace {

// The energy readout's floor: 1e-13, under which the digits are round-off
// (they would change with the compiler and break golden images for no
// physical reason), or the floor of a log plot of the energy error in the
// same frame, so that a frame names one threshold, not two.
double energy_floor(const scene::Scene& s) {
  double floor = 1e-13;
  for (const scene::ViewConfig& v : s.render.explain.views)
    if (v.kind == scene::ViewKind::plot && v.y_log && v.y_range &&
        std::find(v.series.begin(), v.series.end(), "energy_error") != v.series.end())
      floor = std::max(floor, (*v.y_range)[0]);
  return floor;
}

// "10⁻⁹" for a power of ten, else as format_for_people writes it.
std::string power_for_people(double v) {
  const std::string s = format_for_people(v, 1);
  const std::string one = "1\u00d7";
  return s.rfind(one, 0) == 0 ? s.substr(one.size()) : s;
}

// Three significant digits, fixed: "1.17", "0.293", "8.00" (not "8").
std::string three_digits(double v) {
  const int after = std::isfinite(v) && v != 0 ? std::clamp(2 - static_cast<int>(std::floor(std::log10(std::abs(v)))), 0, 6) : 2;
  char text[40];
  std::snprintf(text, sizeof text, "%.*f", after, v);
  return text;
}

// The angle between two vectors, degrees (atan2: exact near 0 and 180, where acos is not).
double degrees_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / std::numbers::pi;
}

// The angle between the first body's ω and L (world), degrees.
double omega_L_degrees(const viz::BodySnapshot& b) { return degrees_between(omega_world(*b.model, b.state), b.state.L); }

// The first body's energy and |L| (world), which stay fixed in a free body,
// then on a line of their own what changes: |ω| and the angle between ω and L
// (ω·L = 2E fixes only ω's part along L, so ω leans off L as it grows).
std::array<std::string, 2> state_readout(const viz::BodySnapshot& b) {
  const Eigen::Vector3d w = omega_world(*b.model, b.state), L = b.state.L;
  char angle[40];
  std::snprintf(angle, sizeof angle, "%.1f\u00b0", omega_L_degrees(b));
  return {"E = " + three_digits(total_energy(*b.model, b.state)) + " J   |L| = " + three_digits(L.norm()) +
              " kg\u00b7m\u00b2/s",
          "|\u03c9| = " + three_digits(w.norm()) + " rad/s   \u2220(\u03c9, L) = " + angle};
}

// The angle between the first body's ω and L (world), degrees: 0 for a spin
// about a principal axis; through a flip ω swings away from L and back.
std::string angle_readout(const viz::BodySnapshot& b) {
  const double deg = omega_L_degrees(b);
  char text[48];
  // Digits are two spaces wide: padded so that the readout never moves.
  std::snprintf(text, sizeof text, "\u2220(\u03c9, L) = %s%.1f\u00b0", deg < 10 ? "  " : "", deg);
  return text;
}

// The angle between the body's principal axis e_i (i = 0, 1, 2) and L
// (world), degrees: near 0 while it spins about e_i, past 90 once e_i has turned over.
std::string axis_angle_readout(const viz::BodySnapshot& b, int i) {
  const double deg = degrees_between(b.state.q * Eigen::Vector3d::Unit(i), b.state.L);
  static const char* kSub[] = {"\u2081", "\u2082", "\u2083"};
  char text[48];
  // Digits are two spaces wide: padded so that the readout never moves.
  std::snprintf(text, sizeof text, "\u2220(e%s, L) = %s%.1f\u00b0", kSub[i], deg < 10 ? "    " : deg < 100 ? "  " : "", deg);
  return text;
}

// The overlay lines: time, method, step, energy error, state, as the scene's overlay asks;
// the energy error on a line of its own where cells are narrow ([compare] arrange = "side").
std::vector<std::string> overlay_line(const scene::OverlayItems& items, const scene::Run& run, std::size_t run_count,
                                      const std::vector<viz::BodySnapshot>& snaps, double t, double floor,
                                      bool energy_apart) {
  // Largest relative energy error over the bodies: the failure users look
  // for. Only where energy is conserved (gravity is in it, as potential):
  // a thruster, torque or damping does work, and its change is no error.
  double rel = 0;  // signed: a method that gains energy shows '+'
  bool conserved = true;
  for (size_t i = 0; i < snaps.size(); ++i) {
    conserved = conserved && snaps[i].model->forces.conserves_energy();
    const double e0 = run.energy0[i];
    const double d = (total_energy(*snaps[i].model, snaps[i].state) - e0) / std::max(std::abs(e0), 1e-300);
    if (std::abs(d) > std::abs(rel) || std::isnan(d)) rel = d;
  }
  // For people: two digits, a power of ten written out, a percentage where it
  // is large; under the floor only the floor.
  std::string energy;
  if (!conserved) energy = "(forces do work)";
  else if (std::abs(rel) < floor) energy = "|\u0394E/E| < " + power_for_people(floor);
  else if (std::abs(rel) >= 1e-2) energy = "\u0394E/E = " + format_for_people(100 * rel, 2, true) + " %";
  else energy = "\u0394E/E = " + format_for_people(rel, 2, true);
  // Digits are two spaces wide in the font: padded so that "t =" never moves.
  char time[40];
  std::snprintf(time, sizeof time, "t = %s%.2f s", t < 10 ? "  " : "", t);
  std::string line;
  auto part = [&](bool on, const std::string& text) {
    if (on) line += (line.empty() ? "" : "   ") + text;
  };
  part(items.time, time);
  part(items.method && run_count == 1, run.label);
  part(items.step, run.step_label);
  std::vector<std::string> lines;
  if (energy_apart && items.energy && !line.empty()) lines.push_back(std::exchange(line, std::string()));
  part(items.energy, energy);
  if (items.state && !snaps.empty()) {
    const std::array<std::string, 2> state = state_readout(snaps.front());
    part(true, state[0]);
    lines.push_back(std::exchange(line, state[1]));
  }
  part(items.angle && !snaps.empty(), snaps.empty() ? std::string() : angle_readout(snaps.front()));
  const bool axes[3] = {items.e1_angle, items.e2_angle, items.e3_angle};
  for (int i = 0; i < 3; ++i) part(axes[i] && !snaps.empty(), snaps.empty() ? std::string() : axis_angle_readout(snaps.front(), i));
  lines.push_back(line);
  return lines;
}

bool energy_apart(const scene::Scene& s) {
  return s.render.compare_arrange == scene::CompareArrange::side && s.render.draw.overlay_items.energy &&
         (s.render.draw.overlay_items.time || s.render.draw.overlay_items.step);
}

}  // namespace

viz::Camera across_camera(const Eigen::Vector3d& target, const Eigen::Vector3d& L, int sign, double azimuth_deg,
                          double elevation_deg, double distance, double fov_y_deg, double roll_deg) {
  const Eigen::Vector3d l = L.norm() > 0 ? Eigen::Vector3d(sign * L.normalized()) : Eigen::Vector3d::UnitZ();
  Eigen::Vector3d u = -Eigen::Vector3d::UnitY() + l.y() * l;  // the side nearest world −y
  if (u.norm() < 1e-3) u = Eigen::Vector3d::UnitX() - l.x() * l;
  u.normalize();
  const Eigen::Vector3d v = l.cross(u);
  const double az = azimuth_deg * M_PI / 180, el = elevation_deg * M_PI / 180;
  const Eigen::Vector3d d = std::cos(el) * (std::cos(az) * u + std::sin(az) * v) + std::sin(el) * l;
  viz::Camera c;
  c.target = to_glm(target);
  c.position = to_glm(target + distance * d);
  // Rolled about the line of sight by `roll_deg`: L turns clockwise in the picture (90: L points right).
  const Eigen::Vector3d right = (-d).cross(l).normalized();
  const double roll = roll_deg * M_PI / 180;
  c.up = to_glm(std::cos(roll) * l - std::sin(roll) * right);
  c.fov_y_deg = fov_y_deg;
  c.near_m = 0.02 * distance;
  c.far_m = 50 * distance;
  return c;
}

viz::Camera scene_camera(const scene::Scene& s, const std::vector<std::vector<glm::dvec3>>& centres, double aspect) {
  const scene::CameraConfig& c = s.render.camera;
  viz::Camera camera;
  if (c.across != 0 && !s.bodies.empty()) {
    // Across the followed (else the first) body's L, far enough to hold every body; the views fit it closer.
    const scene::Body* b = s.find_body(c.follow);
    if (!b) b = &s.bodies.front();
    double reach = 0;
    for (std::size_t i = 0; i < centres.size() && i < s.bodies.size(); ++i)
      for (const glm::dvec3& p : centres[i])
        if (std::isfinite(p.x + p.y + p.z) && glm::length(p) < 1e6)
          reach = std::max(reach, glm::length(p - to_glm(c.target)) + 3 * viz::box_radius(s.bodies[i].model));
    const double half = 0.5 * c.fov_y_deg * M_PI / 180 * std::min(1.0, aspect);
    return across_camera(c.target, b->initial.L, c.across, c.azimuth_deg, c.elevation_deg,
                         std::max(reach, 1e-3) / std::sin(half), c.fov_y_deg, c.roll_deg);
  }
  if (c.automatic) {
    // Frame every body over the whole run (all runs: a failing method may drift).
    std::vector<glm::dvec3> points;
    std::vector<double> radii;
    for (size_t i = 0; i < centres.size() && i < s.bodies.size(); ++i)
      for (const glm::dvec3& p : centres[i]) {
        if (!std::isfinite(p.x + p.y + p.z) || glm::length(p) > 1e6) continue;
        points.push_back(p);
        radii.push_back(viz::box_radius(s.bodies[i].model) * 1.15);
      }
    return viz::auto_camera(points, radii, c.fov_y_deg, aspect);
  }
  camera.position = to_glm(c.position);
  camera.target = to_glm(c.target);
  camera.up = to_glm(c.up);
  camera.fov_y_deg = c.fov_y_deg;
  return camera;
}

viz::Camera scene_camera(const scene::Scene& s, const std::vector<scene::Run>& runs, double aspect) {
  std::vector<std::vector<glm::dvec3>> centres(s.bodies.size());
  if (s.render.camera.automatic || s.render.camera.across != 0)
    for (const scene::Run& r : runs)
      for (const auto& states : r.frames)
        for (size_t i = 0; i < states.size() && i < centres.size(); ++i) centres[i].push_back(to_glm(states[i].c));
  return scene_camera(s, centres, aspect);
}

viz::GridItem ground_grid(const scene::Scene& s, const std::vector<scene::Run>& runs) {
  // Fixed for the whole video: below the lowest any body comes, centred
  // under where the bodies go, wide enough for all of it.
  double zmin = 1e300, size = 0;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
  for (const scene::Run& r : runs)
    for (const auto& states : r.frames)
      for (std::size_t i = 0; i < states.size() && i < s.bodies.size(); ++i) {
        if (!states[i].c.allFinite() || states[i].c.norm() > 1e6) continue;
        const double rad = viz::box_radius(s.bodies[i].model);
        zmin = std::min(zmin, states[i].c.z() - rad);
        lo = lo.cwiseMin(states[i].c), hi = hi.cwiseMax(states[i].c);
        size = std::max(size, rad);
      }
  if (zmin > 1e299) return {{0, 0, 0}, 0.5, 20, {0.5f, 0.52f, 0.58f, 0.5f}};
  // About ten squares across where the bodies go: 1, 2 or 5 times a power of ten, m.
  const double reach = 0.5 * (hi - lo).head<2>().norm() + 4 * size;
  const double rough = reach / 5, decade = std::pow(10.0, std::floor(std::log10(std::max(rough, 1e-6))));
  const double spacing = rough >= 5 * decade ? 5 * decade : rough >= 2 * decade ? 2 * decade : decade;
  const int half = static_cast<int>(std::clamp(std::ceil(3 * reach / spacing), 8.0, 40.0));  // it fades out at its rim
  const Eigen::Vector3d mid = 0.5 * (lo + hi);
  return {{spacing * std::round(mid.x() / spacing), spacing * std::round(mid.y() / spacing), zmin}, spacing, half,
          {0.5f, 0.52f, 0.58f, 0.5f}};
}

WorldViews::WorldViews(const scene::Scene& s, const std::vector<scene::Run>& runs, const scene::FrameClock& clock,
                       float font_px)
    : scene_(s), runs_(runs), clock_(clock), font_px_(font_px), draw_(s.render.draw) {
  for (const scene::Body& b : s.bodies) looks_.push_back(body_look(b, draw_.particles));
  // Trails see every frame from t = 0, so a frame range draws what a full run does.
  trails_.resize(runs.size());
  if (draw_.trail_seconds > 0)
    for (size_t r = 0; r < runs.size(); ++r)
      for (size_t j = 0; j < runs[r].path.size(); ++j)
        trails_[r].record(runs[r].path_t[j], snapshots(s, runs[r].path[j]));
  grid_ = ground_grid(s, runs);
}

viz::View WorldViews::view(std::size_t r, long k, const viz::Camera& camera, int width_px, int height_px,
                           std::optional<std::size_t> only) const {
  const scene::Run& run = runs_[r];
  viz::View v;
  v.camera = camera;
  const long kk = std::min(k, static_cast<long>(run.frames.size()) - 1);
  if (kk < 0) return v;
  auto snaps = snapshots(scene_, run.frames[static_cast<size_t>(kk)], &looks_);
  if (only && *only < snaps.size()) snaps = {snaps[*only]};
  const scene::Body* follow = scene_.find_body(scene_.render.camera.follow);
  if (follow) {
    const glm::dvec3 c = to_glm(run.frames[static_cast<size_t>(kk)][static_cast<size_t>(follow - scene_.bodies.data())].c);
    v.camera.position += c - v.camera.target;
    v.camera.target = c;
  }
  viz::add_bodies(v, snaps, draw_, only ? nullptr : &trails_[r], clock_.time(kk));
  // Beside the exact solution, every other method's cell shows it faintly.
  const auto exact = std::find_if(runs_.begin(), runs_.end(), [](const scene::Run& x) { return x.label == "exact"; });
  if (!only && runs_.size() > 1 && exact != runs_.end() && &*exact != &run) {
    const long ke = std::min(k, static_cast<long>(exact->frames.size()) - 1);
    if (ke >= 0) viz::add_ghosts(v, snapshots(scene_, exact->frames[static_cast<size_t>(ke)], &looks_), kGhostColor);
  }
  if (draw_.grid) v.grids.push_back(grid_);
  if (scene_.render.explain.labels) add_labels(v, snaps, draw_, width_px, height_px, font_px_);
  return v;
}

std::vector<viz::PolylineItem> WorldViews::trails(std::size_t r, long k, std::size_t b,
                                                  std::optional<std::array<bool, 3>> axes,
                                                  std::optional<double> seconds) const {
  const long kk = std::min(k, static_cast<long>(runs_[r].frames.size()) - 1);
  const double s = seconds.value_or(draw_.trail_seconds);
  if (s <= 0 || kk < 0) return {};
  return trails_[r].polylines(clock_.time(kk), s, axes.value_or(draw_.trail_axes), b);
}

std::vector<std::string> WorldViews::overlay(std::size_t r, long k) const {
  const scene::Run& run = runs_[r];
  std::vector<std::string> out;
  const long last = static_cast<long>(run.frames.size()) - 1;
  const long kk = std::min(k, last);
  if (scene_.render.draw.overlay && kk >= 0)
    out = overlay_line(scene_.render.draw.overlay_items, run, runs_.size(),
                       snapshots(scene_, run.frames[static_cast<size_t>(kk)]), clock_.time(k), energy_floor(scene_),
                       energy_apart(scene_));
  if (run.diverged && k > last)
    out.push_back("diverged: stopped at t = " + std::to_string(clock_.time(last)).substr(0, 6) + " s");
  return out;
}

// A view's column is narrow: each item on a line of its own (the state's two lines as they are).
std::vector<std::string> WorldViews::readout(std::size_t r, long k, std::size_t b, const scene::OverlayItems& items) const {
  const scene::Run& run = runs_[r];
  const long kk = std::min(k, static_cast<long>(run.frames.size()) - 1);
  if (kk < 0) return {};
  const std::vector<viz::BodySnapshot> all = snapshots(scene_, run.frames[static_cast<size_t>(kk)]);
  if (b >= all.size()) return {};
  std::vector<std::string> out;
  for (const scene::OverlayItems& one : readout_items(items))
    for (std::string& line : overlay_line(one, run, runs_.size(), {all[b]}, clock_.time(k), 0, false)) out.push_back(std::move(line));
  return out;
}

// A view's readout items one at a time, in the overlay's order.
std::vector<scene::OverlayItems> WorldViews::readout_items(const scene::OverlayItems& items) {
  std::vector<scene::OverlayItems> out;
  const scene::OverlayItems none{false, false, false, false};
  auto add = [&](bool on, bool scene::OverlayItems::*member) {
    if (!on) return;
    out.push_back(none);
    out.back().*member = true;
  };
  add(items.time, &scene::OverlayItems::time);
  add(items.state, &scene::OverlayItems::state);
  add(items.angle, &scene::OverlayItems::angle);
  add(items.e1_angle, &scene::OverlayItems::e1_angle);
  add(items.e2_angle, &scene::OverlayItems::e2_angle);
  add(items.e3_angle, &scene::OverlayItems::e3_angle);
  return out;
}

int WorldViews::readout_lines(const scene::OverlayItems& items) {
  return static_cast<int>(readout_items(items).size()) + (items.state ? 1 : 0);
}

int WorldViews::overlay_lines(std::size_t r) const {
  const scene::DrawConfig& d = scene_.render.draw;
  return (d.overlay ? (energy_apart(scene_) ? 2 : 1) + (d.overlay_items.state ? 1 : 0) : 0) + (runs_[r].diverged ? 1 : 0);
}

}  // namespace tumble::compose
