#include "core/format.hpp"

#include <charconv>
#include <cstdio>
#include <stdexcept>

namespace tumble {

std::string format_number(double v, int digits, char conversion) {
  char buf[400];  // "%.17f" of 1e300 needs 319
  if (digits == kShortestDigits) {
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general);
    return std::string(buf, r.ptr);
  }
  const char* f = conversion == 'e' ? "%.*e" : conversion == 'f' ? "%.*f" : conversion == 'g' ? "%.*g" : nullptr;
  if (!f || digits < 0 || digits > 40) throw std::invalid_argument("format_number: bad digits or conversion");
  std::snprintf(buf, sizeof buf, f, digits, v);
  return buf;
}

}  // namespace tumble
