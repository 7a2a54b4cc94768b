#include "generators.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

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
  c.kont_select = *inRange(0, 3) != 0, c.kont_deselect = *inRange(0, 3) != 0;
  c.g451_select = *inRange(0, 3) == 0, c.g451_deselect = *inRange(0, 3) == 0;
  c.edge_select = *element(460, 461, 462, 462), c.edge_deselect = *element(460, 461, 462, 462);
  c.cdon = *inRange(0, 3) == 0;  // TRC-CD-*: collision detection on every third program
  if (*inRange(0, 4) == 0) c.md20240 = *element(2, 4, 5);
  for (std::size_t i = 0; i < c.steps.size(); ++i) {
    Step& s = c.steps[i];
    // Not in the first step, nor right after another flip (the draws of the campaigns before
    // TRC-SIDE-2, kept so that the cases of a seed stay theirs). Right after G41/G42 again, a flip
    // or another G41/G42 again selects anew before the first contour block (TRC-SIDE-3).
    int side_draw = i > 0 && !c.steps[i - 1].flip ? *inRange(0, 12) : -1;
    s.flip = side_draw == 0;
    s.again = side_draw == 1 && !s.arc;  // a circle would only add alarms 10753
    s.g451 = *inRange(0, 3) == 0;
    // TRC-DUMMY-2: now and then a run of exactly MD20250 (5) blocks without plane motion, the
    // most allowed, or one more (alarm 10762).
    s.dummies = *inRange(0, 8) == 0 ? (*inRange(0, 10) == 0 ? *element(5, 6) : *inRange(1, 3)) : 0;
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

rc::Gen<ContourCase> with_circles() {
  return rc::gen::exec([] {
    ContourCase c;
    c.style = "circles";
    c.radius_um = radius_um();
    // Rotations with integer results on multiples of the hypotenuse (Pythagorean triples),
    // quarter and half turns, and the full turn.
    static const std::int64_t rotations[][3] = {{3, 4, 5},    {4, 3, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25},
                                                {20, 21, 29}, {0, 1, 1}, {-1, 0, 1},  {1, 0, 1},   {-3, 4, 5}};
    std::size_t n = static_cast<std::size_t>(*inRange(1, 7));
    c.steps.resize(n);
    std::int64_t px = 1000, py = 0;  // direction of travel at the end of the previous step
    for (Step& s : c.steps) {
      int kind = *inRange(0, 6);
      if (kind == 5) {  // a CR= circle: its centre has a square root
        s.arc = true;
        s.ccw = *rc::gen::arbitrary<bool>();
        s.dx = signed_um(30000), s.dy = signed_um(30000);
        nonzero(s);
        double half = std::hypot(static_cast<double>(s.dx), static_cast<double>(s.dy)) / 2;
        std::int64_t radius = static_cast<std::int64_t>(std::ceil(half)) + *inRange<std::int64_t>(0, 20000);
        s.cr = *rc::gen::arbitrary<bool>() ? radius : -radius;
        px = s.dx, py = s.dy;  // roughly; the next tangent circle is then only nearly tangent
        continue;
      }
      if (kind == 0) {  // a line
        s.dx = signed_um(40000), s.dy = signed_um(40000);
        nonzero(s);
        px = s.dx, py = s.dy;
        continue;
      }
      const auto& rot = rotations[*inRange(0, 10)];
      std::int64_t m = rot[0], q = *rc::gen::arbitrary<bool>() ? rot[1] : -rot[1], o = rot[2];
      std::int64_t u, v;
      if (kind == 1) {
        // Tangent to the previous direction: the centre on its normal, turning towards it.
        std::int64_t g = std::gcd(std::abs(px), std::abs(py));
        std::int64_t k = *inRange<std::int64_t>(1, 6) * (*rc::gen::arbitrary<bool>() ? 1 : -1);
        u = -py / g * k, v = px / g * k;
        while ((std::abs(u) * o > 60000 || std::abs(v) * o > 60000) && (std::abs(u) > 1 || std::abs(v) > 1))
          u /= 2, v /= 2;
        if (u == 0 && v == 0) u = 1;
        s.ccw = k > 0;
      } else {
        u = signed_um(8000 / o + 1), v = signed_um(8000 / o + 1);
        if (u == 0 && v == 0) v = 1;
        s.ccw = *rc::gen::arbitrary<bool>();
      }
      s.arc = true;
      s.ci = o * u, s.cj = o * v;  // centre relative to the start
      // End = centre + R (start - centre), R the rotation (m, q) / o: exactly on the circle.
      std::int64_t rx = -s.ci, ry = -s.cj;
      s.dx = s.ci + (m * rx - q * ry) / o, s.dy = s.cj + (q * rx + m * ry) / o;
      if (kind == 4) s.dx += *inRange<std::int64_t>(-3, 4);  // a few um off: the centre is corrected
      // Direction of travel at the end: sense * perp(end - centre).
      std::int64_t ex = s.dx - s.ci, ey = s.dy - s.cj;
      px = s.ccw ? -ey : ey, py = s.ccw ? ex : -ex;
      if (px == 0 && py == 0) px = 1000;
    }
    common(c);
    return c;
  });
}

rc::Gen<ContourCase> tiny_blocks() {
  return rc::gen::exec([] {
    ContourCase c;
    c.style = "tiny-blocks";
    c.radius_um = *inRange<std::int64_t>(500, 5001);
    std::size_t n = static_cast<std::size_t>(*inRange(3, 12));
    c.steps.resize(n);
    for (Step& s : c.steps) {
      bool tiny = *inRange(0, 3) != 0;
      std::int64_t m = tiny ? c.radius_um / 2 : 4 * c.radius_um;
      s.dx = signed_um(m), s.dy = signed_um(m);
      nonzero(s);
    }
    common(c);
    if (*inRange(0, 3) == 0) c.md20210 = *element(100, 180);
    return c;
  });
}

rc::Gen<ContourCase> circles_near_radius() {
  return rc::gen::exec([] {
    ContourCase c;
    c.style = "circle-near-radius";
    c.radius_um = *inRange<std::int64_t>(1000, 10001);
    std::size_t n = static_cast<std::size_t>(*inRange(1, 5));
    c.steps.resize(n);
    for (Step& s : c.steps) {
      if (*rc::gen::arbitrary<bool>()) {
        s.dx = signed_um(20000), s.dy = signed_um(20000);
        nonzero(s);
        continue;
      }
      // A half circle of radius r + e, e a few um either side (0 included): its inside equidistant
      // is tiny, zero or collapsed.
      std::int64_t radius = c.radius_um + *inRange<std::int64_t>(-3, 4);
      bool along_x = *rc::gen::arbitrary<bool>();
      s.arc = true, s.ccw = *rc::gen::arbitrary<bool>();
      s.ci = along_x ? radius : 0, s.cj = along_x ? 0 : radius;
      s.dx = 2 * s.ci, s.dy = 2 * s.cj;
    }
    common(c);
    return c;
  });
}

namespace {
// Tangent direction (integers, not normalised) of a step at its start or at its end.
std::pair<std::int64_t, std::int64_t> tangent(const Step& s, bool at_end) {
  if (!s.arc || s.cr != 0) return {s.dx, s.dy};  // CR= circles: the chord, roughly
  int sense = s.ccw ? 1 : -1;
  // sense * perp(P - C) with C = start + (ci, cj).
  std::int64_t px = at_end ? s.dx - s.ci : -s.ci, py = at_end ? s.dy - s.cj : -s.cj;
  return {-sense * py, sense * px};
}

// A point placed against the tangent line through (vx, vy) with direction t: exactly on it, a
// micrometre off it, anywhere, near or exactly on the circle of radius r about the vertex.
std::pair<std::int64_t, std::int64_t> place(std::int64_t vx, std::int64_t vy, std::pair<std::int64_t, std::int64_t> t,
                                            std::int64_t r) {
  std::int64_t g = std::gcd(std::abs(t.first), std::abs(t.second));
  if (g == 0) return {vx + signed_um(80000), vy + signed_um(80000)};
  std::int64_t tx = t.first / g, ty = t.second / g;
  double len = std::hypot(static_cast<double>(tx), static_cast<double>(ty));
  std::int64_t reach = std::max<std::int64_t>(1, static_cast<std::int64_t>(60000 / len));
  switch (*inRange(0, 6)) {
    case 0: {  // on the line, ahead or back
      std::int64_t k = signed_um(reach);
      return {vx + k * tx, vy + k * ty};
    }
    case 1: {  // a micrometre off the line
      std::int64_t k = signed_um(reach);
      bool in_x = *rc::gen::arbitrary<bool>();
      std::int64_t e = *rc::gen::arbitrary<bool>() ? 1 : -1;
      return {vx + k * tx + (in_x ? e : 0), vy + k * ty + (in_x ? 0 : e)};
    }
    case 2: {  // near the circle of radius r, either side by a few um
      double angle = *inRange(0, 3600) * 3.14159265358979 / 1800;
      double d = static_cast<double>(r + *inRange<std::int64_t>(-4, 5));
      return {vx + static_cast<std::int64_t>(std::lround(d * std::cos(angle))),
              vy + static_cast<std::int64_t>(std::lround(d * std::sin(angle)))};
    }
    case 3: {  // exactly on the circle: along an axis or on a 3-4-5 triangle
      std::int64_t sx = *rc::gen::arbitrary<bool>() ? 1 : -1, sy = *rc::gen::arbitrary<bool>() ? 1 : -1;
      int k = *inRange(0, 3);
      if (k == 0) return {vx + sx * r, vy};
      if (k == 1) return {vx, vy + sy * r};
      return {vx + sx * (r / 5) * 3, vy + sy * (r / 5) * 4};
    }
    default:
      return {vx + signed_um(80000), vy + signed_um(80000)};
  }
}

// The first and last contour blocks shortened below the tool radius now and then (TRC-EDGE-*).
void shorten(Step& s, std::int64_t r) {
  if (s.arc || r <= 0) return;
  double len = std::hypot(static_cast<double>(s.dx), static_cast<double>(s.dy));
  double want = static_cast<double>(r) * *inRange(1, 10) / 10.0;
  s.dx = static_cast<std::int64_t>(std::lround(static_cast<double>(s.dx) * want / len));
  s.dy = static_cast<std::int64_t>(std::lround(static_cast<double>(s.dy) * want / len));
  nonzero(s);
}
}  // namespace

rc::Gen<ContourCase> around_ends() {
  return rc::gen::exec([] {
    ContourCase c = *rc::gen::weightedOneOf<ContourCase>(
        {{3, random_walk()}, {3, grid_walk()}, {2, with_circles()}, {1, tiny_blocks()}});
    c.style += "+ends";
    std::int64_t r = std::abs(c.radius_um);
    if (*inRange(0, 3) == 0) shorten(c.steps.front(), r);
    if (*inRange(0, 3) == 0) shorten(c.steps.back(), r);
    std::int64_t ex = c.first_x, ey = c.first_y;
    for (const Step& s : c.steps) ex += s.dx, ey += s.dy;
    auto start = place(c.first_x, c.first_y, tangent(c.steps.front(), false), r);
    auto end = place(ex, ey, tangent(c.steps.back(), true), r);
    c.start_x = start.first, c.start_y = start.second;
    c.end_x = end.first, c.end_y = end.second;
    return c;
  });
}

namespace {
// TRC-CD-*: a straight wall with recesses (U: down, across, up; V: down, up; leaning walls) whose
// width is narrower than, exactly, about or wider than 2r, in any direction; CDON with a window
// that reaches across each recess. `fewest` to `most_recesses` recesses.
rc::Gen<ContourCase> wall_with_recesses(const char* style, int fewest, int most_recesses) {
  return rc::gen::exec([=] {
    ContourCase c;
    c.style = style;
    std::int64_t r = *inRange<std::int64_t>(300, 5001);
    c.radius_um = r;
    // Wall direction u (integer, length l) and the tool side n = left normal of u (G41).
    static constexpr std::int64_t kDirs[][3] = {{1, 0, 1}, {0, 1, 1}, {-1, 0, 1}, {3, 4, 5}, {-4, 3, 5}, {12, -5, 13}};
    const auto& d = kDirs[*inRange(0, 6)];
    std::int64_t ux = d[0], uy = d[1], l = d[2];
    auto step = [&](std::int64_t along, std::int64_t across) {  // in um of the wall's frame, /l
      Step s;
      s.dx = (along * ux - across * uy) / l, s.dy = (along * uy + across * ux) / l;
      nonzero(s);
      return s;
    };
    int recesses = *inRange(fewest, most_recesses + 1), most = 2;
    const bool long_wall = fewest > 2;
    c.steps.push_back(step(*inRange<std::int64_t>(3, 9) * r, 0));
    for (int k = 0; k < recesses; ++k) {
      std::int64_t w;
      switch (*inRange(0, 6)) {
        case 0:
          w = 2 * r;
          break;  // exactly 2r
        case 1:
          w = 2 * r + *element<std::int64_t>(-1, 1);
          break;  // a micrometre off
        case 2:
          w = *inRange<std::int64_t>(2 * r, 4 * r);
          break;  // wider
        default:
          w = *inRange<std::int64_t>(r / 5, 2 * r);
          break;  // narrower: a bottleneck
      }
      std::int64_t depth = *inRange<std::int64_t>(r / 3, 4 * r), lean = *element<std::int64_t>(0, 0, r / 4, -r / 4);
      if (long_wall)  // U recesses deep enough, and narrower than r (cut, TRC-CD-4) or at least 2r wide
        depth = std::max(depth, 2 * r), lean = 0, w = w < 2 * r ? std::min(w, r * 9 / 10) : w;
      bool v_shape = *inRange(0, 3) == 0;
      if (v_shape && !long_wall) {  // V
        c.steps.push_back(step(w / 2, -depth));
        c.steps.push_back(step(w - w / 2, depth));
      } else {
        c.steps.push_back(step(lean, -depth));
        c.steps.push_back(step(std::max<std::int64_t>(w - 2 * lean, 1), 0));
        c.steps.push_back(step(lean, depth));
        most = 3;
      }
      c.steps.push_back(step(*inRange<std::int64_t>(3, 9) * r, 0));
    }
    common(c);
    for (Step& s : c.steps) s.flip = s.again = false;
    if (long_wall) {  // the window's reserve (MD20250 + 1 blocks per traversing one) fills
      c.md20250 = 0;
      // No alarm on the way: at most MD20250 blocks without plane motion (10762), and G450 circles
      // at every corner, so that a recess narrower than 2r is cut by CDON (TRC-CD-4) rather than
      // stopped by its bottom's equidistant running backwards at a G451 corner (TRC-ELEMENT-1).
      for (Step& s : c.steps) s.dummies = 0, s.g451 = false;
      c.g451_select = false;
    }
    c.right = *inRange(0, 4) == 0;  // G42: the recesses are bumps for the tool
    c.cdon = true;
    c.md20240 = most + *inRange(2, 4);
    c.first_x = signed_um(20000), c.first_y = signed_um(20000);
    // Start and end well off the wall on the tool side, before its start and after its end.
    std::int64_t sx = (-2 * r * ux - 3 * r * uy) / l, sy = (-2 * r * uy + 3 * r * ux) / l;
    c.start_x = c.first_x + sx, c.start_y = c.first_y + sy;
    std::int64_t ex = c.first_x, ey = c.first_y;
    for (const Step& s : c.steps) ex += s.dx, ey += s.dy;
    c.end_x = ex + (2 * r * ux - 3 * r * uy) / l, c.end_y = ey + (2 * r * uy + 3 * r * ux) / l;
    c.kont_select = c.kont_deselect = false;
    return c;
  });
}
}  // namespace

rc::Gen<ContourCase> bottleneck() { return wall_with_recesses("bottleneck", 1, 2); }

rc::Gen<ContourCase> long_bottleneck() { return wall_with_recesses("long-bottleneck", 60, 90); }

namespace {
// SAR-DISCL-3: a level for P2 inside, exactly on, or just outside MD20204 (0.01 mm) beyond P1
// (above) or P4 (below, at 0), or anywhere.
std::int64_t p2_level(std::int64_t h1, int decimals) {
  std::int64_t tol = 1;
  for (int i = 2; i < decimals; ++i) tol *= 10;  // 0.01 mm in units of 10^-decimals mm
  std::int64_t off = *element<std::int64_t>(tol / 2, tol, tol + 1, 0);
  switch (*inRange(0, 4)) {
    case 0:
      return h1 + off;
    case 1:
      return -off;
    default:
      return *inRange<std::int64_t>(0, h1 + 1);
  }
}

// SAR-DISR-1/2: mostly comfortable values; sometimes at the edge of alarm 10742.
std::int64_t disr_for(bool line, std::int64_t r) {
  switch (*inRange(0, 8)) {
    case 0:
      return line ? -(r - *element<std::int64_t>(-1, 0, 1)) : r + *element<std::int64_t>(-1, 0, 1);
    case 1:
      return line ? -*inRange<std::int64_t>(0, r + 1) : *inRange<std::int64_t>(0, 3);
    default:
      return *inRange<std::int64_t>(1, 20001);
  }
}

void add_sar(ContourCase& c, bool approach, bool retraction) {
  SarEnds& s = c.sar;
  std::int64_t r = std::abs(c.radius_um);
  s.approach = approach, s.retraction = retraction;
  s.contour_in = *element(147, 247, 347), s.contour_out = *element(148, 248, 348);
  s.side_in = *element(140, 140, 141, 142, 143), s.side_out = *element(140, 140, 141, 142, 143);
  s.seg_in = *element(340, 341), s.seg_out = *element(340, 341);
  s.disr_in = disr_for(s.contour_in == 147, r), s.disr_out = disr_for(s.contour_out == 148, r);
  s.start_h = *inRange<std::int64_t>(0, 30001);
  s.discl_in = *inRange(0, 4) != 0, s.discl_in_ac = *inRange(0, 4) == 0;
  s.discl_in_v = p2_level(s.start_h, c.decimals);
  s.fad_in = *inRange(0, 3) == 0;
  s.p4_mode = *inRange(0, 3);
  s.end_case = *element(1, 2, 3, 3, 4);
  s.end_h = *inRange<std::int64_t>(0, 30001);
  s.discl_out = *inRange(0, 4) != 0, s.discl_out_ac = *inRange(0, 4) == 0;
  s.discl_out_v = p2_level(s.end_case == 1 || s.end_case == 4 ? 30000 : s.end_h, c.decimals);
  s.deselect = *inRange(0, 4) != 0;
  s.follow = *inRange(0, 2) == 0;
}
}  // namespace

rc::Gen<ContourCase> sar_contour() {
  return rc::gen::exec([] {
    ContourCase c = *rc::gen::weightedOneOf<ContourCase>(
        {{3, random_walk()}, {2, grid_walk()}, {2, with_circles()}, {1, tiny_blocks()}, {1, around_ends()}});
    c.style += "+sar";
    int which = *inRange(0, 4);  // approach, retraction, both (twice)
    add_sar(c, which != 1, which != 0);
    return c;
  });
}

rc::Gen<ContourCase> sar_approach_only() {
  return rc::gen::exec([] {
    ContourCase c = *rc::gen::weightedOneOf<ContourCase>({{3, random_walk()}, {2, grid_walk()}, {2, with_circles()}});
    c.style += "+sar-approach";
    add_sar(c, true, false);
    return c;
  });
}

rc::Gen<ContourCase> any_contour() {
  return rc::gen::weightedOneOf<ContourCase>({{4, random_walk()},
                                              {3, grid_walk()},
                                              {2, near_tangent()},
                                              {2, near_reversal()},
                                              {1, notch()},
                                              {4, with_circles()},
                                              {2, tiny_blocks()},
                                              {1, circles_near_radius()},
                                              {2, around_ends()},
                                              {2, bottleneck()},
                                              {2, exact_situations()}});
}

rc::Gen<ContourCase> contour_definitions() {
  return rc::gen::exec([] {
    ContourCase c = *rc::gen::weightedOneOf<ContourCase>(
        {{3, random_walk()}, {3, grid_walk()}, {3, with_circles()}, {1, tiny_blocks()}, {1, near_tangent()}});
    c.style = "definitions/" + c.style;
    auto length = [](const Step& s) { return std::hypot(static_cast<double>(s.dx), static_cast<double>(s.dy)); };
    for (std::size_t i = 0; i < c.steps.size(); ++i) {
      Step& s = c.steps[i];
      if (!s.arc && *rc::gen::inRange(0, 5) == 0) s.polar = true;
      if (i + 1 == c.steps.size() || *rc::gen::inRange(0, 3) != 0) continue;
      // Mostly small against both elements; one in five too large, so that the reduction of a
      // rounding or chamfer that does not fit (NC-CONTOUR-1) runs too.
      double room = (*rc::gen::inRange(0, 5) == 0 ? 3.0 : 0.3) * std::min(length(s), length(c.steps[i + 1]));
      if (s.arc || c.steps[i + 1].arc) room *= 0.3;
      if (room < 2) continue;
      s.corner = *rc::gen::inRange(1, 4);
      s.corner_value = *rc::gen::inRange<std::int64_t>(1, static_cast<std::int64_t>(room));
    }
    if (*rc::gen::inRange(0, 3) == 0)
      c.rotation_mdeg = *rc::gen::element<std::int64_t>(90000, 30000, 45000, 12345, -60000, 180000, 7000, -135500);
    return c;
  });
}

}  // namespace cutcom::props
