// What both engines have in common: their entry point's shape and the errors they may throw.
#pragma once

#include <string>

#include "cutcom/reader.hpp"

namespace cutcom {

// A program construct the engines do not implement yet: named with its line, never run wrongly.
class UnsupportedError : public InputError {
 public:
  UnsupportedError(int line, const std::string& what)
      : InputError(line, 1, what + " (not supported by this version of cutcom)") {}
};

// The effective radius and the edge it came from; a change while active is a D change (ruling 30).
struct ActiveEdge {
  std::int64_t tool = 0, edge = 0;
  Decimal radius, wear, offn;
  static ActiveEdge of(const ModalState& s) { return {s.tool, s.edge, s.edge_radius, s.edge_wear, s.offn}; }
  friend bool operator==(const ActiveEdge&, const ActiveEdge&) = default;
};

}  // namespace cutcom
