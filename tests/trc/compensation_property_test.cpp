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
#include <optional>
#include <random>
#include <sstream>
#include <vector>

#include "ncoffset/channel.hpp"
#include "support/random_contour.hpp"

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

// The issue "radius compensation that never stops on a good contour": random closed contours of
// lines and arcs (tests/support/random_contour.hpp: tangent and non-tangent joins, convex and
// concave, G17 and G18, G41 and G42, G450/G451, CDON/CDOF, R from 0.5 to 5 mm, features larger
// than R), each written with 3, 4 and 6 decimals. Every run must end without alarm and without
// omitted blocks, and every sampled point of every compensated row between the approach and
// the retraction must keep at least R - 1e-6 from the contour (no gouge) and at most R + 1e-6
// where the path follows an element or goes round a corner on a circle; where it takes the
// intersection at an outside corner (G451, or G450 below MD20230), at most as far from the corner
// as the crossing of the extended equidistants (which the check computes itself). The check is
// geometry of its own: it never calls the compensation code.
//
// Size: NCOFFSET_PROPERTY_CONTOURS contours (default 300 for ctest; NCOFFSET_PROPERTY_SHOW: how
// many failures to print, default 3); the full size is
//   NCOFFSET_PROPERTY_CONTOURS=5000 build/tests/ncoffset_unit_tests
//     --gtest_filter='CompensationProperty.RandomRoundedContours*'
// (docs/radius-compensation.md, "How it is checked").

// A contour element in plane coordinates, as the checker reads the program.
struct CheckElement {
  P2 s, e;
  bool arc = false;
  P2 c{0, 0};
  bool ccw = false;
};

P2 planePoint(const Vec3& v, bool g18) {
  return g18 ? P2{v.z, v.x} : P2{v.x, v.y};
}

double angleAbout(P2 c, P2 p) {
  return std::atan2(p.y - c.y, p.x - c.x);
}

// The swept angle from angle `from` to `to` in the sense of travel, in [0, 2 pi).
double swept(double from, double to, bool ccw) {
  double d = ccw ? to - from : from - to;
  while (d < 0) d += 2 * M_PI;
  while (d >= 2 * M_PI) d -= 2 * M_PI;
  return d;
}

// An arc's sweep in (0, 2 pi] (a full circle when its end is its start).
double arcSweep(const CheckElement& e) {
  double d = swept(angleAbout(e.c, e.s), angleAbout(e.c, e.e), e.ccw);
  return d < 1e-12 ? 2 * M_PI : d;
}

// The point at fraction u of a row or an element. An arc whose end radius differs from its start
// radius is the spiral between them (radius linear in the angle), as ncoffset's rows are.
P2 sampleElement(const CheckElement& e, double u) {
  if (!e.arc) return {e.s.x + u * (e.e.x - e.s.x), e.s.y + u * (e.e.y - e.s.y)};
  const double r0 = std::hypot(e.s.x - e.c.x, e.s.y - e.c.y);
  const double r1 = std::hypot(e.e.x - e.c.x, e.e.y - e.c.y);
  const double a = angleAbout(e.c, e.s) + (e.ccw ? 1 : -1) * u * arcSweep(e);
  const double r = r0 + u * (r1 - r0);
  return {e.c.x + r * std::cos(a), e.c.y + r * std::sin(a)};
}

// Distance from p to the element, and whether the nearest point is one of its ends.
double footDistance(P2 p, const CheckElement& e, bool& at_end) {
  if (!e.arc) {
    const double dx = e.e.x - e.s.x, dy = e.e.y - e.s.y;
    const double t = ((p.x - e.s.x) * dx + (p.y - e.s.y) * dy) / (dx * dx + dy * dy);
    at_end = t <= 0 || t >= 1;
    const double tc = std::clamp(t, 0.0, 1.0);
    return std::hypot(p.x - (e.s.x + tc * dx), p.y - (e.s.y + tc * dy));
  }
  const double f = swept(angleAbout(e.c, e.s), angleAbout(e.c, p), e.ccw) / arcSweep(e);
  if (f <= 1) {
    at_end = false;
    const double r0 = std::hypot(e.s.x - e.c.x, e.s.y - e.c.y);
    const double r1 = std::hypot(e.e.x - e.c.x, e.e.y - e.c.y);
    return std::fabs(std::hypot(p.x - e.c.x, p.y - e.c.y) - (r0 + f * (r1 - r0)));
  }
  at_end = true;
  return std::min(std::hypot(p.x - e.s.x, p.y - e.s.y), std::hypot(p.x - e.e.x, p.y - e.e.y));
}

