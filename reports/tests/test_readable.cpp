// geomcheck — numbers as the report's page writes them (report::readable,
// report::readable_numbers): plain decimals where a person reads them so,
// a power of ten with a superscript exponent elsewhere, never e-notation.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "geomcheck/reports/report.hpp"

namespace geomcheck::report {
namespace {

TEST(Readable, PlainDecimalsFromAThousandthToAMillion) {
  EXPECT_EQ(readable(1000), "1000");  // not "1e+03"
  EXPECT_EQ(readable(53.4), "53.4");
  EXPECT_EQ(readable(0.25), "0.25");
  EXPECT_EQ(readable(0.001), "0.001");
  EXPECT_EQ(readable(123456, 3), "123456");  // an integer part is never cut
  EXPECT_EQ(readable(-2.5), "-2.5");
  EXPECT_EQ(readable(0), "0");
  EXPECT_EQ(readable(1.0 / 3.0, 6), "0.333333");
}

TEST(Readable, PowersOfTenOutsideThatRange) {
  EXPECT_EQ(readable(2.5e-9), "2.5\u00d710\u207b\u2079");
  EXPECT_EQ(readable(1e-17), "1\u00d710\u207b\u00b9\u2077");
  EXPECT_EQ(readable(6.34e13), "6.34\u00d710\u00b9\u00b3");
  EXPECT_EQ(readable(-1.41e14), "-1.41\u00d710\u00b9\u2074");
  EXPECT_EQ(readable(999999.7, 3), "1\u00d710\u2076");  // rounds up to a million: the power form
  EXPECT_EQ(readable(0.00099999), "0.001");           // %.3g would say 0.001 too; not "1e-03"
}

TEST(Readable, NoneAndInfinity) {
  EXPECT_EQ(readable(std::numeric_limits<double>::quiet_NaN()), "\u2013");
  EXPECT_EQ(readable(INFINITY), "\u221e");
}

TEST(ReadableNumbers, ENotationInTextOnly) {
  EXPECT_EQ(readable_numbers("hit depth=5.3504372219142694e-06 normal=(0, 1, 2)"),
            "hit depth=5.3504372219142694\u00d710\u207b\u2076 normal=(0, 1, 2)");
  EXPECT_EQ(readable_numbers("t = 1e-08."), "t = 1\u00d710\u207b\u2078.");
  EXPECT_EQ(readable_numbers("distance=-1"), "distance=-1");
  EXPECT_EQ(readable_numbers("mode coaxial-1e-8-deep, seed 20261121"), "mode coaxial-1e-8-deep, seed 20261121");
  EXPECT_EQ(readable_numbers("(-2.5e+03, 4)"), "(-2500, 4)");
  EXPECT_EQ(readable_numbers("0x1e3 stays"), "0x1e3 stays");
}

}  // namespace
}  // namespace geomcheck::report
