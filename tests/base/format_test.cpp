// The project's one number formatter (base/format.hpp): printf's %g/%e/%f,
// and the shortest round-trip text for help texts.
#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>

#include "base/format.hpp"

namespace tumble {
namespace {

TEST(FormatNumber, DefaultRoundTrips) {
  for (double v : {0.1, 1.0 / 3.0, -2.5e-300, 6.02214076e23})
    EXPECT_EQ(std::strtod(format_number(v).c_str(), nullptr), v) << format_number(v);
  EXPECT_EQ(format_number(30), "30");
  EXPECT_EQ(format_number(0.1), "0.10000000000000001");  // %.17g, not the shortest
}

TEST(FormatNumber, PrintfConversions) {
  EXPECT_EQ(format_number(0.000123456, 3), "0.000123");
  EXPECT_EQ(format_number(1.5e-5, 1, 'e'), "1.5e-05");
  EXPECT_EQ(format_number(1e-9, 0, 'e'), "1e-09");
  EXPECT_EQ(format_number(1234.4, 0, 'f'), "1234");
  EXPECT_EQ(format_number(1e300, 2, 'f').size(), 301u + 3u);  // fits: no truncation
}

TEST(FormatNumber, ShortestForHelpTexts) {
  EXPECT_EQ(format_number(0.1, kShortestDigits), "0.1");
  EXPECT_EQ(format_number(5e-4, kShortestDigits), "0.0005");
  EXPECT_EQ(format_number(1e5, kShortestDigits), "100000");
  EXPECT_EQ(format_number(2.5e-7, kShortestDigits), "2.5e-07");
}

TEST(FormatNumber, RejectsWhatPrintfCannotMean) {
  EXPECT_THROW(format_number(1, 3, 'x'), std::invalid_argument);
  EXPECT_THROW(format_number(1, 41), std::invalid_argument);
}

}  // namespace
}  // namespace tumble

TEST(FormatNumber, ForPeople) {
  EXPECT_EQ(tumble::format_for_people(4.7e-13), "4.7\u00d710\u207b\u00b9\u00b3");
  EXPECT_EQ(tumble::format_for_people(1.4e-4, 2, true), "+1.4\u00d710\u207b\u2074");
  EXPECT_EQ(tumble::format_for_people(-0.78, 2, true), "\u22120.78");
  EXPECT_EQ(tumble::format_for_people(0.032), "0.032");
  EXPECT_EQ(tumble::format_for_people(12.5, 3), "12.5");
  EXPECT_EQ(tumble::format_for_people(0), "0.0");
  EXPECT_EQ(tumble::format_for_people(2.5e5), "2.5\u00d710\u2075");
}
