// Throughput of lexer + parser + interpreter (docs/performance.md).
//
// Each benchmark generates its program in memory once, outside the timed region, and runs it
// through a fresh ncoffset::Channel per iteration. items_per_second = executed NC blocks per
// second (source lines that are blocks; the WHILE variant counts every executed line of the
// loop body, including WHILE and ENDWHILE).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "ncoffset/channel.hpp"
#include "out/writers.hpp"

namespace {

// Counts segments; does nothing else.
class NullSink final : public ncoffset::PathSink {
 public:
  void segment(const ncoffset::Segment&) override { ++segments; }
  void finish(const ncoffset::Alarm*) override {}
  long long segments = 0;
};

// Appends a decimal with three fraction digits (like a CAM post-processor writes them).
void appendFixed3(std::string& s, long milli) {
  if (milli < 0) {
    s += '-';
    milli = -milli;
  }
  s += std::to_string(milli / 1000);
  s += '.';
  long frac = milli % 1000;
  s += static_cast<char>('0' + frac / 100);
  s += static_cast<char>('0' + frac / 10 % 10);
  s += static_cast<char>('0' + frac % 10);
}

// `N<n> G1 X.. Y.. Z.. F1000` blocks with varying coordinates (no two consecutive blocks
// end at the same point, so every block produces one segment), then M30.
std::string plainG1Program(long blocks) {
  std::string s;
  s.reserve(static_cast<size_t>(blocks) * 40 + 64);
  unsigned x = 12345, y = 678, z = 91;  // simple LCG-driven coordinates in +-200 mm
  for (long i = 1; i <= blocks; ++i) {
    x = x * 1103515245u + 12345u;
    y = y * 22695477u + 1u;
    z = z * 1664525u + 1013904223u;
    s += 'N';
    s += std::to_string(i * 10);
    s += " G1 X";
    appendFixed3(s, static_cast<long>(x >> 8) % 400000 - 200000);
    s += " Y";
    appendFixed3(s, static_cast<long>(y >> 8) % 400000 - 200000);
    s += " Z";
    appendFixed3(s, static_cast<long>(z >> 8) % 100000 - 50000 + (i & 1));
    s += " F1000\n";
  }
  s += "M30\n";
  return s;
}

// A WHILE loop whose body mixes R-parameter arithmetic, functions, G1 and G2/G3 arcs.
// 9 executed lines per iteration (WHILE, 3 assignments, 4 motion blocks, ENDWHILE).
constexpr long kLoopLinesPerIteration = 9;
std::string loopProgram(long iterations) {
  return "G17 G90 G0 X0 Y0 Z0\n"
         "R1=0 R3=" +
         std::to_string(iterations) +
         "\n"
         "WHILE R1<R3\n"
         "  R1=R1+1\n"
         "  R2=R1*0.001 R4=SIN(R1*7)*2+SQRT(R1)/1000\n"
         "  R5=ROUND(R1/3)*0.5 MOD 10\n"
         "  G1 X=R2 Y=R4 Z=-R5 F=1000+R1 MOD 500\n"
         "  G3 X=R2+10 Y=R4 I5 J0\n"
         "  G2 X=R2+20 Y=R4 CR=5\n"
         "  G1 X=R2 Y=R4+1 Z=0\n"
         "ENDWHILE\n"
         "M30\n";
}

void check(const ncoffset::RunResult& r, benchmark::State& state) {
  if (r.status != ncoffset::RunResult::Status::Ok) {
    std::string why = r.alarm ? "alarm " + std::to_string(r.alarm->number) + " line " +
                                    std::to_string(r.alarm->where.line) + ": " + r.alarm->text
                              : r.file_error;
    state.SkipWithError(why.c_str());
  }
}

// Plain G1 blocks: lexer + parser + interpreter, path discarded.
void BM_PlainG1(benchmark::State& state) {
  const long blocks = state.range(0);
  const std::string text = plainG1Program(blocks);
  long long segments = 0;
  for (auto _ : state) {
    ncoffset::Channel channel;
    NullSink sink;
    check(channel.runText("BENCH.MPF", text, sink), state);
    segments = sink.segments;
    benchmark::DoNotOptimize(segments);
  }
  state.SetItemsProcessed(state.iterations() * (blocks + 1));
  state.SetBytesProcessed(state.iterations() * static_cast<int64_t>(text.size()));
  state.counters["segments"] = static_cast<double>(segments);
}

// WHILE loop with expressions, R parameters and arcs, path discarded.
void BM_LoopArcsExpr(benchmark::State& state) {
  const long iterations = state.range(0);
  const std::string text = loopProgram(iterations);
  long long segments = 0;
  for (auto _ : state) {
    ncoffset::Channel channel;
    NullSink sink;
    check(channel.runText("LOOP.MPF", text, sink), state);
    segments = sink.segments;
    benchmark::DoNotOptimize(segments);
  }
  state.SetItemsProcessed(state.iterations() * iterations * kLoopLinesPerIteration);
  state.counters["segments"] = static_cast<double>(segments);
}

// A radius-compensation program: laps of a 100 x 60 rectangle with rounded corners (lines and
// G3 arcs alternating), G41 with a 4 mm tool, CDON (bottleneck detection over MD20240 = 3
// blocks), G450; end to end to CSV. Its points are whole millimetres, and so is most of the
// output; `decimals` shifts the contour and the tool by fractions of a millimetre so that every
// output number has decimals (the number writer's slower path).
std::string trcProgram(long blocks, bool decimals = false) {
  std::string t = decimals
                      ? "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=4.0625\nT1 D1\nG17 G90 G0 X-20 Y-20 Z0.5\n"
                        "G41 CDON G1 X10.375 Y0.125 F1000.5\n"
                      : "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=4\nT1 D1\nG17 G90 G0 X-20 Y-20 Z0\n"
                        "G41 CDON G1 X10 Y0 F1000\n";
  const char* lap[] = {"G1 X90 Y0\n",  "G3 X100 Y10 CR=10\n", "G1 X100 Y50\n", "G3 X90 Y60 CR=10\n",
                       "G1 X10 Y60\n", "G3 X0 Y50 CR=10\n",   "G1 X0 Y10\n",   "G3 X10 Y0 CR=10\n"};
  const char* lap_decimals[] = {"G1 X90.375 Y0.125\n",   "G3 X100.375 Y10.125 CR=10\n",
                                "G1 X100.375 Y50.125\n", "G3 X90.375 Y60.125 CR=10\n",
                                "G1 X10.375 Y60.125\n",  "G3 X0.375 Y50.125 CR=10\n",
                                "G1 X0.375 Y10.125\n",   "G3 X10.375 Y0.125 CR=10\n"};
  for (long i = 0; i < blocks; ++i) t += (decimals ? lap_decimals : lap)[i % 8];
  t += decimals ? "G1 X10.375 Y0.125\nG40 X-20 Y-20\nM30\n" : "G1 X10 Y0\nG40 X-20 Y-20\nM30\n";
  return t;
}

// Runs `text` end to end through the CLI's CSV writer into /dev/null.
void runToCsv(benchmark::State& state, const std::string& text, long items) {
  std::FILE* devnull = std::fopen("/dev/null", "wb");
  if (!devnull) throw std::runtime_error("cannot open /dev/null");
  for (auto _ : state) {
    ncoffset::Channel channel;
    ncoffset::out::CsvWriter csv(devnull);
    check(channel.runText("BENCH.MPF", text, csv), state);
  }
  std::fclose(devnull);
  state.SetItemsProcessed(state.iterations() * items);
}

void BM_TrcContourCsv(benchmark::State& state) {
  runToCsv(state, trcProgram(state.range(0)), state.range(0));
}

// The same contour shifted by fractions of a millimetre: no whole numbers in the output.
void BM_TrcContourCsvDecimals(benchmark::State& state) {
  runToCsv(state, trcProgram(state.range(0), true), state.range(0));
}

// End to end: plain G1 blocks written as CSV (the CLI's writer) to /dev/null.
void BM_PlainG1Csv(benchmark::State& state) {
  runToCsv(state, plainG1Program(state.range(0)), state.range(0) + 1);
}

}  // namespace

