// ref: the reference TRC engine in exact arithmetic (CORE::Expr through CGAL's sqrt kernel,
// GMP and MPFR for predicates). Literal, readable, never rounding; slow by design. This header
// is CGAL-free so that the CLI, tests and props can include it.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "cutcom/engine.hpp"
#include "cutcom/machine_data.hpp"
#include "cutcom/sink.hpp"

namespace cutcom::ref {

// Results of the exact self-checks on ref's own path (PROP-EXACT-*), computed before rounding.
struct ExactCheckReport {
  int offset_endpoints_checked = 0;  // TRC-EQ-1: each offset end point at signed distance s r
  int circles_checked = 0;           // TRC-G450-1: centre = programmed corner, radius = r
  int joints_checked = 0;            // PATH-CONT-1: each element starts where the previous ended
  std::vector<std::string> failures;
};

// An exact affine map of workpiece coordinates: x' = (m x) / denominator + offset.
struct AffineMap {
  std::array<std::array<long, 3>, 3> m{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  long denominator = 1;
  std::array<Decimal, 3> offset{};
};

// PROP-META-*: runs both programs and checks exactly (before rounding) that the second's path is
// the image of the first's under `map`, element by element, with the same decisions and alarms.
// Elements of source lines before `first_line` are not compared (the first move starts at the
// implicit position X0 Y0 Z0, which is no part of the program and is not mapped).
// Returns what differs, or an empty string.
// `mapped_md`: machine data for the image where lengths among them must be mapped too (MD21000
// under scaling); the original's by default.
std::string exact_image_mismatch(const std::string& original, const std::string& mapped, const MachineData& md,
                                 const AffineMap& map, int first_line = 1, const MachineData* mapped_md = nullptr);

// The mirror relation of approach and retraction (TRC-KONT-*, PROP-META-6): `reversed` runs the
// same contour backwards (sides swapped, start and end swapped). Checks exactly that the approach
// elements of each are the retraction elements of the other, reversed. Empty: they are; nullopt:
// an alarm in either run (not comparable).
std::optional<std::string> exact_reversal_mismatch(const std::string& original, const std::string& reversed,
                                                   const MachineData& md, int selection_line, int deselection_line);

// PROP-CD-1: runs the program and checks exactly that no point of ref's compensated path
// (equidistants, transition circles) comes closer than r to a programmed compensated block.
// Contours with circles are not checked (pairs = 0).
struct ClearanceCheck {
  bool alarm = false;        // an alarm stopped the run: nothing checked
  bool unsupported = false;  // rejected "not supported" (TRC-UNSUP-1): nothing checked
  int pairs = 0;             // (path element, programmed block) pairs decided
  std::string violation;     // empty: none
};
ClearanceCheck exact_clearance(const std::string& program, const MachineData& md);

// Reads the program block by block and runs it. Returns false if an alarm stopped it.
// With `checks`, also verifies the exact path (costs exact zero tests: milliseconds each).
bool run(ProgramReader& reader, const MachineData& md, PathSink& sink, ExactCheckReport* checks = nullptr);

}  // namespace cutcom::ref
