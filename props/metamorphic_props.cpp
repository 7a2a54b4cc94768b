// Metamorphic properties (PROP-META-*), decided exactly in ref: moving, turning, mirroring or
// scaling a program, or writing it in another plane, moves the exact tool-centre path the same
// way and changes no decision.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "cutcom/ref/exact_checks.hpp"
#include "generators.hpp"
#include "run_case.hpp"

namespace cutcom::props {
namespace {

// Applies the in-plane map v -> (M v) / den + t to a case. Coordinates move to a finer unit
// (10^extra, with den dividing 10^extra) so that they stay whole numbers.
struct PlaneMap {
  std::int64_t m00 = 1, m01 = 0, m10 = 0, m11 = 1, den = 1;
  std::int64_t ta = 0, tb = 0;  // translation in the case's units
  std::int64_t radius_factor = 1;
  bool mirror = false;
};

int extra_digits(std::int64_t den) {
  int e = 0;
  for (std::int64_t p = 1; p % den != 0; p *= 10) ++e;
  return e;
}

std::int64_t pow10(int e) {
  std::int64_t p = 1;
  while (e-- > 0) p *= 10;
  return p;
}

ContourCase apply(const ContourCase& c, const PlaneMap& f) {
  ContourCase o = c;
  int extra = extra_digits(f.den);
  std::int64_t k = pow10(extra) / f.den;
  auto lin = [&](std::int64_t a, std::int64_t b, std::int64_t& oa, std::int64_t& ob) {
    oa = (f.m00 * a + f.m01 * b) * k;
    ob = (f.m10 * a + f.m11 * b) * k;
  };
  auto point = [&](std::int64_t a, std::int64_t b, std::int64_t& oa, std::int64_t& ob) {
    lin(a, b, oa, ob);
    oa += f.ta * pow10(extra), ob += f.tb * pow10(extra);
  };
  point(c.start_x, c.start_y, o.start_x, o.start_y);
  point(c.first_x, c.first_y, o.first_x, o.first_y);
  point(c.end_x, c.end_y, o.end_x, o.end_y);
  for (std::size_t i = 0; i < c.steps.size(); ++i) {
    lin(c.steps[i].dx, c.steps[i].dy, o.steps[i].dx, o.steps[i].dy);
    lin(c.steps[i].ci, c.steps[i].cj, o.steps[i].ci, o.steps[i].cj);  // centre offsets are vectors
    o.steps[i].cr = c.steps[i].cr * f.radius_factor * pow10(extra);   // a length, turned or not
    if (f.mirror) o.steps[i].ccw = !c.steps[i].ccw;                   // a reflection swaps G2 and G3
  }
  o.radius_um = c.radius_um * f.radius_factor * pow10(extra);
  o.decimals = c.decimals + extra;
  if (f.mirror) o.right = !c.right;
  // SAR (SAR-*): DISR is a length in the plane; the levels are along the infeed axis, which the
  // map leaves (only their unit changes); a reflection swaps SAR from the left and the right.
  SarEnds& s = o.sar;
  s.disr_in *= f.radius_factor * pow10(extra), s.disr_out *= f.radius_factor * pow10(extra);
  s.start_h *= pow10(extra), s.end_h *= pow10(extra);
  s.discl_in_v *= pow10(extra), s.discl_out_v *= pow10(extra);
  auto swapped = [&f](int side) { return f.mirror && (side == 141 || side == 142) ? 283 - side : side; };
  s.side_in = swapped(s.side_in), s.side_out = swapped(s.side_out);
  return o;
}

// The same map in workpiece coordinates (mm), for ref's exact comparison.
ref::AffineMap workpiece_map(const PlaneMap& f, int plane, int decimals) {
  PlaneAxes ax = plane_axes(plane == 17 ? Plane::kG17 : plane == 18 ? Plane::kG18 : Plane::kG19);
  ref::AffineMap m;
  m.m = {};
  auto at = [&](int i, int j) -> long& { return m.m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]; };
  at(ax.abscissa, ax.abscissa) = f.m00, at(ax.abscissa, ax.ordinate) = f.m01;
  at(ax.ordinate, ax.abscissa) = f.m10, at(ax.ordinate, ax.ordinate) = f.m11;
  at(ax.applicate, ax.applicate) = f.den;
  m.denominator = f.den;
  auto mm = [&](std::int64_t units) { return *Decimal::parse(fixed(units, decimals)).value; };
  m.offset[static_cast<std::size_t>(ax.abscissa)] = mm(f.ta);
  m.offset[static_cast<std::size_t>(ax.ordinate)] = mm(f.tb);
  return m;
}

void check_image(const ContourCase& c, const PlaneMap& f) {
  // The image needs as many decimals more as 1/den has: they must fit the nine of the program
  // grid (PROP-HAIR-1 cases are written with nine already).
  RC_PRE(c.decimals + extra_digits(f.den) <= 9);
  RC_TAG(c.style);
  ContourCase image = apply(c, f);
  // Line 4 is the selection block: the first move (line 3) starts at the implicit X0 Y0 Z0.
  // Lengths among the machine data scale with the contour (MD21000, the circle end point tolerance).
  MachineData image_md = machine_data_of(c);
  image_md.circle_error_const = *Decimal::parse(fixed(10'000 * f.radius_factor, 6)).value;  // 0.01 mm times the factor
  MachineData md = machine_data_of(c);
  std::string why;
  try {
    why = ref::exact_image_mismatch(to_program(c), to_program(image), md, workpiece_map(f, c.plane, c.decimals), 4,
                                    &image_md);
  } catch (const UnsupportedError&) {  // TRC-UNSUP-1: not comparable
    RC_TAG("not supported");
    return;
  }
  if (!why.empty()) RC_FAIL(why + "\nimage program:\n" + to_program(image));
}

// NC-FRAME-*: the program under a programmable frame against the same program under "TRANS"
// (no frame, same line numbers): the first is the exact image of the second.
void check_frame(const ContourCase& c, const std::string& frame, const PlaneMap& f) {
  RC_TAG(c.style);
  MachineData md = machine_data_of(c);
  std::string plain = "TRANS\n" + to_program(c), framed = frame + "\n" + to_program(c);
  std::string why;
  try {
    why = ref::exact_image_mismatch(plain, framed, md, workpiece_map(f, c.plane, c.decimals), 5);
  } catch (const UnsupportedError&) {
    RC_TAG("not supported");
    return;
  }
  if (!why.empty()) RC_FAIL(why + "\nframed program:\n" + framed);
}

const char* abscissa(int plane) { return plane == 17 ? "X" : plane == 18 ? "Z" : "Y"; }
const char* ordinate(int plane) { return plane == 17 ? "Y" : plane == 18 ? "X" : "Z"; }

// covers: PROP-META-7 NC-FRAME-1 NC-FRAME-2
RC_GTEST_PROP(Metamorphic, TransFrameEqualsTranslatedCoordinates, ()) {
  ContourCase c = *any_contour();
  PlaneMap f;
  f.ta = *rc::gen::inRange<std::int64_t>(-50000, 50001);
  f.tb = *rc::gen::inRange<std::int64_t>(-50000, 50001);
  check_frame(c,
              fmt::format("TRANS {}{} {}{}", abscissa(c.plane), fixed(f.ta, c.decimals), ordinate(c.plane),
                          fixed(f.tb, c.decimals)),
              f);
}

// covers: PROP-META-7 NC-FRAME-3
RC_GTEST_PROP(Metamorphic, MirrorFrameEqualsTheMirroredProgram, ()) {
  ContourCase c = *any_contour();
  PlaneMap f;
  f.m00 = -1;
  check_frame(c, fmt::format("MIRROR {}0", abscissa(c.plane)), f);
}

// covers: PROP-META-7 NC-FRAME-4
RC_GTEST_PROP(Metamorphic, QuarterTurnFrameEqualsTheTurnedProgram, ()) {
  ContourCase c = *any_contour();
  int sign = *rc::gen::arbitrary<bool>() ? -1 : 1;
  PlaneMap f;
  f.m00 = 0, f.m01 = -sign, f.m10 = sign, f.m11 = 0;
  check_frame(c, fmt::format("G{} ROT RPL={}", c.plane, sign * 90), f);
}

// covers: PROP-META-7 NC-UNIT-1
RC_GTEST_PROP(Metamorphic, InchProgramEqualsTheProgramInMm, ()) {
  ContourCase c = *any_contour();
  RC_PRE(c.decimals < 9);  // one decimal more must fit the nine of the program grid (PROP-HAIR-1 cases do not)
  c.sar = {}, c.variant = 0;
  for (Step& s : c.steps) s.dummies = 0;  // their Z words would be inches too
  c.plane_only = true;
  PlaneMap f;
  f.m00 = 254, f.m11 = 254, f.den = 10;  // lengths times 25.4, one more decimal
  ContourCase metric = apply(c, f);
  for (std::size_t i = 0; i < c.steps.size(); ++i) metric.steps[i].cr = c.steps[i].cr * 254;
  metric.radius_um = c.radius_um * 10;  // tool data are metric in both
  RC_TAG(c.style);
  std::string why;
  try {
    why = ref::exact_image_mismatch("G71\n" + to_program(metric), "G70\n" + to_program(c), machine_data_of(c),
                                    ref::AffineMap{}, 1);
  } catch (const UnsupportedError&) {
    RC_TAG("not supported");
    return;
  }
  if (!why.empty()) RC_FAIL(why + "\ninch program:\nG70\n" + to_program(c));
}

// covers: PROP-META-1
RC_GTEST_PROP(Metamorphic, TranslationMovesThePathExactly, ()) {
  PlaneMap f;
  f.ta = *rc::gen::inRange<std::int64_t>(-50000, 50001);
  f.tb = *rc::gen::inRange<std::int64_t>(-50000, 50001);
  check_image(*any_contour(), f);
}

// covers: PROP-META-2
RC_GTEST_PROP(Metamorphic, RationalRotationTurnsThePathExactly, ()) {
  // Pythagorean triples with c a power of 5, so the rotated program is still exact decimal text.
  static const std::int64_t triples[][3] = {{3, 4, 5},   {4, 3, 5},      {7, 24, 25},
                                            {24, 7, 25}, {117, 44, 125}, {44, 117, 125}};
  const auto& t = triples[*rc::gen::inRange(0, 6)];
  int sign = *rc::gen::arbitrary<bool>() ? -1 : 1;
  PlaneMap f;
  f.m00 = t[0], f.m01 = -sign * t[1], f.m10 = sign * t[1], f.m11 = t[0], f.den = t[2];
  check_image(*any_contour(), f);
}

// covers: PROP-META-3 TRC-EQ-1
RC_GTEST_PROP(Metamorphic, MirroringSwapsTheSideAndMirrorsThePath, ()) {
  PlaneMap f;
  f.m00 = -1, f.mirror = true;
  check_image(*any_contour(), f);
}

// covers: PROP-META-4 TRC-RADIUS-1
RC_GTEST_PROP(Metamorphic, ScalingContourAndRadiusScalesThePath, ()) {
  PlaneMap f;
  std::int64_t k = *rc::gen::element<std::int64_t>(2, 3, 10);
  f.m00 = k, f.m11 = k, f.radius_factor = k;
  check_image(*any_contour(), f);
}

// covers: PROP-META-5 NC-PLANE-1
RC_GTEST_PROP(Metamorphic, SameContourInAnotherPlaneIsThePermutedPath, ()) {
  ContourCase c = *any_contour();
  c.plane = 17;
  ContourCase other = c;
  other.plane = *rc::gen::element(18, 19);
  // G17 (X,Y,Z) = plane (a,b,h); in G18 the same (a,b,h) is (Z,X,Y), in G19 (Y,Z,X).
  ref::AffineMap m;
  m.m = other.plane == 18 ? std::array<std::array<long, 3>, 3>{{{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}}
                          : std::array<std::array<long, 3>, 3>{{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}};
  std::string why;
  try {
    why = ref::exact_image_mismatch(to_program(c), to_program(other), machine_data_of(c), m);
  } catch (const UnsupportedError&) {  // TRC-UNSUP-1: not comparable
    RC_TAG("not supported");
    return;
  }
  if (!why.empty()) RC_FAIL(why + "\nother program:\n" + to_program(other));
}

}  // namespace
}  // namespace cutcom::props
