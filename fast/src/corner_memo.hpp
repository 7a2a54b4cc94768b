// fast: the last corner intersection and arc extent taken, with their arguments. Under CDON the
// entry (collision.cpp) and then the corner step (compensation.cpp) take both at the same corner
// of the same two blocks; the second asks the memo. A memo answers only for arguments equal bit
// for bit to the last ones, so its answer is the function's (both are pure): the path and the
// trace are the same with it as without it.
#pragma once

#include <bit>
#include <cstdint>

#include "plane_geometry.hpp"

namespace cutcom::fast {

inline bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
inline bool same_bits(Vec2 a, Vec2 b) { return same_bits(a.a, b.a) && same_bits(a.b, b.b); }
inline bool same_bits(const Carrier& u, const Carrier& v) {
  return u.circle == v.circle && same_bits(u.point, v.point) && same_bits(u.direction, v.direction) &&
         same_bits(u.radius, v.radius);
}

// corner_intersection(u, v, corner, ahead, r, x) of the last call.
class IntersectionMemo {
 public:
  bool intersection(const Carrier& u, const Carrier& v, Vec2 corner, Vec2 ahead, double r, Vec2& x) {
    bool same = valid_ && same_bits(u, u_) && same_bits(v, v_) && same_bits(corner, corner_) &&
                same_bits(ahead, ahead_) && same_bits(r, r_);
    if (!same) {
      u_ = u, v_ = v, corner_ = corner, ahead_ = ahead, r_ = r, valid_ = true;
      found_ = corner_intersection(u, v, corner, ahead, r, x_);
    }
    if (found_) x = x_;
    return found_;
  }

 private:
  Carrier u_, v_;
  Vec2 corner_, ahead_, x_;
  double r_ = 0;
  bool found_ = false, valid_ = false;
};

// The rotation of point p from an arc element's start (Compensation::extent_of) of the last two
// calls: an atan2 that the entry and the corner step take of the same point, and that closing the
// element a block later takes again from its start (Compensation::close_open).
class RotationMemo {
 public:
  double rotation(const Element& e, Vec2 p) {
    for (Entry& k : entries_)
      if (k.valid && same_bits(e.start, k.start) && same_bits(e.centre, k.centre) && e.sense == k.sense &&
          same_bits(p, k.p))
        return k.rotation;
    Entry& k = entries_[next_];
    next_ ^= 1;
    k.start = e.start, k.centre = e.centre, k.sense = e.sense, k.p = p, k.valid = true;
    k.rotation = signed_rotation(e.start - e.centre, p - e.centre, e.sense);
    return k.rotation;
  }

 private:
  struct Entry {
    Vec2 start, centre, p;
    int sense = 1;
    double rotation = 0;
    bool valid = false;
  };
  Entry entries_[2];
  int next_ = 0;  // the older entry, replaced next
};

}  // namespace cutcom::fast
