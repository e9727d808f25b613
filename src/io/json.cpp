#include "io/json.hpp"

#include <fstream>

#include "io/atomic_file.hpp"

namespace tumble::io {

std::string json_text(const Json& j) {
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

void write_json_atomic(const std::filesystem::path& path, const Json& j) { atomic_write_file(path, json_text(j)); }

std::optional<Json> read_json_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  Json j = Json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return std::nullopt;
  return j;
}

}  // namespace tumble::io
