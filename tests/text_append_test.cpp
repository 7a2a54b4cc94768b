// The writers' number formatting (core/src/text_append.hpp) prints exactly what std::to_chars
// prints, on its short path and at the ties that leave it.
#include "../core/src/text_append.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace {

std::string reference(double v, int places) {
  char digits[400];
  auto r = std::to_chars(digits, digits + sizeof digits, v, std::chars_format::fixed, places);
  return std::string(digits, r.ptr);
}

std::string fast(double v, int places) {
  std::string s = "x";                       // appends, never replaces
  cutcom::text::append_fixed(s, v, places);  // through put_fixed
  return s.substr(1);
}

TEST(TextAppend, FixedNotationIsThatOfToChars) {
  const double special[] = {0.0,
                            -0.0,
                            0.03125,
                            -0.03125,
                            0.00005,
                            -0.00004999,
                            0.5,
                            1.5,
                            2.5,
                            1e-300,
                            -1e-300,
                            123456.78905,
                            99999.99995,
                            1099511627775.9,
                            1099511627776.5,
                            1e20,
                            -1e20,
                            9.99995,
                            std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity(),
                            std::numeric_limits<double>::quiet_NaN(),
                            std::nextafter(0.00015, 0.0),
                            std::nextafter(0.00015, 1.0)};
  for (int places = 0; places <= 8; ++places)
    for (double v : special) EXPECT_EQ(fast(v, places), reference(v, places)) << v << " places " << places;

  std::mt19937_64 random(20261127);
  std::uniform_real_distribution<double> magnitude(-12, 13);
  std::uniform_int_distribution<int> ticks(-2000000, 2000000);
  for (int k = 0; k < 200000; ++k) {
    int places = k % 7;
    double v = std::pow(10.0, magnitude(random)) * (k % 2 ? -1 : 1);
    EXPECT_EQ(fast(v, places), reference(v, places)) << v << " places " << places;
    // values a decimal grid step or half a step apart: the ties and near-ties of rounding
    double grid = ticks(random) / 20000.0;
    EXPECT_EQ(fast(grid, 4), reference(grid, 4)) << grid;
    double near = std::nextafter(grid, k % 3 ? 1e9 : -1e9);
    EXPECT_EQ(fast(near, 4), reference(near, 4)) << near;
  }
}

}  // namespace
