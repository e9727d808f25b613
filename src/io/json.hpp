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

/// The parsed file, or nothing when it is missing, unreadable or not JSON.
std::optional<Json> read_json_file(const std::filesystem::path& path);

}  // namespace tumble::io
