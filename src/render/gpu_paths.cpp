// Where the GPU does more than draw (renderer.hpp's GpuPaths): chosen by the
// renderer's kind, or by env TUMBLE_GPU_PATHS for measurements and tests.
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "render/renderer.hpp"

namespace tumble::render {

GpuPaths parse_gpu_paths(std::string_view text, bool hardware_gpu) {
  if (text.empty() || text == "auto") return {hardware_gpu, hardware_gpu};
  GpuPaths p;
  if (text == "none") return p;
  std::istringstream in{std::string(text)};
  for (std::string item; std::getline(in, item, ',');) {
    if (item == "pbo") p.overlapped_readback = true;
    else if (item == "fxaa") p.gl_fxaa = true;
    else
      throw std::invalid_argument("TUMBLE_GPU_PATHS = '" + std::string(text) +
                                  "': expected auto, none, or a comma list of pbo and fxaa");
  }
  return p;
}

GpuPaths gpu_paths_from_env(bool hardware_gpu) {
  const char* env = std::getenv("TUMBLE_GPU_PATHS");
  return parse_gpu_paths(env ? env : "", hardware_gpu);
}

GpuPaths default_gpu_paths(const GlContext& context) { return gpu_paths_from_env(context.hardware_gpu()); }

}  // namespace tumble::render
