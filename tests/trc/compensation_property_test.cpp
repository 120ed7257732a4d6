// Property test of tool radius compensation (issue: "every point of the compensated path is at
// distance >= R from the programmed contour, and exactly R on every compensated element"):
// random star-shaped closed polygons in G17, G41 or G42, G450 or G451, R = 2; every sampled
// point of every compensated row away from the approach and the retraction lies at distance R
// from the programmed contour within 1e-7 mm with G450, and at least R with G451 (whose outside
// corners are the farther intersection points).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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

// The point at fraction u of an output row (line or arc in G17).
P2 samplePoint(const Segment& s, double u) {
  if (s.motion == Motion::G1 || s.motion == Motion::G0)
    return {s.start.x + u * (s.end.x - s.start.x), s.start.y + u * (s.end.y - s.start.y)};
  double a0 = std::atan2(s.start.y - s.centre.y, s.start.x - s.centre.x);
  double a1 = std::atan2(s.end.y - s.centre.y, s.end.x - s.centre.x);
  double sweep = s.motion == Motion::G3 ? a1 - a0 : a0 - a1;
  while (sweep < 0) sweep += 2 * M_PI;
  double a = a0 + (s.motion == Motion::G3 ? 1 : -1) * u * sweep;
  double rad = std::hypot(s.start.x - s.centre.x, s.start.y - s.centre.y);
  return {s.centre.x + rad * std::cos(a), s.centre.y + rad * std::sin(a)};
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
      poly.push_back({std::round(rad * std::cos(a) * 1000) / 1000,
                      std::round(rad * std::sin(a) * 1000) / 1000});
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
      if (std::getenv("NCOFFSET_DEBUG_PROPERTY"))
        std::fprintf(stderr, "%s\n", res.alarm->text.c_str());
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
        const P2 p = samplePoint(s, j / 20.0);
        double d = 1e300;
        for (int e = 0; e < n; ++e)
          d = std::min(d, segmentDistance(p, poly[static_cast<size_t>(e)],
                                          poly[static_cast<size_t>((e + 1) % n)]));
        // G450: exactly R everywhere (equidistants and circles about the corners). G451: the
        // intersections of extended equidistants lie farther out at outside corners: >= R.
        if (intersection)
          EXPECT_GE(d, r - 1e-7) << "contour " << iter << " row " << k << " (line " << s.line
                                 << ")\n"
                                 << prog.str();
        else
          EXPECT_NEAR(d, r, 1e-7) << "contour " << iter << " row " << k << " (line " << s.line
                                  << ")\n"
                                  << prog.str();
        ++checked;
      }
    }
  }
  EXPECT_GT(contours, 150);
  EXPECT_GT(checked, 20000);
}

// An edge of a random contour: a line, or an arc from a to b about c (ccw: G3).
struct Edge {
  P2 a, b;
  bool arc = false;
  P2 c{0, 0};
  bool ccw = false;
};

double edgeDistance(P2 p, const Edge& e) {
  if (!e.arc) return segmentDistance(p, e.a, e.b);
  const double rad = std::hypot(e.a.x - e.c.x, e.a.y - e.c.y);
  auto angle = [&](P2 q) { return std::atan2(q.y - e.c.y, q.x - e.c.x); };
  auto fraction = [&](double from, double to) {  // swept angle from -> to in the arc's sense
    double d = e.ccw ? to - from : from - to;
    while (d < 0) d += 2 * M_PI;
    while (d >= 2 * M_PI) d -= 2 * M_PI;
    return d;
  };
  const double a0 = angle(e.a), sweep = fraction(a0, angle(e.b)), at = fraction(a0, angle(p));
  if (at <= sweep) return std::fabs(std::hypot(p.x - e.c.x, p.y - e.c.y) - rad);
  return std::min(std::hypot(p.x - e.a.x, p.y - e.a.y), std::hypot(p.x - e.b.x, p.y - e.b.y));
}

