// PROP-HAIR-1: the generator of exact situations, one function per situation a spec rule
// distinguishes, each exactly on its threshold or a nanometre to either side.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <tuple>
#include <utility>
#include <vector>

#include "generators.hpp"

namespace cutcom::props {

namespace {
using rc::gen::element;
using rc::gen::inRange;
}  // namespace

namespace {
// PROP-HAIR-1: the exact situations a spec rule distinguishes, and the same a nanometre (the
// program grid, decimals = 9) to either side. `hair` is 0 (exactly), +1 or -1 (nm).
constexpr std::int64_t kMm = 1000000000;  // nm in a millimetre: these cases are written with 9 decimals

// Pythagorean triples (a, b, c): directions (a, b) / c that keep every point on the grid.
constexpr std::int64_t kTriples[][3] = {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}, {20, 21, 29}};
const std::int64_t* any_triple() { return kTriples[*inRange<std::size_t>(0, std::size(kTriples))]; }
// (x, y) turned by a random number of quarter turns (exact in integers).
std::pair<std::int64_t, std::int64_t> quarter_turned(std::int64_t x, std::int64_t y) {
  for (int k = *inRange(0, 4); k > 0; --k) std::tie(x, y) = std::make_pair(-y, x);
  return {x, y};
}

// Every position of the case in nm: start and end on the compensation side, well away.
void exact_frame(ContourCase& c) {
  c.decimals = 9;
  c.start_x *= 1000, c.start_y *= 1000, c.first_x *= 1000, c.first_y *= 1000, c.end_x *= 1000, c.end_y *= 1000;
  c.radius_um = c.radius_um == 0 ? kMm : std::abs(c.radius_um) * 1000;
  for (Step& st : c.steps) st.flip = st.again = false, st.dummies = 0;
  c.plane = 17;
}

// TRC-CORNER-3/4 (MD20230) and TRC-CORNER-2 (MD20210): a corner whose contour angle is exactly
// the machine datum (45, 90 or 135 degrees), or a nanometre across it.
void corner_on_md(ContourCase& c, std::int64_t hair) {
  std::int64_t l = *inRange<std::int64_t>(2, 40) * kMm / 2;
  int angle = *element(45, 90, 135);
  bool md20230 = angle != 135 && *rc::gen::arbitrary<bool>();
  if (md20230)
    c.md20230 = angle;
  else
    c.md20210 = angle;
  bool left_turn = *rc::gen::arbitrary<bool>();
  std::int64_t turn = left_turn ? 1 : -1;
  Step a{}, b{};
  a.dx = l;
  // The second direction at `angle` from the first: (l, l), (0, l), (-l, l), mirrored for a
  // right turn; the hair moves its end across (the contour angle changes by about hair / l).
  b.dx = angle == 45 ? l : angle == 90 ? 0 : -l, b.dy = turn * l;
  b.dx += hair;
  c.steps = {a, b};
  Step tail{};
  tail.dx = b.dx, tail.dy = b.dy;  // continue straight: one corner only
  c.steps.push_back(tail);
  c.g451_select = *rc::gen::arbitrary<bool>();
  c.steps[1].g451 = c.g451_select;
}

// TRC-KONT-1 / TRC-KONT-2: the start position on the first block's tangent line (on it counts as
// in front) or on the circle of radius r about the contour's start (on it counts as room).
void start_on_boundary(ContourCase& c, std::int64_t hair) {
  std::int64_t l = *inRange<std::int64_t>(2, 40) * kMm / 2, r = c.radius_um / 5 * 5;
  c.radius_um = r;
  Step a{};
  a.dx = l;
  Step b{};
  b.dx = l / 2, b.dy = (*rc::gen::arbitrary<bool>() ? 1 : -1) * l / 2;
  c.steps = {a, b};
  c.kont_select = true;
  std::int64_t side = c.right ? -1 : 1;  // the compensation side is +y for G41 along +x
  if (*rc::gen::arbitrary<bool>()) {
    // On the tangent line (y = first_y), before or after the start, a hair to either side.
    std::int64_t along = *element<std::int64_t>(-3, -1, 1) * l / 2;
    c.start_x = c.first_x + along, c.start_y = c.first_y + hair;
  } else {
    // Behind the contour, exactly r away on a 3-4-5 triangle, a hair nearer or farther.
    std::int64_t sx = *rc::gen::arbitrary<bool>() ? 1 : -1;
    c.start_x = c.first_x + sx * (r / 5) * 3 + sx * hair, c.start_y = c.first_y - side * (r / 5) * 4;
  }
}

// TRC-ARC-CORNER-1: a line after a circle whose equidistant carrier is exactly tangent to the
// circle's equidistant (cos = 3/5 against the circle's tangent, R = 10u, r = 2u), or the tool
// radius a nanometre off, so that the carriers cross twice or miss.
void line_tangent_to_circle_carrier(ContourCase& c, std::int64_t hair) {
  std::int64_t u = *inRange<std::int64_t>(1, 8) * kMm / 2;
  std::int64_t big = 10 * u;
  c.radius_um = 2 * u + hair;
  Step arc{};
  arc.arc = true, arc.ccw = *rc::gen::arbitrary<bool>();
  // A quarter circle: its centre C = start + (R, 0) (I, J from the start).
  arc.ci = big, arc.cj = 0;
  arc.dx = big, arc.dy = arc.ccw ? -big : big;  // ends below (ccw) or above (cw) the centre
  // At the end V = C + (0, ∓R) the circle runs along +x either way; the line leaves at cos = 3/5.
  Step line{};
  line.dx = 3 * u, line.dy = (*rc::gen::arbitrary<bool>() ? 4 : -4) * u;
  Step tail{};
  tail.dx = line.dx, tail.dy = line.dy;
  c.steps = {arc, line, tail};
  c.g451_select = true;  // inner and outer corners by intersection
  c.steps[1].g451 = true;
}

// TRC-ELEMENT-1 at zero: a straight block of exactly 2r between two inner corners (its
// equidistant vanishes), or a circle of radius exactly r on the inside; a nanometre off.
void zero_equidistant(ContourCase& c, std::int64_t hair) {
  std::int64_t r = c.radius_um, l = *inRange<std::int64_t>(3, 8) * r;
  if (*rc::gen::arbitrary<bool>()) {
    c.right = false;  // G41: the tool inside the U
    c.steps = {Step{}, Step{}, Step{}};
    c.steps[0].dx = l;
    c.steps[1].dy = 2 * r + hair;
    c.steps[2].dx = -l;
  } else {
    Step half{};  // a half circle of radius r + hair
    half.arc = true, half.ccw = *rc::gen::arbitrary<bool>();
    half.ci = r + hair, half.dx = 2 * (r + hair);
    Step a{};
    a.dy = half.ccw ? -l : l;
    Step b{};
    b.dy = -a.dy;
    c.steps = {a, half, b};
    // On the inside (the equidistant collapses to the centre) and every other time with CDON:
    // a collapsed circle at a collision check's entry (TRC-CD-2) or in the window an approach
    // searches further ahead (TRC-CD-6, with G460/G461).
    c.right = !half.ccw;
    if (*rc::gen::arbitrary<bool>()) c.cdon = true;
  }
}

// PATH-ELEMENT-2: a full circle, and the same circle ending a nanometre short of or past its
// start (a sliver or nearly a full turn: the sweep must agree, not only the end points).
void full_circle(ContourCase& c, std::int64_t hair) {
  std::int64_t big = *inRange<std::int64_t>(2, 30) * kMm / 2 + c.radius_um;
  Step lead{};
  lead.dx = big;
  Step circle{};
  circle.arc = true, circle.ccw = *rc::gen::arbitrary<bool>();
  circle.cj = (*rc::gen::arbitrary<bool>() ? 1 : -1) * big;
  circle.dx = hair, circle.dy = 0;
  Step out{};
  out.dx = big;
  c.steps = {lead, circle, out};
}

// PATH-ELEMENT-2 at two corners on one point: a full circle that crosses a straight line at its
// start, the line going on after it (G451, both corners by intersection). The line's equidistant
// cuts the circle's at one point P near the start: the corner into the circle trims it there, the
// corner out of it extends it there (one inner, one outer), so the circle turns exactly a whole
// turn from P to P, computed by two corners a rounding apart on one radius (a turn its points
// alone leave undetermined). Directions from Pythagorean triples: every point a whole nanometre.
// The hair moves the circle's end along x, as in full_circle.
void full_circle_between_corners(ContourCase& c, std::int64_t hair) {
  const std::int64_t *t1 = any_triple(), *t2 = any_triple();
  auto [a, b] = quarter_turned(t1[0], t1[1]);  // the line's direction (a, b) / c1
  const std::int64_t c1 = t1[2], c2 = t2[2];
  // The centre from the start: across the line by p, along it by q (in units of R / c2), either
  // side and either way: the corner's angle is atan(q / p), 16 to 74 degrees, below MD20210.
  bool swap = *rc::gen::arbitrary<bool>();
  std::int64_t p = (swap ? t2[1] : t2[0]) * *element<std::int64_t>(1, -1);
  std::int64_t q = (swap ? t2[0] : t2[1]) * *element<std::int64_t>(1, -1);
  // R large enough that the line's equidistant (|p| R / c2 + r from the centre at most) cuts the
  // circle's (R - r at least): R (1 - |p| / c2) >= 2 r, then a whole multiple of c1 c2.
  const std::int64_t r = c.radius_um, unit = c1 * c2;
  std::int64_t least = 2 * r * c2 / (c2 - std::abs(p)) + r;
  std::int64_t big = (least / unit + 1) * unit * *inRange<std::int64_t>(1, 4);
  Step lead{}, circle{}, out{};
  std::int64_t length = (2 * big / c1 + 1) * c1;
  lead.dx = length / c1 * a, lead.dy = length / c1 * b;
  circle.arc = true, circle.ccw = *rc::gen::arbitrary<bool>();
  circle.ci = big / unit * (p * -b + q * a), circle.cj = big / unit * (p * a + q * b);
  circle.dx = hair, circle.dy = 0;
  out.dx = lead.dx - hair, out.dy = lead.dy;
  c.steps = {lead, circle, out};
  c.g451_select = true;
}

// TRC-LOOK-2: a look-ahead whose intersection is exactly the candidate's equidistant start (an
// intersection at the start is valid), or a nanometre before or after it. G41 along +x, a block
// up by 2v, too short for r = 5v at that inner corner, then the candidate along (3, -4): its
// equidistant starts at 4v along and 5v up from the corner, on the open equidistant (5v up);
// the hair moves it up or down.
void look_ahead_at_candidate_start(ContourCase& c, std::int64_t hair) {
  std::int64_t v = *inRange<std::int64_t>(1, 8) * kMm / 4;
  c.radius_um = 5 * v;
  c.right = false;
  c.md20240 = std::max(c.md20240, 3);
  Step open{}, up{}, candidate{}, tail{};
  open.dx = *inRange<std::int64_t>(3, 10) * v;
  up.dy = 2 * v + hair;
  candidate.dx = 3 * v, candidate.dy = -4 * v;
  tail.dx = 5 * v;
  c.steps = {open, up, candidate, tail};
}

// TRC-CD-6 at a collapsed circle: a G460/G461 approach onto a first block too short for its
// inner corner (it runs backwards; TRC-EDGE-5 finds the hit on the next block), then with CDON the
// later blocks of the window are searched: the third is a half circle on the inside of radius
// exactly r (its equidistant collapses to the centre and is not searched), or a nanometre off.
void approach_window_collapsed_circle(ContourCase& c, std::int64_t hair) {
  std::int64_t v = *inRange<std::int64_t>(1, 8) * kMm / 4, r = 4 * v;
  c.radius_um = r;
  c.right = false, c.cdon = true, c.kont_select = false;
  c.edge_select = *element(460, 461);
  c.md20240 = std::max(c.md20240, 3);
  c.start_x = c.first_x - 2 * r, c.start_y = c.first_y + 2 * r;  // the approach crosses the next equidistant
  Step first{}, up{}, half{}, down{};
  first.dx = v;
  up.dy = 3 * r;
  half.arc = true, half.ccw = true;  // from +y round to -y, on the left: the tool inside
  half.ci = -(r + hair), half.dx = -2 * (r + hair);
  down.dy = -3 * r;
  c.steps = {first, up, half, down};
}
// TRC-CD-2 at an extent of exactly 0: under CDON, G41 along +x, a block exactly r long turning
// left (an inner right-angle corner, whose trim is r) so that the entry's intersection is its
// equidistant's normal end: an entry of one point, still compared with the window (TRC-CD-3);
// a nanometre longer, an entry; shorter, none. Positions on a quarter-millimetre grid, so that
// fast's doubles hold them and the extent exactly.
void cd_entry_at_end(ContourCase& c, std::int64_t hair) {
  std::int64_t q = kMm / 4, v = *inRange<std::int64_t>(1, 8) * q, r = 2 * v;
  c.radius_um = r;
  c.right = false, c.cdon = true, c.kont_select = false;
  c.md20240 = std::max(c.md20240, 3);
  c.first_x = c.first_x / q * q, c.first_y = c.first_y / q * q;
  c.start_x = c.first_x - 4 * r, c.start_y = c.first_y - 2 * r;
  Step held{}, before{}, up{}, on{};
  held.dx = *inRange<std::int64_t>(2, 6) * v;  // in the window when `up` is checked
  before.dx = *inRange<std::int64_t>(3, 8) * v;
  up.dy = r + hair;
  on.dx = *inRange<std::int64_t>(2, 6) * v;  // an outer corner after it
  c.steps = {held, before, up, on};
}

// TRC-CD-3 against a held full circle (PATH-ELEMENT-2: a circle whose start is its end turns a
// whole turn): under CDON, a line into a circle of radius R tangent to it, with the tool outside
// (its equidistant R + r, kept whole), a short step on, then a line back across the circle's
// equidistant, two blocks after it: its entry crosses the held circle, and the loop between is cut
// (mutant 60 took such a circle for a piece of no length).
// The hair moves the circle's end by a nanometre along the line: a tiny arc or nearly a whole turn.
void cd_crossing_a_held_full_circle(ContourCase& c, std::int64_t hair) {
  const std::int64_t r = c.radius_um, big = r + *inRange<std::int64_t>(1, 40) * kMm / 2;
  c.cdon = true, c.kont_select = false, c.g451_select = false;
  c.md20240 = std::max(c.md20240, 3);
  std::int64_t side = c.right ? -1 : 1;  // the tool on the left of +x travel is +y (G41)
  c.start_x = c.first_x - 4 * r, c.start_y = c.first_y + side * 2 * r;
  Step lead{}, circle{}, step{}, across{}, out{};
  lead.dx = *inRange<std::int64_t>(1, 4) * big;
  // Clockwise about a centre on the right for G41 (counter-clockwise on the left for G42): the
  // tool outside, the circle tangent to the line at its start.
  circle.arc = true, circle.ccw = c.right, circle.cj = -side * big, circle.dx = hair;
  step.dx = *inRange<std::int64_t>(1, 16) * (big / 16);  // less than R: the line back cuts the circle
  across.dy = -side * (2 * big + *inRange<std::int64_t>(3, 6) * r);
  out.dx = *inRange<std::int64_t>(1, 3) * big;
  c.steps = {lead, circle, step, across, out};
}

// TRC-CD-5 at a joint: G41 along +x by a radii (A), a right turn that moves exactly r along x (B:
// an outer corner, its G450 circle starting at A's equidistant's end), then up by less than the
// inner corner needs (C, too short), and G40 G462 under CDON: C's equidistant extended (on A's
// end's line across, B's step r less the radius) runs back up through the joint of A's
// equidistant and the circle, where the search
// of earlier blocks cuts; a cut there leaves nothing of the circle (campaign 20261277, case
// 241262). Turned by quarters, mirrored for G42; the hair moves B's end along x.
void retraction_through_a_joint(ContourCase& c, std::int64_t hair) {
  // Millimetres, not the micrometres of the frame: the cut's rounding grows with the positions.
  c.radius_um = *inRange<std::int64_t>(1, 10000) * (kMm / 1000) + *inRange<std::int64_t>(0, 1000);
  c.first_x = *inRange<std::int64_t>(-50, 51) * kMm + *inRange<std::int64_t>(0, 1000);
  c.first_y = *inRange<std::int64_t>(-50, 51) * kMm + *inRange<std::int64_t>(0, 1000);
  const std::int64_t r = c.radius_um;
  std::int64_t a = *inRange<std::int64_t>(1, 4), b = *inRange<std::int64_t>(1, 5);
  std::int64_t up = *element<std::int64_t>(r / 4, r / 2, r, 2 * r);
  std::vector<std::pair<std::int64_t, std::int64_t>> v = {
      {a * r, 0}, {r + hair, -b * r}, {0, up}, {*inRange<std::int64_t>(-3, 4) * r, -*inRange<std::int64_t>(4, 12) * r}};
  c.right = *rc::gen::arbitrary<bool>();
  for (auto& [x, y] : v) {
    if (c.right) y = -y;  // mirrored: the same corners on the other side
    std::tie(x, y) = quarter_turned(x, y);
  }
  c.steps.assign(3, Step{});
  std::int64_t ex = c.first_x, ey = c.first_y;
  for (std::size_t i = 0; i < 3; ++i) c.steps[i].dx = v[i].first, c.steps[i].dy = v[i].second;
  for (std::size_t i = 0; i < 4; ++i) ex += v[i].first, ey += v[i].second;
  c.end_x = ex, c.end_y = ey;
  c.g451_select = false, c.g451_deselect = *rc::gen::arbitrary<bool>();
  c.kont_deselect = false, c.edge_deselect = 462, c.sar.retraction = false;
  c.cdon = true;
  c.md20240 = *inRange(3, 6);
}

// SAR-SIDE-2: a smooth approach by a circle (G247/G347) with G143, so that the side is that of
// the start P0 against the tangent at P4: P0 exactly on the tangent line (alarm 10744), or off it
// by a cross product of 1 nm^2, a distance of 1/|d| nm (d the first block, 2 to 20 mm long:
// below 10^-12 mm), far finer than the grid's nanometre. d's components are coprime, and the
// step off the line solves d x e = 1 (extended Euclid).
void sar_start_on_tangent(ContourCase& c, std::int64_t hair) {
  std::int64_t a = *inRange<std::int64_t>(2 * kMm, 20 * kMm), b = *inRange<std::int64_t>(-20 * kMm, 20 * kMm);
  while (std::gcd(a, b) != 1) ++b;
  // a x + b y = 1; then e = (-y, x) has d x e = a x + b y = 1.
  std::int64_t r0 = a, r1 = b, x0 = 1, x1 = 0, y0 = 0, y1 = 1;
  while (r1 != 0) {
    std::int64_t q = r0 / r1;
    std::tie(r0, r1) = std::make_pair(r1, r0 - q * r1);
    std::tie(x0, x1) = std::make_pair(x1, x0 - q * x1);
    std::tie(y0, y1) = std::make_pair(y1, y0 - q * y1);
  }
  if (r0 < 0) x0 = -x0, y0 = -y0;  // gcd 1 up to its sign
  std::int64_t ex = -y0, ey = x0;
  Step first{};
  first.dx = a, first.dy = b;
  Step turn{};
  turn.dx = -b / 2, turn.dy = a / 2;
  c.steps = {first, turn};
  std::int64_t back = *inRange<std::int64_t>(1, 3);  // P0 behind P4 along the tangent
  c.start_x = c.first_x - back * a + hair * ex, c.start_y = c.first_y - back * b + hair * ey;
  c.kont_select = false, c.cdon = false;
  SarEnds& s = c.sar;
  s = SarEnds{};
  s.approach = true;
  s.contour_in = *element(247, 347);
  s.side_in = 143;
  s.seg_in = *element(340, 341);
  s.disr_in = c.radius_um + *inRange<std::int64_t>(1, 10) * kMm;
  s.start_h = *inRange<std::int64_t>(1, 30) * kMm;
}

// A CR= circle that starts along (ua, ub)/cu, its centre R to the left (G3) or right (G2), its
// end R (wa, wb)/cw from the centre (R a multiple of cu and cw: every point a whole unit); the
// direction it ends along, times cw. A start and end that coincide are moved to the other side.
struct TangentCircle {
  Step step;
  std::int64_t ta, tb;
};
TangentCircle tangent_cr_circle(std::int64_t ua, std::int64_t ub, std::int64_t cu, std::int64_t radius, bool ccw,
                                std::int64_t wa, std::int64_t wb, std::int64_t cw) {
  std::int64_t side = ccw ? 1 : -1;
  std::int64_t to_centre_x = -side * (radius / cu) * ub, to_centre_y = side * (radius / cu) * ua;
  if (to_centre_x + (radius / cw) * wa == 0 && to_centre_y + (radius / cw) * wb == 0) wa = -wa, wb = -wb;
  // Short or long (CR's sign): the turn from start to end about the centre in the sense of travel.
  double from = std::atan2(double(-to_centre_y), double(-to_centre_x)), to = std::atan2(double(wb), double(wa));
  double sweep = std::fmod((ccw ? to - from : from - to) + 4 * std::numbers::pi, 2 * std::numbers::pi);
  TangentCircle t;
  t.step.arc = true, t.step.ccw = ccw;
  t.step.cr = sweep <= std::numbers::pi ? radius : -radius;
  t.step.dx = to_centre_x + (radius / cw) * wa, t.step.dy = to_centre_y + (radius / cw) * wb;
  t.ta = -side * wb, t.tb = side * wa;
  return t;
}

// TRC-CORNER-1 / TRC-KONT-1 at a CR= circle (its centre carries a square root): a line, a CR=
// circle tangent to it (and every other time a second CR= circle tangent to that, bending either
// way), a line leaving along the last circle's end tangent; every direction from a Pythagorean
// triple, so that each point is a whole unit of the grid. Or the circle first, after a KONT start
// on its tangent line. The hair moves the first circle's end (the corners after it turn by a
// trace) or the start across the line.
void cr_circle_tangent(ContourCase& c, std::int64_t hair) {
  auto direction = [](const std::int64_t* t) { return quarter_turned(t[0], t[1]); };  // (a, b) / c
  const std::int64_t *t1 = any_triple(), *t2 = any_triple(), *t3 = any_triple();
  const std::int64_t c1 = t1[2], c2 = t2[2], c3 = t3[2], g = *inRange<std::int64_t>(1, 16) * kMm / 100;
  auto [ua, ub] = direction(t1);  // the line into the circle, times c1
  auto [wa, wb] = direction(t2);  // the first circle's end less its centre, times c2
  TangentCircle first = tangent_cr_circle(ua, ub, c1, *inRange<std::int64_t>(1, 5) * c1 * c2 * g,
                                          *rc::gen::arbitrary<bool>(), wa, wb, c2);
  first.step.dx += hair;
  Step lead{}, leave{};
  std::int64_t lead_length = *inRange<std::int64_t>(1, 4) * g * c2;
  lead.dx = lead_length * ua, lead.dy = lead_length * ub;
  std::vector<Step> circles{first.step};
  std::int64_t ta = first.ta, tb = first.tb, ct = c2;  // the last circle's end direction, times ct
  if (*rc::gen::arbitrary<bool>()) {
    auto [va, vb] = direction(t3);
    TangentCircle second = tangent_cr_circle(ta, tb, c2, *inRange<std::int64_t>(1, 5) * c2 * c3 * g,
                                             *rc::gen::arbitrary<bool>(), va, vb, c3);
    circles.push_back(second.step);
    ta = second.ta, tb = second.tb, ct = c3;
  }
  std::int64_t leave_length = *inRange<std::int64_t>(1, 4) * g * (c1 * c2 * c3 / ct);
  leave.dx = leave_length * ta, leave.dy = leave_length * tb;
  c.g451_select = *rc::gen::arbitrary<bool>();
  if (*rc::gen::arbitrary<bool>()) {
    c.steps = {lead};
    c.steps.insert(c.steps.end(), circles.begin(), circles.end());
    c.steps.insert(c.steps.end(), {leave, leave});
    return;
  }
  circles.front().dx -= hair;  // the circle first, exactly tangent to `lead`'s direction at its start
  c.steps = circles;
  c.steps.insert(c.steps.end(), {leave, leave});
  c.kont_select = true, c.cdon = false;
  std::int64_t back = *element<std::int64_t>(-2, -1, 1);
  c.start_x = c.first_x - back * lead.dx - hair * ub, c.start_y = c.first_y - back * lead.dy + hair * ua;
}

}  // namespace

