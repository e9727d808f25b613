// JSON files (manifest, golden sidecars, `tumble info --json`) through
// nlohmann-json, keys kept in the order they were set.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace tumble::io {

using Json = nlohmann::ordered_json;

/// Two-space indented text with a final newline; bytes that are not UTF-8
/// (a path, say) become U+FFFD instead of throwing.
std::string json_text(const Json& j);

/// Writes json_text(j) with atomic_write_file. Throws IoError.
void write_json_atomic(const std::filesystem::path& path, const Json& j);

/// Largest JSON file read back (a manifest is a few kB).
inline constexpr std::size_t kMaxJsonBytes = std::size_t(16) << 20;

/// The parsed file, or nothing when it is missing (then `*missing` is set, if
/// given), larger than kMaxJsonBytes or not JSON. Throws UnreadableFile
/// (base/input_file.hpp) when it is a directory, FIFO, device or unreadable:
/// what the path is, not a parse error.
std::optional<Json> read_json_file(const std::filesystem::path& path, bool* missing = nullptr);

}  // namespace tumble::io
