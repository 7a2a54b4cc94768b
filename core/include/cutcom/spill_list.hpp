// A list of serialized JSON items written after the path (actions, alarms, notices, …): kept in
// memory up to a bound, then in an anonymous temporary file, so that the JSON writer's memory
// stays flat whatever the program length (CLI-1; issue "Performance": a million blocks with an
// M word in every third once held 100 MB of action text).
#pragma once

#include <cstdio>
#include <memory>
#include <ostream>
#include <string>

namespace cutcom {

class SpillList {
 public:
  explicit SpillList(std::size_t memory_bound = std::size_t{1} << 20) : bound_(memory_bound) {}
  // Appends one item; items are joined by `separator` when written.
  void append(const std::string& item);
  bool empty() const { return count_ == 0; }
  std::size_t size() const { return count_; }
  // Writes the items in order, joined by `separator`, and leaves the list as it was.
  void write_to(std::ostream& out, const char* separator) const;

 private:
  struct Closer {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  void spill();

  std::size_t bound_;
  std::size_t count_ = 0;
  std::string memory_;  // items after the spilled ones, each ended by '\n' (JSON strings escape it)
  std::unique_ptr<std::FILE, Closer> file_;
  bool file_failed_ = false;  // no temporary file: the items stay in memory (never lost)
};

}  // namespace cutcom
