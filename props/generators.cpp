#include "generators.hpp"

#include <algorithm>

namespace cutcom::props {

namespace {
using rc::gen::element;
using rc::gen::inRange;

// Symmetric coordinate that shrinks towards 0 (inRange shrinks to its lower bound).
std::int64_t signed_um(std::int64_t max) {
  bool negative = *rc::gen::arbitrary<bool>();
  std::int64_t m = *inRange<std::int64_t>(0, max + 1);
  return negative ? -m : m;
}

std::int64_t radius_um() {
  int kind = *inRange(0, 20);
  if (kind == 0) return 0;                                  // zero radius
  if (kind == 1) return -*inRange<std::int64_t>(1, 10001);  // negative: swaps the side
  return *inRange<std::int64_t>(1, 10001);                  // 0.001 .. 10 mm
}

// The parts every style shares: side, plane, start/end points, machine data, dummy blocks.
void common(ContourCase& c) {
  c.right = *rc::gen::arbitrary<bool>();
  c.plane = *element(17, 17, 17, 18, 19);
  c.start_x = signed_um(80000), c.start_y = signed_um(80000);
  c.first_x = signed_um(50000), c.first_y = signed_um(50000);
  c.end_x = signed_um(80000), c.end_y = signed_um(80000);
  if (*inRange(0, 5) == 0) {  // machine data at exactly representable angles: ties on the grid
    c.md20210 = *element(0, 45, 90, 135, 180);
    c.md20230 = *element(0, 45, 90);
  }
  for (Step& s : c.steps) {
    s.g451 = *inRange(0, 3) == 0;
    s.dummies = *inRange(0, 8) == 0 ? *inRange(1, 3) : 0;
  }
}

void nonzero(Step& s) {
  if (s.dx == 0 && s.dy == 0) s.dx = 1000;
}

}  // namespace

rc::Gen<ContourCase> random_walk() {
  return rc::gen::exec([] {
    ContourCase c;
    c.style = "random";
    c.radius_um = radius_um();
    c.steps.resize(static_cast<std::size_t>(*inRange(1, 9)));
    for (Step& s : c.steps) s.dx = signed_um(60000), s.dy = signed_um(60000), nonzero(s);
    common(c);
    return c;
  });
}

rc::Gen<ContourCase> grid_walk() {
  return rc::gen::exec([] {
    ContourCase c;
    c.style = "grid";
    c.radius_um = radius_um();
    std::int64_t unit = std::max<std::int64_t>(1000, std::abs(c.radius_um)) * *inRange(1, 4);
    c.steps.resize(static_cast<std::size_t>(*inRange(1, 9)));
    for (Step& s : c.steps) {
      s.dx = unit * *inRange(-3, 4), s.dy = unit * *inRange(-3, 4);
      nonzero(s);
    }
    common(c);
    c.first_x = unit * *inRange(-3, 4), c.first_y = unit * *inRange(-3, 4);
    return c;
  });
}

namespace {
// Each next step continues the previous direction `sign` (+1 on, -1 back) with a tiny sideways slip.
rc::Gen<ContourCase> bent_walk(const char* style, int sign) {
  return rc::gen::exec([style, sign] {
    ContourCase c;
    c.style = style;
    c.radius_um = radius_um();
    std::size_t n = static_cast<std::size_t>(*inRange(2, 9));
    c.steps.resize(n);
    c.steps[0].dx = signed_um(40000), c.steps[0].dy = signed_um(40000);
    nonzero(c.steps[0]);
    for (std::size_t i = 1; i < n; ++i) {
      const Step& p = c.steps[i - 1];
      std::int64_t k = *inRange<std::int64_t>(1, 3);
      std::int64_t slip = *inRange<std::int64_t>(-3, 4);  // micrometres across
      // p / |p|_inf keeps the size; the perpendicular slip bends it by about slip/|p| radians.
      c.steps[i].dx = sign * k * p.dx - slip * (p.dy == 0 ? 0 : (p.dy > 0 ? 1 : -1));
      c.steps[i].dy = sign * k * p.dy + slip * (p.dx == 0 ? 0 : (p.dx > 0 ? 1 : -1));
      std::int64_t big = std::max(std::abs(c.steps[i].dx), std::abs(c.steps[i].dy));
      if (big > 100000) c.steps[i].dx /= 4, c.steps[i].dy /= 4;
      nonzero(c.steps[i]);
    }
    common(c);
    return c;
  });
}
}  // namespace

rc::Gen<ContourCase> near_tangent() { return bent_walk("near-tangent", 1); }
rc::Gen<ContourCase> near_reversal() { return bent_walk("near-reversal", -1); }

rc::Gen<ContourCase> notch() {
  return rc::gen::exec([] {
    ContourCase c;
    c.style = "notch";
    c.radius_um = *inRange<std::int64_t>(1, 5001);
    std::int64_t w = 2 * c.radius_um;  // the width at which the element between two inner corners vanishes
    std::int64_t l = *inRange<std::int64_t>(3, 8) * c.radius_um + *inRange<std::int64_t>(0, 3);
    int turns = *inRange(1, 4);
    // A meander: along, across by exactly 2r, back; the inner corners take r each from the middle.
    for (int t = 0; t < turns; ++t) {
      int dir = t % 2 == 0 ? 1 : -1;
      c.steps.push_back({dir * l, 0});
      c.steps.push_back({0, w + *element<std::int64_t>(0, 0, 0, 1, -1)});
    }
    c.steps.push_back({(turns % 2 == 0 ? 1 : -1) * l, 0});
    common(c);
    c.right = false;  // G41 with this meander puts the tool inside the turns
    c.plane = 17;
    return c;
  });
}

rc::Gen<ContourCase> any_contour() {
  return rc::gen::weightedOneOf<ContourCase>(
      {{4, random_walk()}, {3, grid_walk()}, {2, near_tangent()}, {2, near_reversal()}, {1, notch()}});
}

}  // namespace cutcom::props