// Sizes: 1,000,000 plain blocks and 200,000 loop iterations, or NCOFFSET_BENCH_BLOCKS blocks
// (loop: a fifth of it) when that variable is set, e.g. to profile a shorter run:
//   NCOFFSET_BENCH_BLOCKS=100000 valgrind --tool=callgrind build/bench/ncoffset_bench
//       --benchmark_filter='BM_PlainG1/'
int main(int argc, char** argv) {
  long blocks = 1000000;
  if (const char* env = std::getenv("NCOFFSET_BENCH_BLOCKS")) blocks = std::atol(env);
  if (blocks < 5) blocks = 5;
  benchmark::RegisterBenchmark("BM_PlainG1", BM_PlainG1)
      ->Arg(blocks)
      ->Unit(benchmark::kMillisecond)
      ->Iterations(5);
  benchmark::RegisterBenchmark("BM_LoopArcsExpr", BM_LoopArcsExpr)
      ->Arg(blocks / 5)
      ->Unit(benchmark::kMillisecond)
      ->Iterations(3);
  benchmark::RegisterBenchmark("BM_PlainG1Csv", BM_PlainG1Csv)
      ->Arg(blocks)
      ->Unit(benchmark::kMillisecond)
      ->Iterations(5);
  benchmark::RegisterBenchmark("BM_TrcContourCsv", BM_TrcContourCsv)
      ->Arg(blocks)
      ->Unit(benchmark::kMillisecond)
      ->Iterations(3);
  benchmark::RegisterBenchmark("BM_TrcContourCsvDecimals", BM_TrcContourCsvDecimals)
      ->Arg(blocks)
      ->Unit(benchmark::kMillisecond)
      ->Iterations(3);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
