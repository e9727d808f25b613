// Node names that survive the viewers: three.js's PropertyBinding drops '.',
// ':', '/', '[' and ']' from names (and turns spaces into '_'), Blender keeps
// 63 bytes and renames duplicates ("name.001"). A name a user looks a node up
// by (to hide it, or to bind an animation) must come through both unchanged.
#pragma once

#include <set>
#include <string>
#include <string_view>

namespace tumble::gltf {

/// Blender's longest name, bytes.
inline constexpr std::size_t kMaxNodeName = 63;

/// `name` with every character outside [A-Za-z0-9_-] replaced by '_'.
std::string clean_name(std::string_view name);

/// The names of one file, unique: add() returns clean_name(base) + suffix,
/// cut to kMaxNodeName (from the base, so the suffix stays), and when that is
/// taken the same with "_2", "_3", ... after it.
class NodeNames {
 public:
  std::string add(std::string_view base, std::string_view suffix = "");

 private:
  std::set<std::string> used_;
};

}  // namespace tumble::gltf
