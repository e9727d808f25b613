// A glTF model grown piece by piece (tinygltf's structs, one buffer): flat
// triangle geometry, materials, meshes, nodes and animation channels.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <tiny_gltf.h>

#include "core/triangle_mesh.hpp"
#include "viz/draw_list.hpp"

namespace tumble::gltf {

/// Flat-shaded triangles: positions and normals per corner (3 floats each).
struct Geometry {
  std::vector<float> positions, normals;
  std::vector<std::uint32_t> indices;
};

/// Adds a triangle; one without area (a flat box's edge faces) is left out,
/// as it has no normal (glTF requires unit normals).
void add_triangle(Geometry& g, const std::array<Eigen::Vector3d, 3>& p);
/// The box [lo, hi] (m), outward counter-clockwise faces.
Geometry box_geometry(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);
void append_mesh(Geometry& g, const TriangleMesh& m);
/// A surface as the renderer draws it (corners in threes, each with its normal).
Geometry surface_geometry(const viz::SurfaceMesh& m);

/// glTF's (x, y, z, w) and (x, y, z) of Eigen's values.
std::vector<double> rotation(const Eigen::Quaterniond& q);
std::vector<double> vec(const Eigen::Vector3d& v);

class Builder {
 public:
  Builder();
  tinygltf::Model& model() { return model_; }

  /// An accessor over `data` (`comps` floats per element), with min/max when asked.
  int floats(const std::vector<float>& data, int type, int comps, int target, bool bounds);
  int material(const Eigen::Vector3d& rgb, const std::string& name);
  /// Adds `g` as one primitive of mesh `mesh` (created when -1); returns the mesh.
  int primitive(int mesh, const std::string& name, const Geometry& g, int material);
  /// A node (child of `parent`, or a root of the scene when -1).
  int node(const std::string& name, int parent, int mesh = -1);
  tinygltf::Node& at(int node) { return model_.nodes[static_cast<std::size_t>(node)]; }
  /// A LINEAR channel of `anim` moving `path` ("translation", "rotation") of `node`.
  void channel(tinygltf::Animation& anim, int node, const char* path, int times, int values);

 private:
  int add_view(const void* bytes, std::size_t size, int target);
  tinygltf::Model model_;
};

}  // namespace tumble::gltf
