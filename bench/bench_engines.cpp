// Time per block of both engines on the bundled example, and fast's throughput and allocations
// on long generated programs (the zig-zag's text is written before the timed loop and read from
// memory, as a file's text comes from the page cache; the SAR islands' line by line).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <new>
#include <sstream>
#include <streambuf>
#include <string>
#include <string_view>

#include "cutcom/fast/engine.hpp"
#include "cutcom/ref/engine.hpp"

// Counting allocations: the steady state of fast must not allocate per block.
static std::atomic<long> g_allocations{0};
void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace {

using namespace cutcom;

// As `cutcom run` without --trace: no decision is kept, so the engines do not build them.
class NullSink : public PathSink {
 public:
  void element(const PathElement&) override { ++elements; }
  bool keeps_decisions() const override { return false; }
  long elements = 0;
};

// A compensated zig-zag of `blocks` blocks (inner and outer corners, G450 circles, infeeds).
// Written once before the timed loop: made on the fly, its writing was a twentieth of the time the
// benchmark reported as the reader's and the engine's.
std::string zig_zag_program(long blocks, bool cdon = false) {
  std::string text = "$TC_DP6[1,1]=2\nN1 G0 X-10 Y-10 T1 D1\n";
  text += cdon ? "N2 G1 G41 CDON X0 Y0 F500\n" : "N2 G1 G41 X0 Y0 F500\n";
  char line[64];
  for (long k = 3; k < blocks + 3; ++k) {
    if (k % 7 == 0) {
      text += "Z-1 M8\n";  // a block without plane motion
      continue;
    }
    long i = k - 3;
    char* p = line;
    *p++ = 'X';
    p = std::to_chars(p, line + sizeof line, 10 * (i + 1)).ptr;
    text.append(line, p);
    text += i % 2 == 0 ? ".5 Y20\n" : ".5 Y0\n";
  }
  return text + "G40 X-10 Y-10\n";
}

// A program's text read from memory without a copy of it (std::istringstream copies its string).
class MemoryText : public std::streambuf {
 public:
  explicit MemoryText(std::string& text) { setg(text.data(), text.data(), text.data() + text.size()); }
};

// Islands of 6 blocks each: a SAR approach (G247 G341), a rectangle, a SAR retraction (G248 G340
// with G40 and its end point), produced line by line (spec SAR-*).
class SarIslandsProgram : public std::streambuf {
 public:
  explicit SarIslandsProgram(long blocks) : total_(blocks) {}

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (n_ > total_ + 1) return traits_type::eof();
    int n = next_line();
    setg(line_, line_, line_ + n);
    return traits_type::to_int_type(*gptr());
  }

 private:
  // Written into a fixed buffer: the lines are longer than a short string, and the generator
  // must not allocate (the allocations counted are the engine's).
  int next_line() {
    long k = n_++;
    if (k == 0) return std::snprintf(line_, sizeof line_, "$TC_DP6[1,1]=2\n");
    if (k == 1) return std::snprintf(line_, sizeof line_, "N1 G0 X-70 Y-20 Z10 T1 D1\n");
    long x = 100 * ((k - 2) / 6);
    switch ((k - 2) % 6) {
      case 0:
        return std::snprintf(line_, sizeof line_, "G41 G247 G341 DISR=3 DISCL=2 FAD=200 X%ld Y0 Z-2 F500\n", x);
      case 1:
        return std::snprintf(line_, sizeof line_, "G1 Y20\n");
      case 2:
        return std::snprintf(line_, sizeof line_, "X%ld.5\n", x + 20);
      case 3:
        return std::snprintf(line_, sizeof line_, "Y0\n");
      case 4:
        return std::snprintf(line_, sizeof line_, "X%ld\n", x + 5);
      default:
        return std::snprintf(line_, sizeof line_, "G40 G248 G340 DISR=3 DISCL=2 X%ld Y-20 Z10 F2000\n", x + 30);
    }
  }
  long total_, n_ = 0;
  char line_[128];
};

