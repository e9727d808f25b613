#include "render/sphere_pass.hpp"

#include <cstddef>

namespace tumble::render {
namespace {

const void* offset(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

}  // namespace

SpherePass::SpherePass(const GlFunctions& gl, const std::filesystem::path& shader_dir)
    : gl_(&gl),
      program_(gl, shader_dir, "sphere"),
      vao_(make_vertex_array(gl)),
      instances_(make_buffer(gl)) {
  gl.BindVertexArray(vao_.id());
  gl.BindBuffer(GL_ARRAY_BUFFER, instances_.id());
  gl.EnableVertexAttribArray(0);
  gl.VertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(SphereInstance),
                         offset(offsetof(SphereInstance, sphere)));
  gl.VertexAttribDivisor(0, 1);
  gl.EnableVertexAttribArray(1);
  gl.VertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(SphereInstance),
                         offset(offsetof(SphereInstance, color)));
  gl.VertexAttribDivisor(1, 1);
  gl.BindVertexArray(0);
}

void SpherePass::draw(const std::vector<SphereInstance>& spheres, const glm::mat4& view,
                      const glm::mat4& proj, const glm::vec3& light_dir, float specular,
                      bool multisampled) const {
  if (spheres.empty()) return;
  program_.use();
  program_.set("u_view", view);
  program_.set("u_proj", proj);
  program_.set("u_light_dir", light_dir);
  program_.set("u_specular", specular);
  program_.set("u_coverage", multisampled ? 1 : 0);
  gl_->BindVertexArray(vao_.id());
  gl_->BindBuffer(GL_ARRAY_BUFFER, instances_.id());
  // Orphaning (not SubData): llvmpipe would flush the frame so far before
  // overwriting a buffer its queued draws still read.
  gl_->BufferData(GL_ARRAY_BUFFER, spheres.size() * sizeof(SphereInstance), spheres.data(),
                  GL_STREAM_DRAW);
  if (multisampled) {
    gl_->Disable(GL_BLEND);
    gl_->Enable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  }
  gl_->DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(spheres.size()));
  if (multisampled) {
    gl_->Disable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    gl_->Enable(GL_BLEND);
  }
}

}  // namespace tumble::render
