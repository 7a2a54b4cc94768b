// ref's exact checks for the properties (PROP-META-*, PROP-CD-1): decided on ref's exact path
// before rounding. Apart from the engine's header: the engine is run(), these are test oracles.
#pragma once

#include <array>
#include <optional>
#include <string>

#include "cutcom/machine_data.hpp"
#include "cutcom/ref/engine.hpp"

namespace cutcom::ref {

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

}  // namespace cutcom::ref
