// Draws viz::SurfaceItem meshes, lit and opaque, with the instanced mesh
// shader (one instance each). A mesh is uploaded once and kept on the GPU
// while its draw-list item's SurfaceMesh lives.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "render/instanced_mesh.hpp"
#include "render/shader_program.hpp"
#include "viz/draw_list.hpp"

namespace tumble::render {

class SurfacePass {
 public:
  SurfacePass(const GlFunctions& gl, const std::filesystem::path& shader_dir);
  void draw(const std::vector<viz::SurfaceItem>& items, const glm::mat4& view, const glm::mat4& proj,
            const glm::vec3& light_dir);

 private:
  struct Cached {
    std::weak_ptr<const viz::SurfaceMesh> source;
    std::unique_ptr<InstancedMesh> mesh;
  };
  InstancedMesh& upload(const std::shared_ptr<const viz::SurfaceMesh>& m);

  const GlFunctions* gl_;
  ShaderProgram program_;
  std::map<const viz::SurfaceMesh*, Cached> cache_;
};

}  // namespace tumble::render
