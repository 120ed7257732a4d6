// The random contour generator (random_contour.hpp). Plain geometry of its own: it shares no code
// with src/geom or src/trc, so that what it checks ("features larger than R") is independent of
// the compensation.
#include "random_contour.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

namespace ncoffset::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

Pt add(Pt p, Pt q) {
  return {p.a + q.a, p.o + q.o};
}
Pt sub(Pt p, Pt q) {
  return {p.a - q.a, p.o - q.o};
}
Pt mul(double s, Pt p) {
  return {s * p.a, s * p.o};
}
double dot(Pt p, Pt q) {
  return p.a * q.a + p.o * q.o;
}
double cross(Pt p, Pt q) {
  return p.a * q.o - p.o * q.a;
}
double len(Pt p) {
  return std::hypot(p.a, p.o);
}
Pt unit(Pt p) {
  return mul(1 / len(p), p);
}
Pt left(Pt p) {
  return {-p.o, p.a};
}

// An element with its start point, for the geometry below.
struct Piece {
  Pt s;
  ContourElement e;
};

double radiusOf(const Piece& p) {
  return len(sub(p.s, p.e.centre));
}
// Swept angle of an arc in (0, 2 pi], in its own sense.
double sweepOf(const Piece& p) {
  double a0 = std::atan2(p.s.o - p.e.centre.o, p.s.a - p.e.centre.a);
  double a1 = std::atan2(p.e.end.o - p.e.centre.o, p.e.end.a - p.e.centre.a);
  double d = p.e.ccw ? a1 - a0 : a0 - a1;
  while (d <= 0) d += 2 * kPi;
  while (d > 2 * kPi) d -= 2 * kPi;
  return d;
}
double lengthOf(const Piece& p) {
  return p.e.arc ? radiusOf(p) * sweepOf(p) : len(sub(p.e.end, p.s));
}
Pt tangent(const Piece& p, bool at_end) {
  if (!p.e.arc) return unit(sub(p.e.end, p.s));
  Pt r = unit(sub(at_end ? p.e.end : p.s, p.e.centre));
  return p.e.ccw ? left(r) : mul(-1, left(r));
}
Pt pointAt(const Piece& p, double u) {
  if (!p.e.arc) return add(p.s, mul(u, sub(p.e.end, p.s)));
  double a0 = std::atan2(p.s.o - p.e.centre.o, p.s.a - p.e.centre.a);
  double a = a0 + (p.e.ccw ? 1 : -1) * u * sweepOf(p);
  double r = radiusOf(p);
  return {p.e.centre.a + r * std::cos(a), p.e.centre.o + r * std::sin(a)};
}
double distance(Pt q, const Piece& p) {
  if (!p.e.arc) {
    Pt d = sub(p.e.end, p.s);
    double t = std::clamp(dot(sub(q, p.s), d) / dot(d, d), 0.0, 1.0);
    return len(sub(q, add(p.s, mul(t, d))));
  }
  double a0 = std::atan2(p.s.o - p.e.centre.o, p.s.a - p.e.centre.a);
  double aq = std::atan2(q.o - p.e.centre.o, q.a - p.e.centre.a);
  double d = p.e.ccw ? aq - a0 : a0 - aq;
  while (d < 0) d += 2 * kPi;
  while (d >= 2 * kPi) d -= 2 * kPi;
  if (d <= sweepOf(p)) return std::fabs(len(sub(q, p.e.centre)) - radiusOf(p));
  return std::min(len(sub(q, p.s)), len(sub(q, p.e.end)));
}

// The arc from a to b whose middle lies h off the chord to the left (h < 0: right).
ContourElement bulge(Pt a, Pt b, double h) {
  Pt d = sub(b, a);
  double l = len(d);
  Pt n = left(mul(1 / l, d));
  Pt apex = add(mul(0.5, add(a, b)), mul(h, n));
  double rho = (l * l / 4 + h * h) / (2 * std::fabs(h));
  ContourElement e;
  e.arc = true;
  e.end = b;
  e.centre = sub(apex, mul(h > 0 ? rho : -rho, n));
  e.ccw = h < 0;  // bulging to the right of a -> b: turning left (counter-clockwise)
  return e;
}

