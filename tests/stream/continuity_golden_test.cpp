// A continuous machine path (docs/tool-offsets.md section 5, docs/output-formats.md "Start
// position"): every golden program runs in MCS and in WCS, and
// * in MCS the first segment starts at the start position and every other one where the one
//   before ended (the carrier does not jump at a tool change, a length take-up or a frame change);
// * in WCS every segment is the same motion as in MCS, its start the MCS start expressed with the
//   segment's frame and tool: the chord has the MCS chord's length (frames here do not scale);
//   where the WCS start is not the previous WCS end, the frame or the tool offset changed, which
//   shows as a change of the difference between the MCS and the WCS point.
// Within geom::tol::kPoint, the tolerance of a point (src/geom/tolerance.hpp).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "geom/tolerance.hpp"
#include "ncoffset/channel.hpp"
#include "support/golden_cases.hpp"

namespace ncoffset {
namespace {

using golden::GoldenCase;

class Collect final : public PathSink {
 public:
  std::vector<Segment> segments;
  void segment(const Segment& s) override { segments.push_back(s); }
  void finish(const Alarm*) override {}
};

bool near(const Vec3& a, const Vec3& b) {
  const double scale = std::max({1.0, std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)});
  return norm(a - b) <= geom::tol::kPoint * scale;
}

std::string text(const Vec3& v) {
  return fmt::format("({}, {}, {})", v.x, v.y, v.z);
}

// The segments of the case in `coords`; false if an init file fails.
bool run(const GoldenCase& c, CoordSystem coords, const std::optional<Vec3>& start,
         std::vector<Segment>& out) {
  RunOptions o = c.options;
  o.coords = coords;
  o.start = start;
  Channel ch(o);
  if (!golden::runGoldenInits(ch, c)) return false;
  Collect sink;
  ch.runText(c.program.filename().string(), golden::readAll(c.program), sink,
             c.program.parent_path());
  out = std::move(sink.segments);
  return true;
}

void expectContinuous(const std::vector<Segment>& s, const Vec3& start, const char* coords) {
  if (s.empty()) return;
  EXPECT_TRUE(near(s[0].start, start))
      << coords << ": the first segment (line " << s[0].line << ") starts at " << text(s[0].start)
      << ", not at the start position " << text(start);
  for (size_t i = 1; i < s.size(); ++i)
    EXPECT_TRUE(near(s[i].start, s[i - 1].end))
        << coords << ": segment " << i << " (line " << s[i].line << ") starts at "
        << text(s[i].start) << ", the one before ended at " << text(s[i - 1].end);
}

bool scales(const GoldenCase& c) {
  const std::string t = golden::readAll(c.program);
  return t.find("SCALE") != std::string::npos || t.find(",SC") != std::string::npos;
}

void expectSameMotion(const GoldenCase& c, const std::vector<Segment>& mcs,
                      const std::vector<Segment>& wcs) {
  ASSERT_EQ(mcs.size(), wcs.size());
  const bool check_lengths = !scales(c);
  for (size_t i = 0; i < mcs.size(); ++i) {
    const Segment &m = mcs[i], &w = wcs[i];
    if (check_lengths) {
      EXPECT_NEAR(norm(m.end - m.start), norm(w.end - w.start),
                  geom::tol::kPoint * std::max(1.0, norm(m.end)))
          << "segment " << i << " (line " << m.line << "): the WCS chord is not the MCS chord";
    }
    if (i == 0 || near(w.start, wcs[i - 1].end)) continue;
    // A WCS jump: the map between the systems changed between the two segments.
    const Vec3 before = mcs[i - 1].end - wcs[i - 1].end, now = m.start - w.start;
    EXPECT_FALSE(near(before, now))
        << "segment " << i << " (line " << m.line << ") jumps in WCS from " << text(wcs[i - 1].end)
        << " to " << text(w.start) << " without a frame or tool change";
  }
}

// One test over all cases (a ctest entry per case would cost a process start each).
TEST(Continuity, SegmentsStartWhereThePreviousEndedInEveryGoldenProgram) {
  const std::vector<GoldenCase> cases = golden::discoverGoldenCases(NCOFFSET_PROGRAMS);
  ASSERT_GT(cases.size(), 500u);
  for (const GoldenCase& c : cases) {
    SCOPED_TRACE(c.name);
    std::vector<Segment> mcs, wcs, shifted;
    if (!run(c, CoordSystem::MCS, std::nullopt, mcs)) continue;  // an init file fails
    expectContinuous(mcs, Vec3{}, "MCS");
    ASSERT_TRUE(run(c, CoordSystem::WCS, std::nullopt, wcs));
    expectSameMotion(c, mcs, wcs);
    // From another start position (where the first blocks leave axes unprogrammed, they stay
    // there).
    const Vec3 start{-250, 125.5, 480};
    ASSERT_TRUE(run(c, CoordSystem::MCS, start, shifted));
    expectContinuous(shifted, start, "MCS from --start");
  }
}

}  // namespace
}  // namespace ncoffset
