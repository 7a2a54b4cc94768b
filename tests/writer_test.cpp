// The writers keep the text of what they wrote last (the JSON writer its last numbers, the text
// writer the last end point) and copy it where the same value comes again. An element is written
// exactly as a writer that has written nothing before writes it, whatever came before it: chains
// of elements that start where the one before ended, near misses of an ulp, signed zeros, NaN and
// numbers too long to be kept.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "cutcom/output.hpp"

namespace {

using cutcom::PathElement;
using cutcom::PathPoint;

// The line of a one-element document that holds the element (the text writer numbers its
// elements: the number column is left out).
template <class Writer>
std::string written_alone(const PathElement& e) {
  std::ostringstream out;
  Writer w(out, "fast", false);
  w.element(e);
  w.finish();
  return out.str();
}

std::vector<std::string> element_lines(const std::string& document, bool text) {
  std::vector<std::string> lines;
  std::istringstream in(document);
  for (std::string line; std::getline(in, line);) {
    if (text && line.size() > 5 && std::isdigit(static_cast<unsigned char>(line[3])) && line[4] == ' ')
      lines.push_back(line.substr(4));  // without the element's number
    if (!text && line.find("{\"block\":") != std::string::npos) {
      if (line.back() == ',') line.pop_back();  // the list's separator
      lines.push_back(line);
    }
  }
  return lines;
}

std::vector<PathElement> chain() {
  std::mt19937_64 random(20261129);
  std::vector<double> values = {0.0,    5.0,   -0.0,   1.5,      -0.5, 1.0 / 3, 2.0 / 3, 1e-7, 123456.789,
                                -1e300, 1e300, 1e-300, 4.9e-324, 7.25, -7.25,   0.1,     0.2,  0.30000000000000004};
  std::vector<PathElement> elements;
  PathPoint at{0, 0, 0};
  for (int k = 0; k < 400; ++k) {
    auto pick = [&] {
      double v = values[random() % values.size()];
      if (random() % 4 == 0) v = std::nextafter(v, random() % 2 ? 1e308 : -1e308);  // an ulp beside it
      if (random() % 50 == 0) v = std::numeric_limits<double>::quiet_NaN();
      return v;
    };
    PathElement e;
    e.type = random() % 3 == 0 ? cutcom::ElementType::kArc : cutcom::ElementType::kLine;
    e.ccw = random() % 2 == 0;
    e.rapid = random() % 5 == 0;
    e.feed = cutcom::Decimal::from_int(static_cast<std::int64_t>(random() % 3) * 500 + 100);
    // Mostly from where the last one ended; else from there with one coordinate an ulp beside it
    // or another value (the other two the same), or from elsewhere.
    e.start = at;
    double* moved = random() % 2 ? &e.start.z : random() % 2 ? &e.start.y : &e.start.x;
    switch (random() % 8) {
      case 0:
        *moved = std::nextafter(*moved, 1e308);
        break;
      case 1:
        *moved = pick();
        break;
      case 2:
        e.start = {pick(), pick(), pick()};
        break;
      default:
        break;
    }
    e.end = {pick(), pick(), random() % 3 == 0 ? pick() : e.start.z};
    e.center = {pick(), pick(), e.end.z};
    e.origin.line = k + 1;
    elements.push_back(e);
    at = e.end;
  }
  return elements;
}

template <class Writer>
void expect_each_as_alone(bool text) {
  std::vector<PathElement> elements = chain();
  std::ostringstream out;
  Writer w(out, "fast", false);
  for (const PathElement& e : elements) w.element(e);
  w.finish();
  std::vector<std::string> lines = element_lines(out.str(), text);
  ASSERT_EQ(lines.size(), elements.size());
  for (std::size_t k = 0; k < elements.size(); ++k) {
    std::vector<std::string> alone = element_lines(written_alone<Writer>(elements[k]), text);
    ASSERT_EQ(alone.size(), 1u);
    EXPECT_EQ(lines[k], alone[0]) << "element " << k;
  }
}

// covers: CLI-1
TEST(Writers, TextElementIsWrittenAsAloneWhateverCameBefore) { expect_each_as_alone<cutcom::TextWriter>(true); }

// covers: CLI-1
TEST(Writers, JsonElementIsWrittenAsAloneWhateverCameBefore) { expect_each_as_alone<cutcom::JsonWriter>(false); }

}  // namespace