struct Ideal {
  bool ccw = true;
  Pt start;
  std::vector<ContourElement> elements;
};

// Side of the tool: +1 left of the travel (G41).
double sideOf(bool g41) {
  return g41 ? 1.0 : -1.0;
}

std::vector<Piece> pieces(const Pt& start, const std::vector<ContourElement>& el) {
  std::vector<Piece> out;
  Pt s = start;
  for (const ContourElement& e : el) {
    out.push_back({s, e});
    s = e.end;
  }
  return out;
}

// The corner between element k - 1 and k: deflection (degrees) and whether it is an outside
// corner for the tool.
void corner(const std::vector<Piece>& p, size_t k, double side, double& deg, bool& outside) {
  Pt t1 = tangent(p[(k + p.size() - 1) % p.size()], true), t2 = tangent(p[k], false);
  deg = std::atan2(std::fabs(cross(t1, t2)), dot(t1, t2)) * 180 / kPi;
  outside = side * cross(t1, t2) < 0;
}

// Features larger than R (see the header), on the ideal contour or on a rounded one.
bool feasible(const std::vector<Piece>& p, double r, double side, const GeneratorOptions& opt,
              bool clearance) {
  const size_t n = p.size();
  std::vector<double> trim(n, 0.0);  // at the start of element k
  for (size_t k = 0; k < n; ++k) {
    const Piece& q = p[k];
    if (q.e.arc && (q.e.ccw ? side > 0 : side < 0) && radiusOf(q) < r + 0.5) return false;
    if (q.e.tangent_start) continue;
    double deg;
    bool outside;
    corner(p, k, side, deg, outside);
    if (deg > (outside ? 150 : 120)) return false;
    if (std::fabs(deg - 10) < 1 || std::fabs(deg - 100) < 1) return false;
    if (opt.differential && deg < (outside ? 15 : 5)) return false;
    if (!outside) trim[k] = r * std::tan(deg * kPi / 360);
  }
  for (size_t k = 0; k < n; ++k)
    if (lengthOf(p[k]) < 1.5 * (trim[k] + trim[(k + 1) % n]) + 1) return false;
  if (!clearance) return true;
  // Elements that are not neighbours: more than 2R + 0.5 apart (sampled), unless only a
  // tangent element lies between them.
  std::vector<std::vector<Pt>> samples(n);
  for (size_t k = 0; k < n; ++k)
    for (int j = 0; j <= 48; ++j) samples[k].push_back(pointAt(p[k], j / 48.0));
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours across the start
      const bool one_between = j == i + 2 || (i == 0 && j == n - 2) || (i == 1 && j == n - 1);
      if (one_between) {
        const size_t mid = j == i + 2 ? i + 1 : (i == 0 ? n - 1 : 0);
        if (p[mid].e.tangent_start && p[(mid + 1) % n].e.tangent_start) continue;
      }
      double d = 1e300;
      for (const Pt& s : samples[i]) d = std::min(d, distance(s, p[j]));
      for (const Pt& s : samples[j]) d = std::min(d, distance(s, p[i]));
      if (d < 2 * r + 0.5) return false;
    }
  return true;
}