// 0: examples/pocket.mpf (lines), 1: examples/contour.mpf (lines and circles).
std::string example_text(long which = 0) {
  std::ifstream in(std::string(CUTCOM_EXAMPLES) + (which == 0 ? "/pocket.mpf" : "/contour.mpf"));
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int example_blocks(const std::string& text) {
  std::istringstream in(text);
  ProgramReader r(in);
  Block b;
  int n = 0;
  while (r.next(b)) ++n;
  return n;
}

// Both engines on the bundled example; the counter gives the time per block.
template <bool kRef>
void BM_Example(benchmark::State& state) {
  std::string text = example_text(state.range(0));
  MachineData md;
  for (auto _ : state) {
    std::istringstream in(text);
    ProgramReader reader(in, md.initial_state());
    NullSink sink;
    if constexpr (kRef)
      ref::run(reader, md, sink);
    else
      fast::run(reader, md, sink);
    benchmark::DoNotOptimize(sink.elements);
  }
  int blocks = example_blocks(text);
  state.SetItemsProcessed(state.iterations() * blocks);
  state.counters["us/block"] = benchmark::Counter(
      static_cast<double>(blocks), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Example<false>)->Name("BM_ExampleFast")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Example<true>)->Name("BM_ExampleRef")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// fast on long programs: blocks per second, and allocations per block (0 in the steady state:
// the count does not grow with the program length).
void BM_FastLongProgram(benchmark::State& state, bool cdon) {
  MachineData md;
  long allocations = 0;
  std::string program = zig_zag_program(state.range(0), cdon);
  for (auto _ : state) {
    MemoryText text(program);
    std::istream in(&text);
    ProgramReader reader(in, md.initial_state());
    NullSink sink;
    long before = g_allocations.load();
    fast::run(reader, md, sink);
    allocations = g_allocations.load() - before;
    benchmark::DoNotOptimize(sink.elements);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.counters["allocations"] = static_cast<double>(allocations);
}
// The reader alone (words, modal state, exact positions): blocks per second on the same text.
// Programs without contour definitions pass the contour stage by (NC-CONTOUR-*).
void BM_ReaderLongProgram(benchmark::State& state) {
  MachineData md;
  std::string program = zig_zag_program(state.range(0));
  for (auto _ : state) {
    MemoryText text(program);
    std::istream in(&text);
    ProgramReader reader(in, md.initial_state());
    Block b;
    long n = 0;
    while (reader.next(b)) ++n;
    benchmark::DoNotOptimize(n);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_ReaderLongProgram)->Arg(100000)->Unit(benchmark::kMillisecond);

BENCHMARK_CAPTURE(BM_FastLongProgram, cdof, false)->Arg(1000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FastLongProgram, cdon, true)->Arg(1000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond);

// A pocket written as a WHILE loop (issue "Parametric programs", item 9): `passes` passes of four
// blocks whose coordinates are computed, under G41. Blocks per second through the interpreter,
// the reader and fast, against the same path written out block by block (BM_FastPlainPocket).
std::string while_pocket(long passes) {
  return "DEF INT KK=0\nDEF REAL XX\n$TC_DP1[1,1]=120\n$TC_DP6[1,1]=0.2\n"
         "N10 G0 X-10 Y0 T1 D1\nN20 G1 G41 X0 Y0 F1000\nWHILE KK<" +
         std::to_string(passes) +
         "\n  XX=KK*2\n  G1 Y50\n  X=XX+1\n  Y0\n  X=XX+2\n  KK=KK+1\nENDWHILE\n"
         "G40 G1 X=XX+20 Y-10\nM30\n";
}

std::string plain_pocket(long passes) {
  std::string text = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=0.2\nN10 G0 X-10 Y0 T1 D1\nN20 G1 G41 X0 Y0 F1000\n";
  for (long k = 0; k < passes; ++k)
    text += "G1 Y50\nX" + std::to_string(2 * k + 1) + "\nY0\nX" + std::to_string(2 * k + 2) + "\n";
  return text + "G40 G1 X" + std::to_string(2 * (passes - 1) + 20) + " Y-10\nM30\n";
}

void BM_FastPocket(benchmark::State& state, bool loop) {
  MachineData md;
  long passes = state.range(0) / 4;
  std::string text = loop ? while_pocket(passes) : plain_pocket(passes);
  for (auto _ : state) {
    std::istringstream in(text);
    ProgramReader reader(in, md.initial_state());
    NullSink sink;
    fast::run(reader, md, sink);
    benchmark::DoNotOptimize(sink.elements);
  }
  state.SetItemsProcessed(state.iterations() * 4 * passes);
}
BENCHMARK_CAPTURE(BM_FastPocket, while_loop, true)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_FastPocket, plain, false)->Arg(100000)->Unit(benchmark::kMillisecond);

// SAR: the same for programs made of SAR approaches and retractions (no allocation per SAR block).
void BM_FastLongSarProgram(benchmark::State& state) {
  MachineData md;
  long allocations = 0;
  for (auto _ : state) {
    SarIslandsProgram text(state.range(0));
    std::istream in(&text);
    ProgramReader reader(in, md.initial_state());
    NullSink sink;
    long before = g_allocations.load();
    fast::run(reader, md, sink);
    allocations = g_allocations.load() - before;
    benchmark::DoNotOptimize(sink.elements);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.counters["allocations"] = static_cast<double>(allocations);
}
BENCHMARK(BM_FastLongSarProgram)->Arg(1200)->Arg(120000)->Arg(1200000)->Unit(benchmark::kMillisecond);

void BM_RefLongProgram(benchmark::State& state) {
  MachineData md;
  std::string program = zig_zag_program(state.range(0));
  for (auto _ : state) {
    MemoryText text(program);
    std::istream in(&text);
    ProgramReader reader(in, md.initial_state());
    NullSink sink;
    ref::run(reader, md, sink);
    benchmark::DoNotOptimize(sink.elements);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_RefLongProgram)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
