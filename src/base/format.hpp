// Numbers as text, one way for the whole project (CSV, settings hashes, error
// messages, labels, reports): printf's conversions, so the text is the same on
// every machine and locale-free.
#pragma once

#include <string>

namespace tumble {
namespace base {

/// Significant digits that read back to the same double (CSV, hashes, messages
/// quoting a value the user wrote).
inline constexpr int kRoundTripDigits = 17;
/// The fewest digits that read back to the same double (std::to_chars,
/// chars_format::general): for help texts.
inline constexpr int kShortestDigits = -1;

/// `v` as printf("%.{digits}{conversion}") with conversion 'g', 'e' or 'f'
/// ('e', 'f': `digits` after the point). format_number(0.1) == "0.10000000000000001",
/// format_number(1.5e-5, 1, 'e') == "1.5e-05", format_number(v, kShortestDigits) == "0.1".
std::string format_number(double v, int digits = kRoundTripDigits, char conversion = 'g');

/// `v` for people, with `digits` significant digits: "4.7×10⁻¹³", "0.032",
/// "12.5" (plain from 10⁻² to 10⁴; a power of ten with superscripts outside);
/// `plus`: a '+' before a positive value, for a signed change. UTF-8.
std::string format_for_people(double v, int digits = 2, bool plus = false);

}  // namespace base

// The old names, kept for every layer above.
using base::kRoundTripDigits;
using base::kShortestDigits;
using base::format_number;
using base::format_for_people;

}  // namespace tumble
