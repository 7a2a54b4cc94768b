// RapidCheck generators of contours (lines and circles): random walks and
// adversarial shapes (near-tangent, near-reversal, exact threshold angles, vanishing elements).
#pragma once

#include <rapidcheck.h>

#include "contour_case.hpp"

namespace cutcom::props {

rc::Gen<ContourCase> any_contour();  // all styles below, weighted
// Contours of the other styles with roundings and chamfers (RND CHR CHF) at their corners, straight
// blocks in polar coordinates and a rotated frame (NC-CONTOUR-1, NC-POLAR-2, NC-FRAME-4).
rc::Gen<ContourCase> contour_definitions();
rc::Gen<ContourCase> random_walk();    // free directions and lengths
rc::Gen<ContourCase> grid_walk();      // multiples of a grid step: exact 45/90 deg corners, ties
rc::Gen<ContourCase> near_tangent();   // successive directions differ by a few micrometres
rc::Gen<ContourCase> near_reversal();  // successive directions almost opposite
rc::Gen<ContourCase> with_circles();   // lines and I/J/K circles: tangent, inner, outer, full
rc::Gen<ContourCase> notch();
rc::Gen<ContourCase> tiny_blocks();  // many blocks shorter than the radius: look-ahead and its window
rc::Gen<ContourCase> around_ends();  // start/end in front of, behind, on the tangent line, near the circle r
rc::Gen<ContourCase> bottleneck();   // walls with recesses narrower/wider than 2r, CDON (TRC-CD-*)
// The same wall with 60 to 90 recesses, MD20250 = 0 and only recesses CDON cuts or passes (G450,
// narrower than r or at least 2r wide): several times more held records than the collision window
// reserves, so that its records are filled again in place (fast's collision_window.hpp).
rc::Gen<ContourCase> long_bottleneck();
rc::Gen<ContourCase> sar_contour();          // SAR approach/retraction on any contour (SAR-*)
rc::Gen<ContourCase> sar_approach_only();    // a SAR approach, its DISCL at the MD20204 boundary in half of them
rc::Gen<ContourCase> exact_situations();     // PROP-HAIR-1: exact boundaries of spec rules and a nanometre off
rc::Gen<ContourCase> circles_near_radius();  // circles whose radius is the tool radius within a few um          //
                                             // slots of width exactly 2r: elements of length 0

}  // namespace cutcom::props
