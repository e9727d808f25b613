#include "base/format.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace tumble::base {

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

std::string format_for_people(double v, int digits, bool plus) {
  static const char* const kSup[10] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                       "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  const std::string sign = v < 0 ? "\u2212" : plus && v > 0 ? "+" : "";  // a true minus sign
  const double a = std::abs(v);
  digits = std::clamp(digits, 1, 17);
  if (a == 0 || (a >= 1e-2 && a < 1e4)) {
    const int whole = a == 0 ? 1 : static_cast<int>(std::floor(std::log10(a))) + 1;  // digits before the point
    return sign + format_number(a, std::max(0, digits - whole), 'f');
  }
  std::string e = format_number(a, digits - 1, 'e');  // "4.7e-13"
  const std::size_t at = e.find('e');
  std::string out = sign + e.substr(0, at) + "\u00d710";
  int power = std::stoi(e.substr(at + 1));
  if (power < 0) out += "\u207b", power = -power;
  const std::string p = std::to_string(power);
  for (char c : p) out += kSup[c - '0'];
  return out;
}

}  // namespace tumble::base