Ideal idealContour(std::mt19937& rng, double r, double side) {
  std::uniform_real_distribution<double> u(0, 1);
  Ideal c;
  c.ccw = u(rng) < 0.5;
  const int n = 5 + static_cast<int>(u(rng) * 5);
  const Pt centre{-20 + 40 * u(rng), -20 + 40 * u(rng)};
  const double th0 = 2 * kPi * u(rng);
  std::vector<Pt> v;
  for (int i = 0; i < n; ++i) {
    double th = th0 + (i + 0.2 + 0.6 * u(rng)) / n * 2 * kPi, rad = 30 + 30 * u(rng);
    v.push_back({centre.a + rad * std::cos(th), centre.o + rad * std::sin(th)});
  }
  if (!c.ccw) std::reverse(v.begin(), v.end());
  // Edge kinds: 0 line, 1 bulge, 2 ogee; a corner between two lines may get a fillet.
  std::vector<int> kind(static_cast<size_t>(n));
  for (int& k : kind) {
    double x = u(rng);
    k = x < 0.45 ? 0 : x < 0.8 ? 1 : 2;
  }
  auto at = [&](int i) { return v[static_cast<size_t>((i % n + n) % n)]; };
  std::vector<double> fillet(static_cast<size_t>(n), 0.0);  // radius, 0: sharp
  std::vector<Pt> t_in(static_cast<size_t>(n)), t_out(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) {
    const size_t k = static_cast<size_t>(i);
    t_in[k] = unit(sub(at(i), at(i - 1)));
    t_out[k] = unit(sub(at(i + 1), at(i)));
    if (kind[k] != 0 || kind[static_cast<size_t>((i + n - 1) % n)] != 0 || u(rng) < 0.4) continue;
    const double turn = cross(t_in[k], t_out[k]);
    const double half = std::atan2(std::fabs(turn), dot(t_in[k], t_out[k])) / 2;
    const bool inside_for_tool = side * turn > 0;
    double rho = inside_for_tool ? r + 0.5 + 9.5 * u(rng) : 0.5 + 9.5 * u(rng);
    const double room = 0.35 * std::min(len(sub(at(i), at(i - 1))), len(sub(at(i + 1), at(i))));
    rho = std::min(rho, room / std::tan(half));
    if (half > 1e-3 && rho >= (inside_for_tool ? r + 0.5 : 0.5)) fillet[k] = rho;
  }
  // Where the edge from vertex i starts and where it ends (at the fillets' tangent points).
  auto edgeStart = [&](int i) {
    const size_t k = static_cast<size_t>(i % n);
    if (fillet[k] == 0) return at(i);
    const double half = std::atan2(std::fabs(cross(t_in[k], t_out[k])), dot(t_in[k], t_out[k])) / 2;
    return add(at(i), mul(fillet[k] * std::tan(half), t_out[k]));
  };
  auto edgeEnd = [&](int i) {
    const size_t k = static_cast<size_t>((i + 1) % n);
    if (fillet[k] == 0) return at(i + 1);
    const double half = std::atan2(std::fabs(cross(t_in[k], t_out[k])), dot(t_in[k], t_out[k])) / 2;
    return sub(at(i + 1), mul(fillet[k] * std::tan(half), t_in[k]));
  };
  c.start = edgeStart(0);
  bool pending_tangent = false;  // the element after a fillet starts tangentially
  auto push = [&](ContourElement e) {
    e.tangent_start = e.tangent_start || pending_tangent;
    pending_tangent = false;
    c.elements.push_back(e);
  };
  for (int i = 0; i < n; ++i) {
    const Pt a = edgeStart(i), b = edgeEnd(i);
    const Pt d = sub(b, a);
    const double l = len(d);
    // The interior is to the left of a counter-clockwise contour.
    const double out = c.ccw ? -1 : 1;
    if (kind[static_cast<size_t>(i)] == 0) {
      push({false, b, {}, false, false});
    } else if (kind[static_cast<size_t>(i)] == 1) {
      const double h = (u(rng) < 0.5 ? out : -out) * (0.05 + 0.25 * u(rng)) * l;
      push(bulge(a, b, h));
    } else {
      const Pt m = mul(0.5, add(a, b));
      const double h = (u(rng) < 0.5 ? 1 : -1) * (0.05 + 0.15 * u(rng)) * l / 2;
      ContourElement first = bulge(a, m, h);
      ContourElement second = first;
      second.end = b;
      second.centre = sub(mul(2, m), first.centre);
      second.ccw = !first.ccw;
      second.tangent_start = true;
      push(first);
      push(second);
    }
    const size_t k = static_cast<size_t>((i + 1) % n);
    if (fillet[k] > 0) {
      const double turn = cross(t_in[k], t_out[k]);
      ContourElement f;
      f.arc = true;
      f.end = edgeStart(i + 1);
      f.ccw = turn > 0;
      f.centre = add(b, mul(fillet[k], f.ccw ? left(t_in[k]) : mul(-1, left(t_in[k]))));
      f.tangent_start = true;
      push(f);
      pending_tangent = true;
    }
  }
  if (pending_tangent) c.elements[0].tangent_start = true;
  return c;
}

