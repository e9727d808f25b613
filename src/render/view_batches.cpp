#include "render/view_batches.hpp"

#include <algorithm>
#include <cmath>

namespace tumble::render {
namespace {

// Arrow proportions relative to the shaft radius; the head is capped to a
// fraction of the length so short arrows still read as arrows.
constexpr double kHeadRadius = 2.4;
constexpr double kHeadLength = 6.0;
constexpr double kMaxHeadFraction = 0.4;

// Model matrix mapping the unit z-axis shape onto `axis` (unit) with the
// given radial/axial scales, starting at `base`.
glm::mat4 along_axis(const glm::dvec3& base, const glm::dvec3& axis, double radial,
                     double length) {
  const glm::dvec3 helper =
      std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 u = glm::normalize(glm::cross(helper, axis));
  const glm::dvec3 v = glm::cross(axis, u);
  return glm::mat4(glm::dmat4(glm::dvec4(u * radial, 0), glm::dvec4(v * radial, 0),
                              glm::dvec4(axis * length, 0), glm::dvec4(base, 1)));
}

void add_arrow(const viz::ArrowItem& a, ViewBatches& out) {
  const double length = glm::length(a.vector);
  if (!(length > 1e-12) || !(a.radius > 0)) return;
  const glm::dvec3 dir = a.vector / length;
  const double head = std::min(kHeadLength * a.radius, kMaxHeadFraction * length);
  const double shaft = length - head;
  out.arrow_shafts.push_back({along_axis(a.origin, dir, a.radius, shaft), a.color});
  out.arrow_heads.push_back(
      {along_axis(a.origin + dir * shaft, dir, kHeadRadius * a.radius, head), a.color});
}

void add_box(const viz::BoxItem& b, ViewBatches& out) {
  const glm::dmat3 axes = b.rotation * glm::dmat3(glm::dvec3(b.half_extents.x, 0, 0),
                                                  glm::dvec3(0, b.half_extents.y, 0),
                                                  glm::dvec3(0, 0, b.half_extents.z));
  if (b.face.a > 0)  // an outline has no faces
    out.boxes.push_back({glm::mat4(glm::dmat4(glm::dvec4(axes[0], 0), glm::dvec4(axes[1], 0),
                                              glm::dvec4(axes[2], 0), glm::dvec4(b.center, 1))),
                         b.face});
  // Corner k has sign bits (x, y, z) = bits 0, 1, 2; edges join corners that
  // differ in exactly one bit.
  auto corner = [&](int k) {
    return glm::vec3(b.center + axes[0] * ((k & 1) ? 1.0 : -1.0) +
                     axes[1] * ((k & 2) ? 1.0 : -1.0) + axes[2] * ((k & 4) ? 1.0 : -1.0));
  };
  for (int k = 0; k < 8; ++k) {
    for (int bit = 1; bit < 8; bit <<= 1) {
      if (k & bit) continue;
      out.box_edges.push_back({corner(k), b.edge});
      out.box_edges.push_back({corner(k | bit), b.edge});
    }
  }
}

// Lines are split into cells so alpha can fade towards the grid's rim.
void add_grid(const viz::GridItem& g, ViewBatches& out) {
  const int n = std::max(g.half_count, 1);
  const double extent = n * g.spacing;
  auto faded = [&](double x, double y) {
    const double r = std::min(1.0, std::hypot(x, y) / extent);
    glm::vec4 c = g.color;
    c.a *= static_cast<float>(1.0 - r * r);
    return c;
  };
  for (int axis = 0; axis < 2; ++axis) {
    for (int i = -n; i <= n; ++i) {
      for (int j = -n; j < n; ++j) {
        const double fixed = i * g.spacing, a = j * g.spacing, b = (j + 1) * g.spacing;
        const glm::dvec2 p = axis == 0 ? glm::dvec2(a, fixed) : glm::dvec2(fixed, a);
        const glm::dvec2 q = axis == 0 ? glm::dvec2(b, fixed) : glm::dvec2(fixed, b);
        out.grid.push_back({glm::vec3(g.origin + glm::dvec3(p, 0)), faded(p.x, p.y)});
        out.grid.push_back({glm::vec3(g.origin + glm::dvec3(q, 0)), faded(q.x, q.y)});
      }
    }
  }
}

void add_polyline(const viz::PolylineItem& p, ViewBatches& out) {
  if (p.points.size() < 2) return;
  Polyline line{{}, p.width_px, p.over_glass};
  line.strip.reserve(p.points.size());
  const double last = static_cast<double>(p.points.size() - 1);
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    glm::vec4 c = p.color;
    if (p.fade) c.a *= static_cast<float>(0.04 + 0.96 * (static_cast<double>(i) / last));
    line.strip.push_back({glm::vec3(p.points[i]), c});
  }
  out.polylines.push_back(std::move(line));
}

}  // namespace

ViewBatches build_view_batches(const viz::View& view) {
  ViewBatches out;
  for (const auto& a : view.arrows) add_arrow(a, out);
  for (const auto& pt : view.points) {
    if (!(pt.radius > 0)) continue;
    out.spheres.push_back({glm::vec4(glm::vec3(pt.position), float(pt.radius)), pt.color});
  }

  // Translucent boxes blend correctly only when drawn far to near.
  std::vector<const viz::BoxItem*> boxes;
  for (const auto& b : view.boxes) boxes.push_back(&b);
  const glm::dvec3 eye = view.camera.position;
  std::stable_sort(boxes.begin(), boxes.end(), [&](const auto* a, const auto* b) {
    return glm::length(a->center - eye) > glm::length(b->center - eye);
  });
  for (const auto* b : boxes) add_box(*b, out);

  for (const auto& g : view.grids) add_grid(g, out);
  for (const auto& p : view.polylines) add_polyline(p, out);
  return out;
}

}  // namespace tumble::render
