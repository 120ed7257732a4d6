// The motion builder's short way (MotionBuilder::buildPlain and buildBlock, src/interp/
// motion_plain.cpp, docs/performance.md section 35) against its general twin build(): random
// sequences of blocks under random modal states, tools and frames, built by both on two builders
// side by side, must give the same motion blocks field by field (doubles bit for bit), the same
// positions, the same return values and the same alarms. The fast builder is told what the
// interpreter tells it (settingsMayChange) only where the interpreter would: after a change that
// a plain line cannot make; changes a plain line makes (G0..G3, F, G40..G42) are not announced.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "interp/collect_stage.hpp"
#include "interp/motion_builder.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {
namespace {

using Side = BuilderRig;

bool same(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
bool same(const Vec3& a, const Vec3& b) {
  return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}

void expectSameBlock(const core::MotionBlock& a, const core::MotionBlock& b) {
  EXPECT_EQ(a.motion, b.motion);
  EXPECT_EQ(a.has_tip, b.has_tip);
  EXPECT_EQ(a.tip_at, b.tip_at);
  EXPECT_TRUE(same(a.start, b.start));
  EXPECT_TRUE(same(a.end, b.end));
  EXPECT_TRUE(same(a.centre, b.centre));
  EXPECT_EQ(a.applicate, b.applicate);
  EXPECT_EQ(a.plane, b.plane);
  EXPECT_EQ(a.trc.mode, b.trc.mode);
  EXPECT_TRUE(same(a.trc.radius, b.trc.radius));
  EXPECT_EQ(a.trc.approach, b.trc.approach);
  EXPECT_EQ(a.trc.corner, b.trc.corner);
  EXPECT_EQ(a.trc.collision, b.trc.collision);
  EXPECT_TRUE(same(a.trc.disc, b.trc.disc));
  EXPECT_EQ(a.trc.strategy, b.trc.strategy);
  EXPECT_EQ(a.trc.frame_plane, b.trc.frame_plane);
  EXPECT_EQ(a.trc.constant, b.trc.constant);
  EXPECT_TRUE(same(a.trc.corner_limit, b.trc.corner_limit));
  EXPECT_TRUE(same(a.trc.curve_insert_limit, b.trc.curve_insert_limit));
  EXPECT_EQ(a.trc.max_dummy_blocks, b.trc.max_dummy_blocks);
  EXPECT_EQ(a.trc.check_blocks, b.trc.check_blocks);
  EXPECT_EQ(a.turns, b.turns);
  EXPECT_EQ(a.frame.state(), b.frame.state());
  EXPECT_EQ(a.frame.isIdentity(), b.frame.isIdentity());
  EXPECT_TRUE(same(a.tool_offset, b.tool_offset));
  if (a.has_tip) {
    EXPECT_TRUE(same(a.tip, b.tip));
  }
  EXPECT_TRUE(same(a.feed, b.feed));
  EXPECT_EQ(a.feed_unit, b.feed_unit);
  EXPECT_EQ(a.has_feed, b.has_feed);
  EXPECT_TRUE(same(a.lead_change, b.lead_change));
  EXPECT_EQ(a.line, b.line);
  EXPECT_EQ(a.file, b.file);
  EXPECT_EQ(a.seq, b.seq);
  EXPECT_EQ(a.sar.kind, b.sar.kind);
}

// A small deterministic generator (the same sequences on every run).
struct Random {
  unsigned seed;
  unsigned operator()(unsigned n) {
    seed = seed * 1103515245u + 12345u;
    return (seed >> 16) % n;
  }
};

// One random change of what a block is built under, on both sides; true when a plain line could
// not have made it (the interpreter then calls settingsMayChange).
bool change(Random& next, ModalState& modal, Side& a, Side& b) {
  const double values[] = {0, 1, -2.5, 4, 0.125, 10};
  auto both = [&](auto f) {
    f(a);
    f(b);
  };
  switch (next(14)) {
    case 0:
      modal.motion = static_cast<Motion>(next(4));  // G0..G3: a plain line's word
      return false;
    case 1:
      modal.feed = next(8) == 0 ? 0.0 : 100.0 + next(5);  // F: a plain line's word
      return false;
    case 2:
      modal.trc = static_cast<core::TrcMode>(next(3));  // G40..G42: a plain line's word
      return false;
    case 3:
      modal.offn = values[next(6)];
      modal.disc = values[next(6)];
      modal.cut_constant = next(2);
      modal.corner = next(2) ? CornerMode::Intersection : CornerMode::TransitionCircle;
      break;
    case 4:
      modal.plane = static_cast<Plane>(next(3));
      break;
    case 5:
      modal.incremental = next(2);
      break;
    case 6:
      modal.units = next(3) == 0 ? Units::G70 : Units::G71;
      modal.feed_unit = next(2) ? FeedUnit::MmPerRev : FeedUnit::MmPerMin;
      break;
    case 7: {
      const int axis = static_cast<int>(next(3));
      modal.diam_abs[axis] = next(2) ? 0.5 : 1;
      modal.diam_inc[axis] = next(2) ? 0.5 : 1;
      break;
    }
    case 8:
    case 9: {  // a tool: T/D with a length, a radius and sometimes a cutting edge position
      const std::vector<lang::Value> idx{lang::Value::integer(1),
                                         lang::Value::integer(1 + next(2))};
      const double length = values[next(6)] * 10, radius = values[next(6)];
      const int type = next(3) == 0 ? 500 : 120, position = static_cast<int>(next(9));
      const tool::ToolWords words{1, static_cast<int>(idx[1].num), false};
      both([&](Side& s) {
        s.tools.write("$TC_DP1", idx, true, lang::Value::real(type));
        s.tools.write("$TC_DP2", idx, true, lang::Value::real(position));
        s.tools.write("$TC_DP3", idx, true, lang::Value::real(length));
        s.tools.write("$TC_DP4", idx, true, lang::Value::real(length / 2));
        s.tools.write("$TC_DP6", idx, true, lang::Value::real(radius));
        s.tools.execute(words, true, {});
      });
      break;
    }
    case 10: {  // a frame: a translation, a mirror, or none again
      const unsigned kind = next(3);
      const double t = values[next(6)];
      both([&](Side& s) {
        s.frames.programmable() = {};
        if (kind == 1) s.frames.programmable().coarse = {t, 0, 0};
        if (kind == 2) s.frames.programmable().mirror = {false, true, false};
        s.frames.update();
      });
      break;
    }
    case 11:
      modal.trc_strategy = static_cast<core::TrcStrategy>(next(3));
      modal.collision = next(2) ? CollisionCheck::Cdon : CollisionCheck::Cdof;
      break;
    default:  // G33 needs a line of other words
      modal.motion = next(3) ? Motion::G1 : static_cast<Motion>(next(5));
      return isThreadMotion(modal.motion);
  }
  return true;
}

// Random words of a block: plain ones mostly, some the short way does not take.
BlockWords words(Random& next, bool arc) {
  const double values[] = {0, 10, -2.5, 30.125, 100, 7, 1e10};
  BlockWords w;
  for (int i = 0; i < 3; ++i)
    if (next(2)) {
      w.axis[i] = true;
      w.axis_value[i] = values[next(next(20) == 0 ? 7 : 6)];
    }
  if (arc ? next(8) != 0 : next(10) == 0) w.cr = next(4) ? 200.0 : -150.0;
  if (next(12) == 0) {
    w.centre[0] = w.centre[1] = true;
    w.centre_value[0] = 5;
    w.centre_value[1] = -5;
  }
  if (next(15) == 0) w.axis_mode[next(3)] = next(2) ? lang::AxisMode::AC : lang::AxisMode::IC;
  if (next(20) == 0) w.suppress_frames = 53;
  if (next(25) == 0) w.turn = 1;
  return w;
}

struct Outcome {
  bool moved = false;
  std::optional<AlarmNumber> alarm;
  std::string text;
};

template <typename F>
Outcome attempt(F build) {
  Outcome o;
  try {
    o.moved = build();
  } catch (const AlarmError& e) {
    o.alarm = e.alarm();
    o.text = e.what();
  }
  return o;
}

// One block built by side a's short way (`plain`: buildPlain, else buildBlock with its choice)
// and by side b's build(), compared: the same alarm and text, else the same return value, the
// same motion block (doubles bit for bit) and the same positions. `out`: side a's outcome.
void buildBoth(Side& a, Side& b, const BlockWords& w, const ModalState& modal,
               const BlockContext& at, bool plain, Outcome& out) {
  out = attempt([&] {
    return plain ? a.builder.buildPlain(w, modal, at) : a.builder.buildBlock(w, modal, at);
  });
  const Outcome fb = attempt([&] { return b.builder.build(w, modal, at); });
  ASSERT_EQ(out.alarm, fb.alarm);
  EXPECT_EQ(out.text, fb.text);
  if (out.alarm) return;
  EXPECT_EQ(out.moved, fb.moved);
  ASSERT_EQ(a.stage.blocks.size(), b.stage.blocks.size());
  if (out.moved) expectSameBlock(a.stage.blocks.back(), b.stage.blocks.back());
  EXPECT_TRUE(same(a.builder.wcs(), b.builder.wcs()));
  EXPECT_TRUE(same(a.builder.bcs(), b.builder.bcs()));
  EXPECT_TRUE(same(a.builder.mcs(), b.builder.mcs()));
}

TEST(MotionFastPath, PlainBlocksBuildAsTheGeneralPath) {
  Random next{2026};
  int blocks = 0, alarms = 0, arcs = 0;
  for (int program = 0; program < 800; ++program) {
    Side a, b;  // a: buildBlock/buildPlain with its kept settings, b: build
    ModalState modal;
    modal.motion = Motion::G1;
    modal.feed = 100;
    for (int k = 0; k < 40; ++k) {
      while (next(3) == 0)
        if (change(next, modal, a, b)) a.builder.settingsMayChange();
      const BlockWords w = words(next, modal.motion == Motion::G2 || modal.motion == Motion::G3);
      const BlockContext at{k + 1, 0, 100, Motion::G1};
      SCOPED_TRACE(testing::Message() << "program " << program << " block " << k);
      const bool plain_words =
          w.suppress_frames == 0 && w.axis_mode[0] == lang::AxisMode::Default &&
          w.axis_mode[1] == lang::AxisMode::Default && w.axis_mode[2] == lang::AxisMode::Default;
      Outcome o;
      buildBoth(a, b, w, modal, at, plain_words && next(2), o);
      if (testing::Test::HasFatalFailure()) return;
      if (o.alarm) {
        ++alarms;
        break;  // an alarm ends the run
      }
      if (o.moved) {
        ++blocks;
        arcs += a.stage.blocks.back().motion == Motion::G2 ||
                a.stage.blocks.back().motion == Motion::G3;
      }
    }
  }
  // Enough of each kind to compare something.
  EXPECT_GT(blocks, 10000);
  EXPECT_GT(arcs, 300);
  EXPECT_GT(alarms, 300);
  std::printf("%d blocks, %d arcs, %d alarms\n", blocks, arcs, alarms);
}

// Circles by their centre (MotionBuilder::centreArc, docs/performance.md §53): I, J, K from the
// start point in every plane, the end on the circle to 3 decimals, just off it or far off, the
// full circle (no end point in the plane), a helix, TURN=, the applicate's parameter, =AC(..) and
// =IC(..) centres, CR= or AR= beside them, under the random settings of change() (inch and
// diameter programming put most ends off the circle: alarms, compared too).
TEST(MotionFastPath, CirclesByCentreBuildAsTheGeneralPath) {
  const double offsets[] = {0, 5, -12.5, 30.125, 7.0625, -0.5};
  Random next{53};
  int centre_arcs = 0, alarms = 0;
  for (int program = 0; program < 600; ++program) {
    Side a, b;
    ModalState modal;
    modal.feed = 100;
    for (int k = 0; k < 30; ++k) {
      while (next(4) == 0)
        if (change(next, modal, a, b)) a.builder.settingsMayChange();
      if (modal.motion != Motion::G2 && modal.motion != Motion::G3)
        modal.motion = next(2) ? Motion::G2 : Motion::G3;  // a plain line's word
      const PlaneAxes pa = planeAxes(modal.plane);
      const int ax[2] = {pa.abscissa, pa.ordinate};
      // The words in the program's units: I, J, K in inch under G70 (toMm), an end point also
      // by its diameter factor (plainTarget).
      const double unit = modal.units == Units::G70 || modal.units == Units::G700 ? 25.4 : 1.0;
      const double* factor = modal.incremental ? modal.diam_inc : modal.diam_abs;
      const Vec3 start = a.builder.wcs();
      BlockWords w;
      Vec3 centre = start;
      for (int i : ax)
        if (next(10) != 0) {
          w.centre[i] = true;
          w.centre_value[i] = offsets[next(20) == 0 ? 0 : 1 + next(5)];
          centre[i] += w.centre_value[i] * unit;
        }
      if (next(150) == 0) w.centre[pa.applicate] = true;
      if (next(20) == 0)
        w.centre_mode[ax[next(2)]] = next(4) ? lang::AxisMode::IC : lang::AxisMode::AC;
      const double radius = std::hypot(centre[ax[0]] - start[ax[0]], centre[ax[1]] - start[ax[1]]);
      const double angle = next(360) * 3.14159265358979 / 180, off = next(40) == 0 ? 0.05 : 0;
      // 0: the full circle; 1: the abscissa alone, mirrored about the centre; else both.
      const unsigned ends = next(6);
      for (int n = 0; n < 2; ++n) {
        if (ends == 0 || (ends == 1 && n == 1)) continue;
        const double on = ends == 1 ? 2 * centre[ax[0]] - start[ax[0]] + off
                                    : centre[ax[n]] + (radius + off) * (n == 0 ? std::cos(angle)
                                                                               : std::sin(angle));
        const double end = std::round(on * 1000) / 1000;
        w.axis[ax[n]] = true;
        w.axis_value[ax[n]] =
            ((modal.incremental ? end - start[ax[n]] : end) / unit) / factor[ax[n]];
      }
      if (next(4) == 0) {  // a helix
        w.axis[pa.applicate] = true;
        w.axis_value[pa.applicate] = offsets[next(6)];
      }
      if (next(20) == 0) w.turn = 2;
      if (next(60) == 0) w.cr = 10.0;
      if (next(60) == 0) w.ar = 90.0;
      const BlockContext at{k + 1, 0, 100, Motion::G1};
      SCOPED_TRACE(testing::Message() << "program " << program << " block " << k);
      Outcome o;
      buildBoth(a, b, w, modal, at, next(2) != 0, o);
      if (testing::Test::HasFatalFailure()) return;
      if (o.alarm) {
        ++alarms;
        break;  // an alarm ends the run
      }
      centre_arcs += o.moved && !w.cr && !w.ar;
    }
  }
  EXPECT_GT(centre_arcs, 4000);
  EXPECT_GT(alarms, 300);
  std::printf("%d circles by their centre, %d alarms\n", centre_arcs, alarms);
}

}  // namespace
}  // namespace ncoffset::interp
