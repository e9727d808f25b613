// Limits checked on a scene's text before toml++ parses it: toml++ recurses
// once per dot of a dotted key (a 100 KB key of 50 000 dots overflows the
// stack) and per nested array, and spends ~100 bytes per value (a 10⁶-body
// scene of 11-byte tables took 30× its size). A cheap lexical pass refuses
// such text with file:line:column and the limit's name.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace tumble::scene {

inline constexpr std::size_t kMaxKeyDepth = 32;         ///< parts of one dotted key or table header
inline constexpr std::size_t kMaxNesting = 32;          ///< arrays and inline tables inside each other
inline constexpr std::size_t kMaxSceneValues = 2'000'000;  ///< keys, array elements and tables in one scene

/// Throws SceneError (exit 2) at the first limit `text` breaks; `source_name` labels it.
void check_toml_limits(std::string_view text, const std::string& source_name);

}  // namespace tumble::scene
