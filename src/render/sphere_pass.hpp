// Particles as ray-cast sphere impostors: one instanced quad per sphere
// instead of a tessellated mesh, so thousands of particles cost a few
// thousand vertices and only the pixels they cover.
#pragma once

#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "render/gl_object.hpp"
#include "render/shader_program.hpp"

namespace tumble::render {

struct SphereInstance {
  glm::vec4 sphere;  ///< world centre xyz, radius w (m)
  glm::vec4 color;
};

class SpherePass {
 public:
  SpherePass(const GlFunctions& gl, const std::filesystem::path& shader_dir);

  /// Draws lit, depth-writing spheres. `multisampled`: anti-alias the rims by
  /// alpha-to-coverage (blending is switched off for the pass and back on).
  void draw(const std::vector<SphereInstance>& spheres, const glm::mat4& view,
            const glm::mat4& proj, const glm::vec3& light_dir, float specular,
            bool multisampled) const;

 private:
  const GlFunctions* gl_;
  ShaderProgram program_;
  GlObject vao_, instances_;
};

}  // namespace tumble::render
