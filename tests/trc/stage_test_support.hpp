// Shared by the stage tests of src/trc: a Stage that collects what reaches it, and motion
// blocks built by hand in G17 (a = X, o = Y, applicate Z), so that a stage runs alone, without
// the interpreter and the Channel.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "core/stage.hpp"

namespace ncoffset::trc::test {

// The end of the chain: keeps every block and warning.
class Collect final : public core::Stage {
 public:
  std::vector<core::MotionBlock> blocks;
  std::vector<std::pair<int, int>> warnings;  // (line, number)
  int without_motion = 0;
  int flushed = 0;
  core::Feedback motion(const core::MotionBlock& m) override {
    blocks.push_back(m);
    return {};
  }
  void warning(const core::MotionBlock& at, int number, const std::string&) override {
    warnings.emplace_back(at.line, number);
  }
  void blockWithoutMotion() override { ++without_motion; }
  void flush() override { ++flushed; }
};

// Blocks of one program: each starts where the last one ended, with the settings `trc`.
struct Program {
  core::TrcSettings trc;
  Vec3 at;
  double feed = 100;
  core::MotionBlock line(int no, double x, double y, double z, Motion m = Motion::G1) {
    core::MotionBlock b;
    b.motion = m;
    b.start = at;
    b.end = {x, y, z};
    b.trc = trc;
    b.line = no;
    b.feed = m == Motion::G0 ? 0 : feed;
    b.has_feed = m != Motion::G0;
    at = b.end;
    return b;
  }
  core::MotionBlock line(int no, double x, double y, Motion m = Motion::G1) {
    return line(no, x, y, at.z, m);
  }
  // G2/G3 in G17 to (x, y) about (cx, cy).
  core::MotionBlock arc(int no, Motion m, double x, double y, double cx, double cy) {
    core::MotionBlock b = line(no, x, y);
    b.motion = m;
    b.centre = {cx, cy, b.start.z};
    b.applicate = 2;
    return b;
  }
};

inline core::TrcSettings g41(double r, CornerMode corner = CornerMode::TransitionCircle) {
  core::TrcSettings t;
  t.mode = core::TrcMode::Left;
  t.radius = r;
  t.corner = corner;
  return t;
}

inline void expectVec(const Vec3& v, double x, double y, double z, double tol = 1e-9) {
  EXPECT_NEAR(v.x, x, tol);
  EXPECT_NEAR(v.y, y, tol);
  EXPECT_NEAR(v.z, z, tol);
}

// One written element: its line, motion, end point and (arcs) centre, in the golden cases' terms.
inline void expectRow(const core::MotionBlock& b, int line, Motion m, double x, double y,
                      double z = 0) {
  EXPECT_EQ(b.line, line);
  EXPECT_EQ(b.motion, m) << "line " << line;
  expectVec(b.end, x, y, z);
}

}  // namespace ncoffset::trc::test
