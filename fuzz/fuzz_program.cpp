// Fuzz target: the whole pipeline. The input is a tool/setting-data init file and a part
// program separated by a line "%MPF"; without it the whole input is the program. Limits are
// small so that every input ends quickly (a hang is a finding).
#include <cstddef>
#include <cstdint>
#include <string>

#include "ncoffset/channel.hpp"

namespace {
class NullSink final : public ncoffset::PathSink {
 public:
  void segment(const ncoffset::Segment& s) override { last_ = s.end.x + s.end.y + s.end.z; }
  void finish(const ncoffset::Alarm*) override {}
  double last_ = 0;
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string all(reinterpret_cast<const char*>(data), size);
  std::string init, program = all;
  size_t cut = all.find("%MPF\n");
  if (cut != std::string::npos) {
    init = all.substr(0, cut);
    program = all.substr(cut + 5);
  }
  ncoffset::RunOptions o;
  o.limits.max_blocks = 20000;
  o.limits.max_array_elements = 10000;
  o.limits.max_total_elements = 40000;
  o.limits.max_variables = 200;
  // The default line limit: the corpus holds blocks that fill it (operator chains of 65,536
  // characters, issue 14); fuzzing sessions use -max_len=8192 anyway.
  o.limits.max_line_length = ncoffset::Limits{}.max_line_length;
  ncoffset::Channel channel(o);
  NullSink sink;
  if (!init.empty()) {
    auto r = channel.runInitText("FUZZ.INI", init, sink);
    if (r.status != ncoffset::RunResult::Status::Ok) return 0;
  }
  channel.runText("FUZZ.MPF", program, sink, "/nonexistent-fuzz-dir");
  return 0;
}
