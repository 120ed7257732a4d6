// Property test of tool radius compensation (issue: "every point of the compensated path is at
// distance >= R from the programmed contour, and exactly R on every compensated element"):
// random star-shaped closed polygons in G17, G41 or G42, G450 or G451, R = 2; every sampled
// point of every compensated row away from the approach and the retraction lies at distance R
// from the programmed contour within 1e-7 mm with G450, and at least R with G451 (whose outside
// corners are the farther intersection points).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <random>
#include <sstream>
#include <vector>

#include "ncoffset/channel.hpp"

namespace ncoffset {
namespace {

struct Collect final : PathSink {
  std::vector<Segment> rows;
  void segment(const Segment& s) override { rows.push_back(s); }
  void finish(const Alarm*) override {}
};

struct P2 {
  double x, y;
};

double segmentDistance(P2 p, P2 a, P2 b) {
  double dx = b.x - a.x, dy = b.y - a.y;
  double t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy);
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

TEST(CompensationProperty, RandomClosedContoursStayAtTheRadius) {
  std::mt19937 rng(20261123);
  std::uniform_real_distribution<double> unit(0, 1);
  const double r = 2;
  int checked = 0, contours = 0;
  for (int iter = 0; iter < 200; ++iter) {
    int n = 5 + static_cast<int>(unit(rng) * 6);
    // Stratified angles: one vertex per sector, so no two vertices crowd together.
    std::vector<double> ang;
    for (int i = 0; i < n; ++i) ang.push_back((i + 0.2 + 0.6 * unit(rng)) / n * 2 * M_PI);
    std::vector<P2> poly;
    for (double a : ang) {
      double rad = 30 + unit(rng) * 30;
      poly.push_back({std::round(rad * std::cos(a) * 1000) / 1000, std::round(rad * std::sin(a) * 1000) / 1000});
    }
    const bool left = unit(rng) < 0.5, intersection = unit(rng) < 0.5;
    std::ostringstream prog;
    // MD20230 = 0: G450 puts a circle at every outside corner, however flat.
    prog << "$MC_CUTCOM_CURVE_INSERT_LIMIT=0\n$TC_DP1[1,1]=120\n$TC_DP6[1,1]=" << r
         << "\nT1 D1\nG17 G90 G0 X0 Y0 Z0\n"
         << (intersection ? "G451\n" : "G450\n") << (left ? "G41" : "G42") << " G1 X" << poly[0].x
         << " Y" << poly[0].y << " F100\n";
    for (int i = 1; i <= n + 1; ++i) {
      const P2& v = poly[static_cast<size_t>(i % n)];
      prog << "X" << v.x << " Y" << v.y << "\n";
    }
    prog << "G40 X0 Y0\nM30\n";
    Channel ch;
    Collect out;
    RunResult res = ch.runText("P.MPF", prog.str(), out);
    if (res.status != RunResult::Status::Ok) {  // an alarm (e.g. a bottleneck) is allowed
      if (std::getenv("NCOFFSET_DEBUG_PROPERTY")) std::fprintf(stderr, "%s\n", res.alarm->text.c_str());
      continue;
    }
    ++contours;
    ASSERT_GE(out.rows.size(), 3u);
    // The contour blocks are lines 8 .. 8+n (the polygon and its first edge once more). The
    // first and last of them touch the approach and the retraction, whose NORM points may lie
    // nearer than R to the neighbouring edge (the control does the same); every row of the
    // blocks in between is fixed by its corners on both sides.
    for (size_t k = 0; k < out.rows.size(); ++k) {
      const Segment& s = out.rows[k];
      if (s.line < 9 || s.line > 7 + n) continue;
      for (int j = 0; j <= 20; ++j) {
        double u = j / 20.0;
        P2 p;
        if (s.motion == Motion::G1 || s.motion == Motion::G0) {
          p = {s.start.x + u * (s.end.x - s.start.x), s.start.y + u * (s.end.y - s.start.y)};
        } else {
          double a0 = std::atan2(s.start.y - s.centre.y, s.start.x - s.centre.x);
          double a1 = std::atan2(s.end.y - s.centre.y, s.end.x - s.centre.x);
          double sweep = s.motion == Motion::G3 ? a1 - a0 : a0 - a1;
          while (sweep < 0) sweep += 2 * M_PI;
          double a = a0 + (s.motion == Motion::G3 ? 1 : -1) * u * sweep;
          double rad = std::hypot(s.start.x - s.centre.x, s.start.y - s.centre.y);
          p = {s.centre.x + rad * std::cos(a), s.centre.y + rad * std::sin(a)};
        }
        double d = 1e300;
        for (int e = 0; e < n; ++e)
          d = std::min(d, segmentDistance(p, poly[static_cast<size_t>(e)], poly[static_cast<size_t>((e + 1) % n)]));
        // G450: exactly R everywhere (equidistants and circles about the corners). G451: the
        // intersections of extended equidistants lie farther out at outside corners: >= R.
        if (intersection)
          EXPECT_GE(d, r - 1e-7) << "contour " << iter << " row " << k << " (line " << s.line << ")\n"
                                 << prog.str();
        else
          EXPECT_NEAR(d, r, 1e-7) << "contour " << iter << " row " << k << " (line " << s.line << ")\n"
                                  << prog.str();
        ++checked;
      }
    }
  }
  EXPECT_GT(contours, 150);
  EXPECT_GT(checked, 20000);
}

}  // namespace
}  // namespace ncoffset
