// Reads one program and runs it through the reader alone (--reader) or the reader and the fast
// engine, without output: the process whose instructions bench/peer_bench.py counts under
// valgrind (a count per block does not move with a shared machine's load, as times do). It links
// no ref: CGAL checks the rounding modes when it starts, which valgrind does not emulate.
#include <cstdio>
#include <cstring>
#include <fstream>

#include "cutcom/fast/engine.hpp"
#include "cutcom/reader.hpp"

namespace {
// As `cutcom run` without --trace: no decision is kept, so the engine does not build them.
class CountingSink : public cutcom::PathSink {
 public:
  void element(const cutcom::PathElement&) override { ++elements; }
  bool keeps_decisions() const override { return false; }
  long elements = 0;
};
}  // namespace

int main(int argc, char** argv) {
  bool reader_only = argc == 3 && std::strcmp(argv[2], "--reader") == 0;
  if (argc < 2 || (argc == 3 && !reader_only) || argc > 3) {
    std::fprintf(stderr, "usage: block_instructions PROGRAM [--reader]\n");
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::fprintf(stderr, "block_instructions: cannot open %s\n", argv[1]);
    return 2;
  }
  cutcom::MachineData md;
  cutcom::ProgramReader reader(in, md.initial_state());
  try {
    if (reader_only) {
      cutcom::Block b;
      long blocks = 0;
      while (reader.next(b)) ++blocks;
      std::printf("%ld blocks\n", blocks);
      return 0;
    }
    CountingSink sink;
    cutcom::fast::run(reader, md, sink);
    std::printf("%ld elements\n", sink.elements);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "block_instructions: %s: %s\n", argv[1], e.what());
    return 1;
  }
  return 0;
}