P2 elementTangent(const CheckElement& e, bool at_end) {
  if (!e.arc) {
    const double l = std::hypot(e.e.x - e.s.x, e.e.y - e.s.y);
    return {(e.e.x - e.s.x) / l, (e.e.y - e.s.y) / l};
  }
  const P2 q = at_end ? e.e : e.s;
  const double l = std::hypot(q.x - e.c.x, q.y - e.c.y);
  const P2 r{(q.x - e.c.x) / l, (q.y - e.c.y) / l};
  return e.ccw ? P2{-r.y, r.x} : P2{r.y, -r.x};
}

// The equidistant at distance R on the tool side (`side` +1: left) of element e near one of its
// ends, as a whole line or circle: a point and direction, or a centre and radius (an arc: its
// radius at that end).
struct Offset {
  bool circle = false;
  P2 p{0, 0}, d{0, 0};  // line: a point and the unit direction
  P2 c{0, 0};
  double r = 0;  // circle
};

Offset offsetNear(const CheckElement& e, bool at_end, double radius, double side) {
  Offset o;
  const P2 t = elementTangent(e, at_end), n{-side * t.y, side * t.x};
  const P2 q = at_end ? e.e : e.s;
  if (!e.arc) {
    o.p = {q.x + radius * n.x, q.y + radius * n.y};
    o.d = t;
    return o;
  }
  o.circle = true;
  o.c = e.c;
  o.r = std::hypot(q.x + radius * n.x - e.c.x, q.y + radius * n.y - e.c.y);
  return o;
}

// The crossings of two offsets taken as whole lines and circles.
std::vector<P2> crossings(const Offset& a, const Offset& b) {
  std::vector<P2> out;
  if (!a.circle && !b.circle) {
    const double den = a.d.x * b.d.y - a.d.y * b.d.x;
    if (std::fabs(den) < 1e-15) return out;
    const double t = ((b.p.x - a.p.x) * b.d.y - (b.p.y - a.p.y) * b.d.x) / den;
    out.push_back({a.p.x + t * a.d.x, a.p.y + t * a.d.y});
    return out;
  }
  if (a.circle != b.circle) {
    const Offset& l = a.circle ? b : a;
    const Offset& c = a.circle ? a : b;
    const double fx = l.p.x - c.c.x, fy = l.p.y - c.c.y;
    const double bb = fx * l.d.x + fy * l.d.y, cc = fx * fx + fy * fy - c.r * c.r;
    const double disc = bb * bb - cc;
    if (disc < 0) return out;
    for (double t : {-bb - std::sqrt(disc), -bb + std::sqrt(disc)})
      out.push_back({l.p.x + t * l.d.x, l.p.y + t * l.d.y});
    return out;
  }
  const double dx = b.c.x - a.c.x, dy = b.c.y - a.c.y, dist = std::hypot(dx, dy);
  if (dist < 1e-15) return out;
  const double m = (a.r * a.r - b.r * b.r + dist * dist) / (2 * dist), h2 = a.r * a.r - m * m;
  if (h2 < 0) return out;
  const double h = std::sqrt(h2);
  for (double sgn : {1.0, -1.0})
    out.push_back({a.c.x + (m * dx - sgn * h * dy) / dist, a.c.y + (m * dy + sgn * h * dx) / dist});
  return out;
}

