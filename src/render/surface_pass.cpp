#include "render/surface_pass.hpp"

#include <algorithm>

namespace tumble::render {

SurfacePass::SurfacePass(const GlFunctions& gl, const std::filesystem::path& shader_dir)
    : gl_(&gl), program_(gl, shader_dir, "mesh") {}

InstancedMesh& SurfacePass::upload(const std::shared_ptr<const viz::SurfaceMesh>& m) {
  // Forget meshes whose owner is gone (their address may be reused).
  std::erase_if(cache_, [](const auto& kv) { return kv.second.source.expired(); });
  auto it = cache_.find(m.get());
  if (it != cache_.end()) return *it->second.mesh;
  MeshData data;
  data.vertices.reserve(m->positions.size());
  for (std::size_t i = 0; i < m->positions.size(); ++i) {
    data.vertices.push_back({m->positions[i], m->normals[i]});
    data.indices.push_back(static_cast<std::uint32_t>(i));
  }
  Cached c{m, std::make_unique<InstancedMesh>(*gl_, data)};
  return *cache_.emplace(m.get(), std::move(c)).first->second.mesh;
}

void SurfacePass::draw(const std::vector<viz::SurfaceItem>& items, const glm::mat4& view, const glm::mat4& proj,
                       const glm::vec3& light_dir) {
  draw_items(items, view, proj, light_dir, false);
}

void SurfacePass::draw_translucent(const std::vector<viz::SurfaceItem>& items, const glm::mat4& view,
                                   const glm::mat4& proj, const glm::vec3& light_dir) {
  if (std::none_of(items.begin(), items.end(), [](const viz::SurfaceItem& it) { return it.color.a < 1.0f; })) return;
  gl_->DepthMask(GL_FALSE);
  gl_->Enable(GL_CULL_FACE);
  gl_->CullFace(GL_FRONT);
  draw_items(items, view, proj, light_dir, true);
  gl_->CullFace(GL_BACK);
  draw_items(items, view, proj, light_dir, true);
  gl_->Disable(GL_CULL_FACE);
  gl_->DepthMask(GL_TRUE);
}

void SurfacePass::draw_items(const std::vector<viz::SurfaceItem>& items, const glm::mat4& view, const glm::mat4& proj,
                             const glm::vec3& light_dir, bool translucent) {
  if (items.empty()) return;
  program_.use();
  program_.set("u_view", view);
  program_.set("u_proj", proj);
  program_.set("u_light_dir", light_dir);
  program_.set("u_specular", 0.22f);
  for (const viz::SurfaceItem& it : items) {
    if (!it.mesh || it.mesh->positions.empty() || (it.color.a < 1.0f) != translucent) continue;
    InstancedMesh& mesh = upload(it.mesh);
    mesh.upload({MeshInstance{glm::mat4(it.model), it.color}});
    if (it.behind) {
      gl_->Enable(GL_POLYGON_OFFSET_FILL);
      gl_->PolygonOffset(2.0f, 8.0f);  // a few depth steps back, more on faces seen at a slant
    }
    mesh.draw();
    if (it.behind) gl_->Disable(GL_POLYGON_OFFSET_FILL);
  }
}

}  // namespace tumble::render
