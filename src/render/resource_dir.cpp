#include "render/resource_dir.hpp"

#include <dlfcn.h>

#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace tumble::render {
namespace fs = std::filesystem;

std::filesystem::path find_resource_dir() {
  std::string tried;
  auto has_shaders = [&](const fs::path& dir) {
    tried += "\n  " + dir.string();
    std::error_code ec;
    return fs::is_directory(dir / "shaders", ec);
  };

  // The file this code was loaded from: the executable, or the Python module
  // (installed with its shaders beside it, whatever python3's folder is).
  std::error_code ec;
  std::vector<fs::path> starts;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&find_resource_dir), &info) != 0 && info.dli_fname)
    starts.push_back(fs::absolute(info.dli_fname, ec));
  if (const fs::path exe = fs::read_symlink("/proc/self/exe", ec); !ec) starts.push_back(exe);
  for (const fs::path& start : starts) {
    // Build trees look like <source>/build-xxx/src/app/tumble, so walking up
    // from the executable reaches the source tree's shaders/.
    for (fs::path dir = start.parent_path(); !dir.empty(); dir = dir.parent_path()) {
      if (has_shaders(dir)) return dir;
      if (dir == dir.root_path()) break;
    }
  }
#ifdef TUMBLE_SOURCE_DIR
  if (has_shaders(TUMBLE_SOURCE_DIR)) return fs::path(TUMBLE_SOURCE_DIR);
#endif
  throw ResourceError("cannot find the tumble resource directory (a folder holding "
                           "shaders/); looked in:" + tried);
}

std::filesystem::path find_font_file(const std::filesystem::path& resource_dir) {
  const fs::path candidates[] = {resource_dir / "fonts" / "DejaVuSans.ttf",
                                 "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"};
  for (const fs::path& p : candidates) {
    std::error_code ec;
    if (fs::is_regular_file(p, ec)) return p;
  }
  throw ResourceError("font DejaVuSans.ttf not found in " +
                           (resource_dir / "fonts").string() +
                           " nor /usr/share/fonts/truetype/dejavu (Debian package "
                           "fonts-dejavu-core)");
}

}  // namespace tumble::render