// The same property on contours of lines and arcs (convex and concave), with CDON or CDOF: the
// compensated path keeps at least R from every element, exactly R with G450, also where the
// bottleneck detection omitted blocks.
TEST(CompensationProperty, RandomContoursWithArcsStayAtTheRadius) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  const double r = 2;
  int checked = 0, contours = 0, arcs = 0;
  for (int iter = 0; iter < 200; ++iter) {
    const int n = 5 + static_cast<int>(unit(rng) * 6);
    std::vector<P2> poly;
    for (int i = 0; i < n; ++i) {
      double a = (i + 0.2 + 0.6 * unit(rng)) / n * 2 * M_PI, rad = 30 + unit(rng) * 30;
      poly.push_back({rad * std::cos(a), rad * std::sin(a)});
    }
    std::vector<Edge> edges;
    for (int i = 0; i < n; ++i) {
      Edge e{poly[static_cast<size_t>(i)], poly[static_cast<size_t>((i + 1) % n)]};
      if (unit(rng) < 0.6) {
        // An arc through a and b whose apex lies off the chord by h (outwards or inwards).
        const double dx = e.b.x - e.a.x, dy = e.b.y - e.a.y, len = std::hypot(dx, dy);
        const double h = (unit(rng) < 0.5 ? 1 : -1) * (0.05 + 0.25 * unit(rng)) * len;
        const P2 m{(e.a.x + e.b.x) / 2, (e.a.y + e.b.y) / 2}, nl{-dy / len, dx / len};
        const P2 q{m.x - h * nl.x, m.y - h * nl.y};  // h > 0: to the right of a -> b (outwards)
        const double rho = (len * len / 4 + h * h) / (2 * std::fabs(h));
        e.c = {q.x + (h > 0 ? 1 : -1) * rho * nl.x, q.y + (h > 0 ? 1 : -1) * rho * nl.y};
        e.ccw = (q.x - e.a.x) * (e.b.y - q.y) - (q.y - e.a.y) * (e.b.x - q.x) > 0;
        e.arc = true;
        ++arcs;
      }
      edges.push_back(e);
    }
    const bool left = unit(rng) < 0.5, intersection = unit(rng) < 0.5, cdon = unit(rng) < 0.5;
    std::ostringstream prog;
    prog.precision(17);
    prog << "$MC_CUTCOM_CURVE_INSERT_LIMIT=0\n$TC_DP1[1,1]=120\n$TC_DP6[1,1]=" << r
         << "\nT1 D1\nG17 G90 G0 X0 Y0 Z0\n"
         << (intersection ? "G451" : "G450") << (cdon ? " CDON\n" : " CDOF\n")
         << (left ? "G41" : "G42") << " G1 X" << poly[0].x << " Y" << poly[0].y << " F100\n";
    for (int i = 0; i <= n; ++i) {
      const Edge& e = edges[static_cast<size_t>(i % n)];
      if (e.arc)
        prog << (e.ccw ? "G3" : "G2") << " X" << e.b.x << " Y" << e.b.y << " I=AC(" << e.c.x
             << ") J=AC(" << e.c.y << ")\n";
      else
        prog << "G1 X" << e.b.x << " Y" << e.b.y << "\n";
    }
    prog << "G1 G40 X0 Y0\nM30\n";
    Channel ch;
    Collect out;
    RunResult res = ch.runText("P.MPF", prog.str(), out);
    if (res.status != RunResult::Status::Ok) {
      if (std::getenv("NCOFFSET_DEBUG_PROPERTY"))
        std::fprintf(stderr, "%s\n", res.alarm->text.c_str());
      continue;
    }
    ++contours;
    // Contour blocks are lines 8 .. 8+n; skip the first and the last (next to the approach
    // and the retraction) as above.
    for (const Segment& s : out.rows) {
      if (s.line < 9 || s.line > 7 + n) continue;
      for (int j = 0; j <= 20; ++j) {
        const P2 p = samplePoint(s, j / 20.0);
        double d = 1e300;
        for (const Edge& e : edges) d = std::min(d, edgeDistance(p, e));
        if (intersection)
          ASSERT_GE(d, r - 1e-7) << "contour " << iter << " line " << s.line << "\n" << prog.str();
        else
          ASSERT_NEAR(d, r, 1e-7) << "contour " << iter << " line " << s.line << "\n" << prog.str();
        ++checked;
      }
    }
  }
  EXPECT_GT(arcs, 500);
  EXPECT_GT(contours, 150);
  EXPECT_GT(checked, 20000);
}

}  // namespace
}  // namespace ncoffset
