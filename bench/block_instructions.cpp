// Reads one program and runs it through the reader alone (--reader), the reader and the fast
// engine without output, or those and a writer (--text, --json) on the same thread to a stream
// that discards what it is given: the process whose instructions bench/peer_bench.py counts under
// valgrind (a count per block does not move with a shared machine's load, as times do). It links
// no ref: CGAL checks the rounding modes when it starts, which valgrind does not emulate.
#include <cstdio>
#include <fstream>
#include <ostream>
#include <streambuf>
#include <string>

#include "cutcom/fast/engine.hpp"
#include "cutcom/output.hpp"
#include "cutcom/reader.hpp"

namespace {
// As `cutcom run` without --trace: no decision is kept, so the engine does not build them.
class CountingSink : public cutcom::PathSink {
 public:
  void element(const cutcom::PathElement&) override { ++elements; }
  bool keeps_decisions() const override { return false; }
  long elements = 0;
};

// Takes the writer's large blocks and drops them (as -o /dev/null, without the system calls).
class Discard : public std::streambuf {
 protected:
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
  int overflow(int c) override { return c == traits_type::eof() ? 0 : c; }
};

template <class Writer>
int run_writing(cutcom::ProgramReader& reader, const cutcom::MachineData& md) {
  Discard discard;
  std::ostream out(&discard);
  Writer writer(out, "fast", false);
  cutcom::fast::run(reader, md, writer);
  writer.finish();
  std::printf("written\n");
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  std::string mode = argc == 3 ? argv[2] : "";
  if (argc < 2 || argc > 3 || (argc == 3 && mode != "--reader" && mode != "--text" && mode != "--json")) {
    std::fprintf(stderr, "usage: block_instructions PROGRAM [--reader | --text | --json]\n");
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
    if (mode == "--text") return run_writing<cutcom::TextWriter>(reader, md);
    if (mode == "--json") return run_writing<cutcom::JsonWriter>(reader, md);
    if (mode == "--reader") {
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