struct Outcome {
  int runs = 0, alarms = 0, warned = 0, points = 0, bad = 0;
  int alarms_by_decimals[7] = {};
  int arcs = 0, tangent = 0, convex = 0, concave = 0;
};

struct CollectAll final : PathSink {
  std::vector<Segment> rows;
  int warnings = 0;
  void segment(const Segment& s) override { rows.push_back(s); }
  void warning(const SourceLoc&, int, const std::string&) override { ++warnings; }
  void finish(const Alarm*) override {}
};

// Runs one rounded contour and checks its compensated path; returns a description of the first
// failure (empty: none).
std::string checkContour(const test::RandomContour& c, Outcome& out) {
  const std::string prog = test::programText(c);
  Channel ch(RunOptions{CoordSystem::WCS, {}});
  CollectAll sink;
  RunResult res = ch.runText("P.MPF", prog, sink);
  ++out.runs;
  if (res.status != RunResult::Status::Ok) {
    ++out.alarms;
    ++out.alarms_by_decimals[c.decimals];
    return "alarm " + std::to_string(res.alarm->number) + " line " +
           std::to_string(res.alarm->where.line) + ": " + res.alarm->text + "\n" + prog;
  }
  if (sink.warnings > 0) {
    ++out.warned;
    return "warning (block omitted)\n" + prog;
  }
  // The contour as the checker sees it.
  const size_t n = c.elements.size();
  std::vector<CheckElement> el;
  P2 s{c.start.a, c.start.o};
  for (const test::ContourElement& e : c.elements) {
    CheckElement k;
    k.s = s;
    k.e = {e.end.a, e.end.o};
    k.arc = e.arc;
    k.c = {e.centre.a, e.centre.o};
    k.ccw = e.ccw;
    el.push_back(k);
    s = k.e;
    out.arcs += e.arc;
  }
  const double r = c.radius, side = c.left ? 1 : -1;
  const double insert_limit = c.curve_insert_limit >= 0 ? c.curve_insert_limit : 10;
  // How far from the contour a point may lie whose nearest contour point is vertex k (the start
  // of element k): R, or at an outside corner that is intersected R / cos(delta / 2).
  std::vector<double> vertex_max(n);
  for (size_t k = 0; k < n; ++k) {
    const P2 t1 = elementTangent(el[(k + n - 1) % n], true), t2 = elementTangent(el[k], false);
    const double cr = t1.x * t2.y - t1.y * t2.x, dt = t1.x * t2.x + t1.y * t2.y;
    const double delta = std::atan2(std::fabs(cr), dt);
    const double deg = delta * 180 / M_PI;
    const bool outside = side * cr < 0;
    if (c.elements[k].tangent_start)
      ++out.tangent;
    else
      ++(outside ? out.convex : out.concave);
    const bool intersected = outside && (c.g451 ? deg < 100 : deg < insert_limit);
    vertex_max[k] = r + 1e-6;
    if (!intersected) continue;
    // The path goes out to where the extended equidistants cross (nearest the corner); none:
    // the circle.
    const CheckElement& e1 = el[(k + n - 1) % n];
    const CheckElement& e2 = el[k];
    const P2 v = e2.s;
    std::optional<P2> best;
    for (const P2& x : crossings(offsetNear(e1, true, r, side), offsetNear(e2, false, r, side)))
      if (!best || std::hypot(x.x - v.x, x.y - v.y) < std::hypot(best->x - v.x, best->y - v.y))
        best = x;
    if (!best) continue;
    // ncoffset extends a spiral (an arc whose radii differ) as a spiral, this check with the
    // circle of its end radius: they differ by the change of radius over the extension, at
    // most a turn.
    auto change = [&](const CheckElement& e) {
      if (!e.arc) return 0.0;
      const double r0 = std::hypot(e.s.x - e.c.x, e.s.y - e.c.y);
      const double r1 = std::hypot(e.e.x - e.c.x, e.e.y - e.c.y);
      return std::fabs(r1 - r0) * (1 + 2 * M_PI / arcSweep(e));
    };
    const double far = std::hypot(best->x - v.x, best->y - v.y);
    vertex_max[k] = std::max(vertex_max[k], far + 1e-6 + change(e1) + change(e2));
  }
  const int first = test::contourLine(c, 1), last = test::contourLine(c, static_cast<int>(n));
  for (const Segment& row : sink.rows) {
    if (row.line < first || row.line > last) continue;
    CheckElement e;
    e.s = planePoint(row.start, c.g18);
    e.e = planePoint(row.end, c.g18);
    e.arc = row.motion == Motion::G2 || row.motion == Motion::G3;
    e.c = planePoint(row.centre, c.g18);
    e.ccw = row.motion == Motion::G3;
    for (int j = 0; j <= 16; ++j) {
      const P2 p = sampleElement(e, j / 16.0);
      double d = 1e300, allowed = 0;
      std::vector<std::pair<double, double>> near;  // distance, allowed maximum
      for (size_t k = 0; k < n; ++k) {
        bool at_end = false;
        const double dk = footDistance(p, el[k], at_end);
        double max = r + 1e-6;
        if (at_end) {
          const bool at_start = std::hypot(p.x - el[k].s.x, p.y - el[k].s.y) <=
                                std::hypot(p.x - el[k].e.x, p.y - el[k].e.y);
          max = vertex_max[at_start ? k : (k + 1) % n];
        }
        near.push_back({dk, max});
        d = std::min(d, dk);
      }
      allowed = 1e300;
      for (const auto& [dk, max] : near)
        if (dk <= d + 1e-9) allowed = std::min(allowed, max);
      ++out.points;
      if (d < r - 1e-6 || d > allowed) {
        ++out.bad;
        char buf[256];
        std::snprintf(buf, sizeof buf,
                      "line %d %s point (%.9f, %.9f): distance %.9f, R %.3f, allowed up to %.9f\n",
                      row.line, motionName(row.motion), p.x, p.y, d, r, allowed);
        std::string near_list;
        for (size_t k = 0; k < n; ++k)
          if (near[k].first < d + 1e-3)
            near_list += "  element " + std::to_string(k) + " (line " +
                         std::to_string(test::contourLine(c, static_cast<int>(k))) +
                         "): distance " + std::to_string(near[k].first) + " allowed " +
                         std::to_string(near[k].second) + "\n";
        return buf + near_list + prog;
      }
    }
  }
  return {};
}

