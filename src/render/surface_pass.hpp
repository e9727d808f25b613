// Draws viz::SurfaceItem meshes, lit, with the instanced mesh shader (one
// instance each): the opaque ones in the scene's depth pass, the translucent
// ones (alpha < 1) last, without depth writes, back faces before front faces. A mesh is uploaded once and kept on the GPU
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
  /// The opaque items (alpha = 1).
  void draw(const std::vector<viz::SurfaceItem>& items, const glm::mat4& view, const glm::mat4& proj,
            const glm::vec3& light_dir);
  /// The translucent items: exact for one convex surface, close enough for a few.
  void draw_translucent(const std::vector<viz::SurfaceItem>& items, const glm::mat4& view, const glm::mat4& proj,
                        const glm::vec3& light_dir);

 private:
  struct Cached {
    std::weak_ptr<const viz::SurfaceMesh> source;
    std::unique_ptr<InstancedMesh> mesh;
  };
  InstancedMesh& upload(const std::shared_ptr<const viz::SurfaceMesh>& m);
  void draw_items(const std::vector<viz::SurfaceItem>& items, const glm::mat4& view, const glm::mat4& proj,
                  const glm::vec3& light_dir, bool translucent);

  const GlFunctions* gl_;
  ShaderProgram program_;
  std::map<const viz::SurfaceMesh*, Cached> cache_;
};

}  // namespace tumble::render
