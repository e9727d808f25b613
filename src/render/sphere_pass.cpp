#include "render/sphere_pass.hpp"

#include <cstddef>
#include <numeric>

#include "viz/particle_set.hpp"

namespace tumble::render {
namespace {

const void* sphere_offset(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

}  // namespace

void append_quads(const std::vector<std::uint32_t>& which, std::vector<std::uint32_t>& indices) {
  indices.reserve(indices.size() + 6 * which.size());
  for (const std::uint32_t i : which) {
    const std::uint32_t v = 4 * i;  // corners (-1,-1), (1,-1), (-1,1), (1,1): see sphere.vert
    indices.insert(indices.end(), {v, v + 1, v + 2, v + 2, v + 1, v + 3});
  }
}

SpherePass::SpherePass(const GlFunctions& gl, const std::filesystem::path& shader_dir)
    : gl_(&gl), program_(gl, shader_dir, "sphere"), loose_(make_batch()) {}

SpherePass::Batch SpherePass::make_batch() const {
  Batch b{make_vertex_array(*gl_), make_buffer(*gl_), make_buffer(*gl_)};
  gl_->BindVertexArray(b.vao.id());
  gl_->BindBuffer(GL_ARRAY_BUFFER, b.vertices.id());
  gl_->EnableVertexAttribArray(0);
  gl_->VertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(SphereInstance), sphere_offset(offsetof(SphereInstance, sphere)));
  gl_->EnableVertexAttribArray(1);
  gl_->VertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(SphereInstance), sphere_offset(offsetof(SphereInstance, color)));
  gl_->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.indices.id());
  gl_->BindVertexArray(0);
  return b;
}

void SpherePass::fill(const Batch& b, const std::vector<SphereInstance>& spheres, GLenum usage) const {
  std::vector<SphereInstance> corners;
  corners.reserve(4 * spheres.size());
  for (const SphereInstance& s : spheres) corners.insert(corners.end(), 4, s);
  gl_->BindBuffer(GL_ARRAY_BUFFER, b.vertices.id());
  gl_->BufferData(GL_ARRAY_BUFFER, corners.size() * sizeof(SphereInstance), corners.data(), usage);
}

void SpherePass::draw_indexed(const Batch& b, const std::vector<std::uint32_t>& indices) const {
  if (indices.empty()) return;
  gl_->BindVertexArray(b.vao.id());
  // Orphaning (not SubData): llvmpipe would flush the frame so far before
  // overwriting a buffer its queued draws still read.
  gl_->BufferData(GL_ELEMENT_ARRAY_BUFFER, indices.size() * sizeof(std::uint32_t), indices.data(), GL_STREAM_DRAW);
  gl_->DrawElementsInstanced(GL_TRIANGLES, static_cast<GLsizei>(indices.size()), GL_UNSIGNED_INT, nullptr, 1);
}

const SpherePass::Cached& SpherePass::upload(const std::shared_ptr<const viz::ParticleSet>& set) {
  // Forget sets whose owner is gone (their address may be reused).
  std::erase_if(cache_, [](const auto& kv) { return kv.second.source.expired(); });
  auto it = cache_.find(set.get());
  if (it != cache_.end()) return it->second;
  Cached c{set, {}};
  for (const viz::ParticleLevel& level : set->levels) {
    std::vector<SphereInstance> spheres;
    spheres.reserve(level.positions.size());
    for (std::size_t i = 0; i < level.positions.size(); ++i)
      spheres.push_back({glm::vec4(level.positions[i], level.radius), level.colors[i]});
    c.levels.push_back(make_batch());
    fill(c.levels.back(), spheres, GL_STATIC_DRAW);
  }
  return cache_.emplace(set.get(), std::move(c)).first->second;
}

void SpherePass::begin(const glm::mat4& proj, const SphereShading& shading) const {
  program_.use();
  program_.set("u_proj", proj);
  program_.set("u_light_dir", shading.light_dir);
  program_.set("u_specular", shading.specular);
  program_.set("u_coverage", shading.multisampled ? 1 : 0);
  if (shading.multisampled) {
    gl_->Disable(GL_BLEND);
    gl_->Enable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  }
}

void SpherePass::end(const SphereShading& shading) const {
  if (shading.multisampled) {
    gl_->Disable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    gl_->Enable(GL_BLEND);
  }
}

void SpherePass::draw(const std::vector<SphereInstance>& spheres, const glm::mat4& view, const glm::mat4& proj,
                      const SphereShading& shading) {
  if (spheres.empty()) return;
  begin(proj, shading);
  program_.set("u_model_view", view);
  fill(loose_, spheres, GL_STREAM_DRAW);
  which_.resize(spheres.size());
  std::iota(which_.begin(), which_.end(), 0u);
  indices_.clear();
  append_quads(which_, indices_);
  draw_indexed(loose_, indices_);
  end(shading);
}

void SpherePass::draw(const std::vector<viz::ParticlesItem>& items, const viz::Camera& camera, const glm::mat4& view,
                      const glm::mat4& proj, double viewport_height_px, const SphereShading& shading) {
  if (items.empty()) return;
  begin(proj, shading);
  for (const viz::ParticlesItem& item : items) {
    if (!item.set || item.set->levels.empty()) continue;
    const std::size_t l = viz::particle_level(*item.set, item.model, camera, viewport_height_px);
    const Batch& b = upload(item.set).levels[l];
    viz::facing_particles(item.set->levels[l], item.model, camera, which_);
    indices_.clear();
    append_quads(which_, indices_);
    program_.set("u_model_view", view * glm::mat4(item.model));
    draw_indexed(b, indices_);
  }
  end(shading);
}

}  // namespace tumble::render
