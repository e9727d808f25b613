// Particles as ray-cast sphere impostors: one quad per sphere instead of a
// tessellated mesh, so thousands of particles cost a few thousand vertices and
// only the pixels they cover. The quads are plain indexed triangles (four
// vertices per sphere), not instances: llvmpipe runs an instanced draw through
// its vertex pipeline once per instance, which cost ~3 µs per particle.
// A body's particle set is uploaded once; each frame only the indices of the
// particles that face the eye (viz::faces_eye) at the chosen level of detail
// (viz::particle_level) are sent, and the set is placed by its model matrix.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "render/gl_object.hpp"
#include "render/shader_program.hpp"
#include "viz/draw_list.hpp"

namespace tumble::render {

struct SphereInstance {
  glm::vec4 sphere;  ///< centre xyz (world, or a particle set's cloud axes), radius w (m)
  glm::vec4 color;
};

/// Lighting and anti-aliasing shared by every sphere of a view.
struct SphereShading {
  glm::vec3 light_dir;  ///< view space, unit, towards the light
  float specular;
  bool multisampled;    ///< anti-alias the rims by alpha-to-coverage (blending off for the pass)
};

/// Triangle indices of the quads of spheres `which` (each sphere owns vertices 4i .. 4i + 3).
void append_quads(const std::vector<std::uint32_t>& which, std::vector<std::uint32_t>& indices);

class SpherePass {
 public:
  SpherePass(const GlFunctions& gl, const std::filesystem::path& shader_dir);

  /// Draws lit, depth-writing spheres given in world coordinates.
  void draw(const std::vector<SphereInstance>& spheres, const glm::mat4& view, const glm::mat4& proj,
            const SphereShading& shading);

  /// Draws bodies' particle sets, each at the level of detail viz::particle_level
  /// picks for `camera` and a viewport `viewport_height_px` high, without the
  /// particles facing away from the eye.
  void draw(const std::vector<viz::ParticlesItem>& items, const viz::Camera& camera, const glm::mat4& view,
            const glm::mat4& proj, double viewport_height_px, const SphereShading& shading);

 private:
  struct Batch {  // spheres on the GPU, four vertices each
    GlObject vao, vertices, indices;
  };
  struct Cached {
    std::weak_ptr<const viz::ParticleSet> source;
    std::vector<Batch> levels;
  };
  Batch make_batch() const;
  void fill(const Batch& b, const std::vector<SphereInstance>& spheres, GLenum usage) const;
  void draw_indexed(const Batch& b, const std::vector<std::uint32_t>& indices) const;
  const Cached& upload(const std::shared_ptr<const viz::ParticleSet>& set);
  void begin(const glm::mat4& proj, const SphereShading& shading) const;
  void end(const SphereShading& shading) const;

  const GlFunctions* gl_;
  ShaderProgram program_;
  Batch loose_;  // per-call world-space spheres
  std::map<const viz::ParticleSet*, Cached> cache_;
  std::vector<std::uint32_t> which_, indices_;  // per-draw scratch, kept to reuse their memory
};

}  // namespace tumble::render
