#include "render/mesh_geometry.hpp"

#include <cmath>
#include <numbers>

namespace tumble::render {
namespace {

using Index = std::uint32_t;

Index add(MeshData& m, glm::vec3 p, glm::vec3 n) {
  m.vertices.push_back({p, n});
  return static_cast<Index>(m.vertices.size() - 1);
}

void tri(MeshData& m, Index a, Index b, Index c) { m.indices.insert(m.indices.end(), {a, b, c}); }

glm::vec2 ring(int i, int segments) {
  const double a = 2.0 * std::numbers::pi * i / segments;
  return {static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a))};
}

// Flat disk at height z facing +z (up) or -z.
void disk(MeshData& m, float z, bool up, int segments) {
  const glm::vec3 n(0, 0, up ? 1.f : -1.f);
  const Index centre = add(m, {0, 0, z}, n);
  const Index first = static_cast<Index>(m.vertices.size());
  for (int i = 0; i < segments; ++i) add(m, glm::vec3(ring(i, segments), z), n);
  for (int i = 0; i < segments; ++i) {
    const Index a = first + i, b = first + (i + 1) % segments;
    up ? tri(m, centre, a, b) : tri(m, centre, b, a);
  }
}

}  // namespace

MeshData unit_cube() {
  MeshData m;
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {-1.f, 1.f}) {
      glm::vec3 n(0), u(0), v(0);
      n[axis] = sign;
      u[(axis + 1) % 3] = 1;
      v[(axis + 2) % 3] = 1;
      if (sign < 0) std::swap(u, v);  // keep u x v = n so winding faces out
      const Index base = add(m, n - u - v, n);
      add(m, n + u - v, n);
      add(m, n + u + v, n);
      add(m, n - u + v, n);
      tri(m, base, base + 1, base + 2);
      tri(m, base, base + 2, base + 3);
    }
  }
  return m;
}

MeshData unit_cylinder(int segments) {
  MeshData m;
  const Index first = static_cast<Index>(m.vertices.size());
  for (int i = 0; i < segments; ++i) {
    const glm::vec2 r = ring(i, segments);
    add(m, {r, 0}, {r, 0});
    add(m, {r, 1}, {r, 0});
  }
  for (int i = 0; i < segments; ++i) {
    const Index a = first + 2 * i, b = first + 2 * ((i + 1) % segments);
    tri(m, a, b, b + 1);
    tri(m, a, b + 1, a + 1);
  }
  disk(m, 0, false, segments);
  disk(m, 1, true, segments);
  return m;
}

MeshData unit_cone(int segments) {
  MeshData m;
  // Slant normal of a cone with height 1 and radius 1: (cos, sin, 1)/sqrt2.
  // The tip is duplicated per segment so each facet gets its own normal.
  for (int i = 0; i < segments; ++i) {
    const glm::vec2 r0 = ring(i, segments), r1 = ring(i + 1, segments);
    const glm::vec2 rm = ring(2 * i + 1, 2 * segments);
    const Index a = add(m, {r0, 0}, glm::normalize(glm::vec3(r0, 1)));
    const Index b = add(m, {r1, 0}, glm::normalize(glm::vec3(r1, 1)));
    const Index tip = add(m, {0, 0, 1}, glm::normalize(glm::vec3(rm, 1)));
    tri(m, a, b, tip);
  }
  disk(m, 0, false, segments);
  return m;
}

MeshData unit_sphere(int slices, int stacks) {
  MeshData m;
  for (int j = 0; j <= stacks; ++j) {
    const double theta = std::numbers::pi * j / stacks;
    for (int i = 0; i <= slices; ++i) {
      const glm::vec2 r = ring(i, slices);
      const glm::vec3 p(r * static_cast<float>(std::sin(theta)),
                        static_cast<float>(-std::cos(theta)));
      add(m, p, p);
    }
  }
  const int row = slices + 1;
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const Index a = j * row + i, b = a + 1, c = a + row, d = c + 1;
      tri(m, a, b, d);
      tri(m, a, d, c);
    }
  }
  return m;
}

}  // namespace tumble::render
