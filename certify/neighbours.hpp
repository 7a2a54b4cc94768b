// Programs near a user's program (`cutcom certify --from`, issue "Certification strength" item
// 6): its values moved by small steps and onto nearby exact ties, so that fast is certified on
// the programs a user runs and on what a small edit of them would be.
#pragma once

#include <cstdint>
#include <string>

#include "cutcom/machine_data.hpp"

namespace cutcom::props {

struct Neighbour {
  std::string text;
  MachineData md;
  std::string change;  // what was moved, for the report ("line 7 X: 12.5 -> 12.500000001")
};

// Neighbour k of `text` (with machine data `md`): one to three of its coordinates, radii and
// SAR distances (numbers written after X Y Z I J K, CR= RND= CHF= DISR= DISCL= AP= RP= and the
// tool radius $TC_DP6) moved by 10^-3, 10^-6 or 10^-9 mm either way, or set equal to another
// value of the same address (an exact tie: an axis-parallel move, a zero-length block, equal
// radii); every fourth neighbour also moves MD20210 or MD20230 by a degree or MD20240 by one
// block. The same (text, md, seed, k) gives the same neighbour.
Neighbour neighbour_of(const std::string& text, const MachineData& md, std::uint64_t seed, long k);

}  // namespace cutcom::props
