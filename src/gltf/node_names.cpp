#include "gltf/node_names.hpp"

#include <algorithm>

namespace tumble::gltf {

std::string clean_name(std::string_view name) {
  std::string out(name);
  for (char& c : out)
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-')) c = '_';
  return out;
}

std::string NodeNames::add(std::string_view base, std::string_view suffix) {
  const std::string clean = clean_name(base);
  for (int n = 1;; ++n) {
    const std::string tail = clean_name(suffix) + (n > 1 ? "_" + std::to_string(n) : "");
    std::string name = clean.substr(0, kMaxNodeName - std::min(tail.size(), kMaxNodeName)) + tail;
    if (used_.insert(name).second) return name;
  }
}

}  // namespace tumble::gltf
