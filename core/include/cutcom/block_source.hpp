// What an engine reads its blocks from: the reader (ProgramReader), or in a test a source of its
// own. Both engines take one; neither knows which it has.
#pragma once

#include "cutcom/block.hpp"

namespace cutcom {

class BlockSource {
 public:
  virtual ~BlockSource() = default;
  // The next block, valid until the next call; nullptr at the end of the program. Throws the
  // reader's InputError where the reader would.
  virtual const Block* next_block() = 0;
  // SAR-END-3: the blocks after a SAR retraction without end point start where it ended.
  virtual void set_position(const Point3& p) = 0;
};

}  // namespace cutcom
