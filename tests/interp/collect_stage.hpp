// The motion builder's tests: the stage behind it (keeps what it is given, feeds back `next`)
// and a builder with what it reads.
#pragma once

#include <string>
#include <vector>

#include "core/stage.hpp"
#include "interp/motion_builder.hpp"

namespace ncoffset::interp {

class Collect final : public core::Stage {
 public:
  std::vector<core::MotionBlock> blocks;
  core::Feedback next;
  core::Feedback motion(const core::MotionBlock& m) override {
    blocks.push_back(m);
    return next;
  }
  void warning(const core::MotionBlock&, int, const std::string&) override {}
};

// A motion builder with what it reads, and the stage behind it.
struct BuilderRig {
  Collect stage;
  MachineData data;
  FrameState frames;
  tool::ToolSelection tools{32000};
  MotionBuilder builder{stage, data, frames, tools};
};

}  // namespace ncoffset::interp
