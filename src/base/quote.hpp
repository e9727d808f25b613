// A token from a file or the command line, made safe to put in a message: at
// most kQuoteChars characters (a 50 MB number must not be echoed whole), NUL
// and other control bytes shown as \xNN (a NUL would cut the message short).
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

namespace tumble {
namespace base {

inline constexpr std::size_t kQuoteChars = 80;  ///< longest token quoted in a message

/// `s` between `mark`s, shortened to kQuoteChars with "... (N bytes)".
inline std::string quote_token(std::string_view s, char mark = '"') {
  std::string out(1, mark);
  const std::size_t shown = s.size() > kQuoteChars ? kQuoteChars : s.size();
  for (std::size_t i = 0; i < shown; ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x20 || c == 0x7f) {
      char b[8];
      std::snprintf(b, sizeof b, "\\x%02x", c);
      out += b;
    } else {
      out += static_cast<char>(c);
    }
  }
  out += mark;
  if (shown < s.size()) out += "... (" + std::to_string(s.size()) + " bytes)";
  return out;
}

}  // namespace base

// The old names, kept for every layer above.
using base::kQuoteChars;
using base::quote_token;

}  // namespace tumble
