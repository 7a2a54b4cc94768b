// The writers' number formatting (core/src/text_append.hpp) prints exactly what std::to_chars
// prints, on its short path and at the ties that leave it; JSON's numbers read back
// as the same double in nlohmann::json's layout.
#include "../core/src/text_append.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <nlohmann/json.hpp>
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

// docs/json-format.md: a JSON number is the shortest decimal that reads back as the double, fixed
// for 1e-4 <= |v| < 1e15 with ".0" on whole numbers, else in scientific notation: here from
// std::to_chars's own fixed and scientific shortest forms.
std::string json_reference(double v) {
  char digits[400];
  double a = std::fabs(v);
  if (v == 0) return std::signbit(v) ? "-0.0" : "0.0";
  bool fixed = a >= 1e-4 && a < 1e15;
  std::string s(digits, std::to_chars(digits, digits + sizeof digits, v,
                                      fixed ? std::chars_format::fixed : std::chars_format::scientific)
                            .ptr);
  if (fixed && s.find('.') == std::string::npos) s += ".0";
  return s;
}

// The significant digits of a number as written ("0.00120" and "1.2e-03" both "12").
std::string significant(const std::string& s) {
  std::string d;
  for (char c : s) {
    if (c == 'e') break;
    if (c >= '0' && c <= '9') d += c;
  }
  d.erase(0, std::min(d.find_first_not_of('0'), d.size()));
  while (!d.empty() && d.back() == '0') d.pop_back();
  return d;
}

void expect_json_number(double v) {
  char out[40];
  std::string ours(out, cutcom::text::put_shortest(out, v));
  ASSERT_EQ(ours, json_reference(v)) << v;
  ASSERT_EQ(std::strtod(ours.c_str(), nullptr), v) << ours;
  // nlohmann::json's layout, where its Grisu2 finds the shortest digits too (mostly)
  char buffer[64];
  std::string theirs(buffer, nlohmann::detail::to_chars(buffer, buffer + sizeof buffer, v));
  if (significant(theirs) == significant(ours)) {
    ASSERT_EQ(ours, theirs) << v;
  }
  // the short path applies exactly to decimals of up to 6 places between 1e-3 and 1e9
  double a = std::fabs(v);
  char* short_end = cutcom::text::put_short_decimal(out, v);
  std::size_t point = ours.find('.');
  bool six_places = point != std::string::npos && ours.find('e') == std::string::npos && ours.size() - point - 1 <= 6;
  ASSERT_EQ(short_end != nullptr, a >= 1e-3 && a < 1e9 && six_places) << ours;
}

TEST(TextAppend, JsonNumbersAreTheShortestInNlohmannsLayout) {
  for (double v : {0.0,
                   -0.0,
                   1.0,
                   -1.0,
                   0.5,
                   12.0,
                   0.001,
                   -0.001,
                   0.0009999,
                   0.00012,
                   0.0001,
                   0.00001,
                   1.25e-5,
                   999999999.999999,
                   1e9,
                   -1e9,
                   123456789012345.0,
                   1234567890123456.0,
                   1e15,
                   1e16,
                   3e20,
                   0.1,
                   0.2,
                   0.30000000000000004,
                   1.5857864376269049,
                   -8925.40643,
                   51.787744,
                   1e100,
                   -1.5e-100,
                   std::numeric_limits<double>::max(),
                   std::numeric_limits<double>::denorm_min(),
                   std::numeric_limits<double>::min()})
    expect_json_number(v);
  char out[40];
  auto json = [&](double v) { return std::string(out, cutcom::text::put_shortest(out, v)); };
  EXPECT_EQ(json(-0.0), "-0.0");
  EXPECT_EQ(json(12.0), "12.0");
  EXPECT_EQ(json(-0.0012), "-0.0012");
  EXPECT_EQ(json(1.25e-5), "1.25e-05");
  EXPECT_EQ(json(3e20), "3e+20");
  EXPECT_EQ(json(-8925.40643), "-8925.40643");  // nlohmann: -8925.406429999999, the same double

  // Significands of every length (put_shortest counts their digits from the bit width): the
  // powers of ten and their neighbours over the whole range, and 2^k.
  for (int k = -323; k <= 308; ++k) {
    double ten = std::pow(10.0, k);
    for (double v : {ten, std::nextafter(ten, 0.0), std::nextafter(ten, 1e308), 9 * ten, 99 * ten, -3 * ten})
      if (std::isfinite(v) && v != 0) expect_json_number(v);
  }
  for (int k = -1074; k <= 1023; ++k) expect_json_number(std::ldexp(1.0, k));

  std::mt19937_64 random(20261129);
  std::uniform_real_distribution<double> magnitude(-8, 17);
  std::uniform_int_distribution<std::int64_t> ticks(-999999999999999, 999999999999999);
  for (int k = 0; k < 200000; ++k) {
    expect_json_number(std::pow(10.0, magnitude(random)) * (k % 2 ? -1 : 1));
    // decimals of up to 6 places (the short path, nearest doubles) and a few ulps beside them
    std::int64_t t = ticks(random) / static_cast<std::int64_t>(std::pow(10.0, k % 9));
    double grid = static_cast<double>(t) / std::pow(10.0, k % 7);
    expect_json_number(grid);
    expect_json_number(std::nextafter(grid, k % 3 ? 1e300 : -1e300));
    expect_json_number(std::nextafter(std::nextafter(grid, 0.0), 0.0));
  }
}

}  // namespace
