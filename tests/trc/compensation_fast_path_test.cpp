// Radius compensation's fast paths (docs/performance.md §36) against their general twins: every
// program of tests/programs/trc and the trc_ ones of tests/programs/bad, and random contours of
// lines and arcs (tests/support/random_contour.hpp: G17/G18, G41/G42, G450/G451, CDON/CDOF), run
// once with the fast paths and once with RadiusCompensation::useGeneralPaths(true); the rows must
// be the same bit for bit, the alarms the same.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "ncoffset/channel.hpp"
#include "support/random_contour.hpp"
#include "trc/radius_compensation.hpp"

namespace ncoffset::trc {
namespace {

namespace fs = std::filesystem;

struct Rows final : PathSink {
  std::vector<Segment> rows;
  void segment(const Segment& s) override { rows.push_back(s); }
  void finish(const Alarm*) override {}
};

bool sameBits(const Vec3& a, const Vec3& b) {
  return std::memcmp(&a.x, &b.x, sizeof a.x) == 0 && std::memcmp(&a.y, &b.y, sizeof a.y) == 0 &&
         std::memcmp(&a.z, &b.z, sizeof a.z) == 0;
}

bool sameRow(const Segment& a, const Segment& b) {
  return a.line == b.line && a.file == b.file && a.motion == b.motion &&
         sameBits(a.start, b.start) && sameBits(a.end, b.end) && sameBits(a.centre, b.centre) &&
         sameBits(a.normal, b.normal) && a.turns == b.turns &&
         std::memcmp(&a.feed, &b.feed, sizeof a.feed) == 0 && a.has_feed == b.has_feed;
}

struct Outcome {
  Rows out;
  RunResult result;
};

// One run: the init files, then the program (a file, or `text` when given).
Outcome run(bool general, const std::vector<fs::path>& inits, const fs::path& file,
            const std::string& text) {
  RadiusCompensation::useGeneralPaths(general);
  Outcome o;
  Channel ch;
  Rows init_rows;
  for (const fs::path& i : inits) ch.runInit(i, init_rows);
  o.result = text.empty() ? ch.runProgram(file, o.out) : ch.runText("P.MPF", text, o.out);
  RadiusCompensation::useGeneralPaths(false);
  return o;
}

// Both paths on one program; the number of rows compared.
size_t expectSame(const std::vector<fs::path>& inits, const fs::path& file,
                  const std::string& text = {}) {
  const Outcome fast = run(false, inits, file, text), general = run(true, inits, file, text);
  EXPECT_EQ(fast.result.status, general.result.status);
  if (fast.result.alarm && general.result.alarm) {
    EXPECT_EQ(fast.result.alarm->number, general.result.alarm->number);
    EXPECT_EQ(fast.result.alarm->where.line, general.result.alarm->where.line);
    EXPECT_EQ(fast.result.alarm->text, general.result.alarm->text);
  }
  EXPECT_EQ(fast.out.rows.size(), general.out.rows.size());
  const size_t n = std::min(fast.out.rows.size(), general.out.rows.size());
  for (size_t i = 0; i < n; ++i)
    EXPECT_TRUE(sameRow(fast.out.rows[i], general.out.rows[i])) << "row " << i;
  return n;
}

// The --init files a golden case names in its `# args:` line.
std::vector<fs::path> initsOf(const fs::path& program) {
  std::vector<fs::path> inits;
  std::ifstream in(fs::path(program).replace_extension(".expected"));
  std::string line;
  if (!std::getline(in, line) || line.rfind("# args:", 0) != 0) return inits;
  std::istringstream words(line.substr(7));
  for (std::string w; words >> w;)
    if (w == "--init" && words >> w) inits.push_back(program.parent_path() / w);
  return inits;
}

TEST(CompensationFastPath, GoldenProgramsAsTheGeneralPaths) {
  const fs::path programs = NCOFFSET_PROGRAMS;
  size_t cases = 0, rows = 0;
  for (const char* dir : {"trc", "bad"}) {
    for (const auto& e : fs::directory_iterator(programs / dir)) {
      // (Of the bad programs the compensation's: the others stop before it, some only after
      // seconds of their loops.)
      const bool trc = dir[0] == 't' || e.path().stem().string().rfind("trc_", 0) == 0;
      if (e.path().extension() != ".MPF" || !trc) continue;
      SCOPED_TRACE(e.path().string());
      rows += expectSame(initsOf(e.path()), e.path());
      ++cases;
    }
  }
  EXPECT_GT(cases, 80u);
  EXPECT_GT(rows, 500u);
}

TEST(CompensationFastPath, RandomContoursAsTheGeneralPaths) {
  size_t rows = 0;
  for (int i = 0; i < 300; ++i) {
    const test::RandomContour c = test::randomContour(36, i, i % 3 == 0 ? 3 : 6, {});
    SCOPED_TRACE(i);
    rows += expectSame({}, {}, test::programText(c));
  }
  EXPECT_GT(rows, 3000u);
}

}  // namespace
}  // namespace ncoffset::trc
