// CPU-side unit shapes, built once and instanced with per-item transforms.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace tumble::render {

struct MeshVertex {
  glm::vec3 position;
  glm::vec3 normal;
};

struct MeshData {
  std::vector<MeshVertex> vertices;
  std::vector<std::uint32_t> indices;  ///< triangles, counter-clockwise outside
};

MeshData unit_cube();                        ///< [-1, 1]^3, flat faces
MeshData unit_cylinder(int segments);        ///< radius 1, z in [0, 1], capped
MeshData unit_cone(int segments);            ///< base radius 1 at z = 0, tip z = 1
MeshData unit_sphere(int slices, int stacks);  ///< radius 1, centred

}  // namespace tumble::render