TEST(CompensationProperty, RandomRoundedContoursKeepTheRadius) {
  int contours = 300;
  if (const char* env = std::getenv("NCOFFSET_PROPERTY_CONTOURS")) contours = std::atoi(env);
  Outcome out;
  int failures = 0;
  for (int i = 0; i < contours; ++i) {
    for (int d : {3, 4, 6}) {
      const test::RandomContour c = test::randomContour(13, i, d, {});
      const std::string why = checkContour(c, out);
      if (why.empty()) continue;
      if (++failures <= (std::getenv("NCOFFSET_PROPERTY_SHOW")
                             ? std::atoi(std::getenv("NCOFFSET_PROPERTY_SHOW"))
                             : 3))
        ADD_FAILURE() << "contour " << i << " with " << d << " decimals: " << why;
    }
  }
  std::printf(
      "%d contours x 3 roundings: %d runs, %d alarms (%d/%d/%d with 3/4/6 decimals), %d with "
      "omitted blocks, %d failed; %d points checked; %d arcs, %d tangent joins, %d convex and "
      "%d concave corners\n",
      contours, out.runs, out.alarms, out.alarms_by_decimals[3], out.alarms_by_decimals[4],
      out.alarms_by_decimals[6], out.warned, failures, out.points, out.arcs, out.tangent,
      out.convex, out.concave);
  EXPECT_EQ(failures, 0);
  EXPECT_GT(out.points, contours * 3 * 100);
}

}  // namespace
}  // namespace ncoffset