using Ticks = std::int64_t;

double power10(int d) {
  double p = 1;
  for (int i = 0; i < d; ++i) p *= 10;
  return p;
}

// The contour with every coordinate a multiple of 10^-d; arc centres fitted (see the header).
std::vector<ContourElement> rounded(const Ideal& c, int d, Pt& start) {
  const double scale = power10(d);
  auto tick = [&](double x) { return static_cast<Ticks>(std::llround(x * scale)); };
  auto back = [&](Ticks t) { return static_cast<double>(t) / scale; };
  Ticks sa = tick(c.start.a), so = tick(c.start.o);
  start = {back(sa), back(so)};
  std::vector<ContourElement> out;
  for (size_t k = 0; k < c.elements.size(); ++k) {
    const ContourElement& e = c.elements[k];
    const bool last = k + 1 == c.elements.size();
    Ticks ea = last ? tick(c.start.a) : tick(e.end.a), eo = last ? tick(c.start.o) : tick(e.end.o);
    ContourElement r = e;
    r.end = {back(ea), back(eo)};
    if (e.arc) {
      const Ticks ca = tick(e.centre.a), co = tick(e.centre.o);
      Ticks best_a = ca, best_o = co;
      double best = 1e300;
      for (Ticks i = -2; i <= 2; ++i)
        for (Ticks j = -2; j <= 2; ++j) {
          const Ticks xa = ca + i, xo = co + j;
          const Ticks r0 = (sa - xa) * (sa - xa) + (so - xo) * (so - xo);
          const Ticks r1 = (ea - xa) * (ea - xa) + (eo - xo) * (eo - xo);
          const double diff = std::fabs(static_cast<double>(r0 - r1)) + 1e-3 * (i * i + j * j);
          if (diff < best) best = diff, best_a = xa, best_o = xo;
        }
      r.centre = {back(best_a), back(best_o)};
    }
    out.push_back(r);
    sa = ea, so = eo;
  }
  return out;
}

// Start and end radius of every arc nearly equal: the spiral's tilt (difference / length).
bool radiiAgree(const std::vector<Piece>& p) {
  for (const Piece& q : p)
    if (q.e.arc && std::fabs(len(sub(q.e.end, q.e.centre)) - radiusOf(q)) > 2e-4 * lengthOf(q))
      return false;
  return true;
}

std::string fixed(double x, int d) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", d, x);
  return buf;
}

}  // namespace

RandomContour randomContour(unsigned seed, int index, int decimals, const GeneratorOptions& opt) {
  std::mt19937 rng(seed * 1000003u + static_cast<unsigned>(index));
  std::uniform_real_distribution<double> u(0, 1);
  for (;;) {
    RandomContour c;
    c.index = index;
    c.g18 = index % 2 == 1;
    c.left = u(rng) < 0.5;
    c.g451 = u(rng) < 0.5;
    c.cdon = u(rng) < 0.5;
    c.radius = std::round((0.5 + 4.5 * u(rng)) * 1000) / 1000;
    c.decimals = decimals;
    if (opt.differential) {  // LinuxCNC: an arc at every convex corner, no bottleneck detection
      c.curve_insert_limit = 0;
      c.g451 = c.cdon = false;
    }
    const double side = sideOf(c.left);
    Ideal ideal = idealContour(rng, c.radius, side);
    c.ccw = ideal.ccw;
    if (!feasible(pieces(ideal.start, ideal.elements), c.radius, side, opt, true)) continue;
    bool ok = true;
    for (int d : {3, 4, 6}) {
      Pt s;
      std::vector<ContourElement> el = rounded(ideal, d, s);
      std::vector<Piece> p = pieces(s, el);
      ok = ok && radiiAgree(p) && feasible(p, c.radius, side, opt, false);
      if (d == decimals) c.start = s, c.elements = el;
    }
    if (!ok) continue;
    // The approach: in front of the start on the tool's side, a little back along the first
    // element.
    std::vector<Piece> p = pieces(c.start, c.elements);
    const Pt t = tangent(p[0], false), n = mul(side, left(t));
    const double out = c.toolOutside() ? 12 : 8;
    const double scale = power10(decimals);
    Pt a = sub(add(c.start, mul(out, n)), mul(3, t));
    c.approach = {std::round(a.a * scale) / scale, std::round(a.o * scale) / scale};
    return c;
  }
}

