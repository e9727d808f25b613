#include "io/json.hpp"


#include "base/input_file.hpp"
#include "io/atomic_file.hpp"

namespace tumble::io {

std::string json_text(const Json& j) {
  return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

void write_json_atomic(const std::filesystem::path& path, const Json& j) { atomic_write_file(path, json_text(j)); }

std::optional<Json> read_json_file(const std::filesystem::path& path, bool* missing) {
  std::optional<std::string> text;
  try {
    text = read_file_if_exists(path, kMaxJsonBytes, "JSON file", ReadRole::own_output);
  } catch (const InputError&) {  // over the cap: not a file tumble wrote
    return std::nullopt;
  }
  if (missing) *missing = !text;
  if (!text) return std::nullopt;
  Json j = Json::parse(*text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) return std::nullopt;
  return j;
}

}  // namespace tumble::io
