#include "core/particle_cloud.hpp"

namespace tumble {

void append_cloud(ParticleCloud& dst, const ParticleCloud& src, const Eigen::Vector3d& offset) {
  dst.reserve(dst.size() + src.size());
  for (const Particle& p : src) dst.push_back({p.position + offset, p.mass});
}

}  // namespace tumble