int contourLine(const RandomContour&, int k) {
  return 8 + k;
}

std::string programText(const RandomContour& c) {
  const int d = c.decimals;
  const char* A = c.g18 ? "Z" : "X";
  const char* O = c.g18 ? "X" : "Y";
  const char* CA = c.g18 ? "K" : "I";
  const char* CO = c.g18 ? "I" : "J";
  std::string t = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=" + fixed(c.radius, 3) + "\n";
  t += c.curve_insert_limit >= 0
           ? "$MC_CUTCOM_CURVE_INSERT_LIMIT=" + fixed(c.curve_insert_limit, 3) + "\n"
           : "; MD20230 default\n";
  t += "T1 D1\n";
  t += std::string(c.g18 ? "G18" : "G17") + " G90 G0 " + A + fixed(c.approach.a, d) + " " + O +
       fixed(c.approach.o, d) + (c.g18 ? " Y0\n" : " Z0\n");
  t += std::string(c.g451 ? "G451" : "G450") + (c.cdon ? " CDON\n" : " CDOF\n");
  t += std::string(c.left ? "G41" : "G42") + " G1 " + A + fixed(c.start.a, d) + " " + O +
       fixed(c.start.o, d) + " F100\n";
  for (size_t k = 0; k <= c.elements.size() + 1; ++k) {
    const ContourElement& e = c.elements[k % c.elements.size()];
    if (!e.arc) {
      t += "G1 " + std::string(A) + fixed(e.end.a, d) + " " + O + fixed(e.end.o, d) + "\n";
    } else {
      t += std::string(e.ccw ? "G3 " : "G2 ") + A + fixed(e.end.a, d) + " " + O +
           fixed(e.end.o, d) + " " + CA + "=AC(" + fixed(e.centre.a, d) + ") " + CO + "=AC(" +
           fixed(e.centre.o, d) + ")\n";
    }
  }
  t += "G40 G1 " + std::string(A) + fixed(c.approach.a, d) + " " + O + fixed(c.approach.o, d) +
       "\nM30\n";
  return t;
}

std::string description(const RandomContour& c) {
  const int d = c.decimals;
  std::string t = "contour " + std::to_string(c.index) + (c.g18 ? " G18 " : " G17 ") +
                  (c.left ? "G41 " : "G42 ") + fixed(c.radius, 3) + " " + std::to_string(d) +
                  (c.g451 ? " G451" : " G450") + (c.cdon ? " CDON\n" : " CDOF\n");
  t += "start " + fixed(c.start.a, d) + " " + fixed(c.start.o, d) + "\n";
  t += "approach " + fixed(c.approach.a, d) + " " + fixed(c.approach.o, d) + "\n";
  for (const ContourElement& e : c.elements) {
    if (!e.arc)
      t += "line " + fixed(e.end.a, d) + " " + fixed(e.end.o, d) + "\n";
    else
      t += "arc " + fixed(e.end.a, d) + " " + fixed(e.end.o, d) + " " + fixed(e.centre.a, d) + " " +
           fixed(e.centre.o, d) + (e.ccw ? " ccw\n" : " cw\n");
  }
  return t;
}

}  // namespace ncoffset::test