rc::Gen<ContourCase> exact_situations() {
  return rc::gen::exec([] {
    ContourCase c = *random_walk();
    exact_frame(c);
    std::int64_t hair = *element<std::int64_t>(0, 0, 1, -1);
    // One entry per situation: its name (the style the report counts) and what writes it.
    struct Situation {
      const char* name;
      void (*write)(ContourCase&, std::int64_t);
    };
    static constexpr Situation kSituations[] = {{"corner-on-md", corner_on_md},
                                                {"start-on-boundary", start_on_boundary},
                                                {"line-tangent-to-circle-carrier", line_tangent_to_circle_carrier},
                                                {"zero-equidistant", zero_equidistant},
                                                {"full-circle", full_circle},
                                                {"full-circle-between-corners", full_circle_between_corners},
                                                {"look-ahead-at-candidate-start", look_ahead_at_candidate_start},
                                                {"approach-window-collapsed-circle", approach_window_collapsed_circle},
                                                {"sar-start-on-tangent", sar_start_on_tangent},
                                                {"cd-entry-at-end", cd_entry_at_end},
                                                {"retraction-through-a-joint", retraction_through_a_joint},
                                                {"cd-crossing-a-held-full-circle", cd_crossing_a_held_full_circle},
                                                {"cr-circle-tangent", cr_circle_tangent}};
    // Uniform whatever the case's size (inRange alone favours the first entries at small sizes:
    // the last situation came up 5 times in 20,000 cases, the first 198).
    const Situation& situation =
        kSituations[*rc::gen::resize(rc::kNominalSize, inRange<std::size_t>(0, std::size(kSituations)))];
    situation.write(c, hair);
    c.style = std::string("exact/") + situation.name +
              (hair == 0  ? "/exactly"
               : hair > 0 ? "/a-hair-above"
                          : "/a-hair-below");
    return c;
  });
}

}  // namespace cutcom::props
