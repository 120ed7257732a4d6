// Fuzz target: the init-file reader (TO_INI tool data, setting data, _UFR frames: NC syntax
// ending with M17), followed by a fixed program that selects a tool and moves.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "ncoffset/channel.hpp"

namespace {
class NullSink final : public ncoffset::PathSink {
 public:
  void segment(const ncoffset::Segment&) override {}
  void finish(const ncoffset::Alarm*) override {}
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string init(reinterpret_cast<const char*>(data), size);
  ncoffset::RunOptions o;
  o.limits.max_blocks = 20000;
  o.limits.max_line_length = 4096;
  ncoffset::Channel channel(o);
  NullSink sink;
  auto r = channel.runInitText("FUZZ.INI", init, sink);
  if (r.status != ncoffset::RunResult::Status::Ok) return 0;
  channel.runText("FUZZ.MPF",
                  "G17 G90 G54 G0 X0 Y0 Z0\nT1 D1\nG1 X10 Y5 Z2 F100\nG18 G2 Z5 X5 CR=5\n"
                  "DEF INT A[3]\nDEF REAL M[3,3]\nR1=LENTOAX(A,M)\nM30\n",
                  sink);
  std::ostringstream vars;
  channel.writeVariablesJson(vars);
  return 0;
}
