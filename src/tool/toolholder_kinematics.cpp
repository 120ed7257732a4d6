// What a selected toolholder does (W1 2.5 "Toolholder with orientation capability", kinematic
// types T, P, M; docs/toolholders.md "The chain"): the rotations R1 = R(v1, a1), R2 = R(v2, a2)
// and the offset vectors l1..l4, and for TCOFR the angles that turn the tool along the frame.
#include <fmt/format.h>

#include <cmath>

#include "ncoffset/alarm.hpp"
#include "tool/toolholder.hpp"

namespace ncoffset::tool {

namespace {

// Unit vectors closer than this are the same direction (TCOFR: the orientation is reachable).
constexpr double kSame = 1e-9;

Vec3 unit(Vec3 v) {
  double n = norm(v);
  return n > 1e-12 ? (1.0 / n) * v : Vec3{};
}

Vec3 vec(const CarrierData& d, int first, bool fine, int fine_first) {
  Vec3 v{d.num[static_cast<size_t>(first)], d.num[static_cast<size_t>(first + 1)],
         d.num[static_cast<size_t>(first + 2)]};
  if (fine)
    v = v + Vec3{d.num[static_cast<size_t>(fine_first)], d.num[static_cast<size_t>(fine_first + 1)],
                 d.num[static_cast<size_t>(fine_first + 2)]};
  return v;
}

// The angle about unit axis u that turns s into t (both with the same component along u); the
// preset where s lies on the axis (every angle does).
double angleAbout(Vec3 u, Vec3 s, Vec3 t, double preset) {
  Vec3 sp = s - dot(s, u) * u;
  Vec3 tp = t - dot(t, u) * u;
  if (norm(sp) < kSame || norm(tp) < kSame) return preset;
  return std::atan2(dot(u, cross(sp, tp)), dot(sp, tp)) * kDegreePerRad;
}

// One axis u (unit) turns s into t: one solution or none.
AngleSolutions oneAxis(Vec3 u, Vec3 s, Vec3 t, double preset, int slot, double other) {
  AngleSolutions r;
  if (std::fabs(dot(s, u) - dot(t, u)) > kSame) return r;
  r.count = 1;
  r.b[0][static_cast<size_t>(slot)] = angleAbout(u, s, t, preset);
  r.b[0][static_cast<size_t>(1 - slot)] = other;
  return r;
}

// `alpha` plus the multiple of 360 degrees nearest to `preset` (W1: "the solution closest to
// the specified angles"; 750 specified, 10 computed: 730). Half a turn away (180 from 0) goes
// up: +180, whichever of +-180 the solution came as.
double nearTurn(double alpha, double preset) {
  return alpha + 360.0 * std::floor((preset - alpha) / 360.0 + 0.5);
}

}  // namespace

Mat3 rotationAboutVector(Vec3 v, double degrees) {
  Vec3 u = unit(v);
  if (norm(u) == 0.0 || degrees == 0.0) return Mat3::identity();
  const double a = degrees * kRadPerDegree;
  const double c = std::cos(a), s = std::sin(a), t = 1 - c;
  Mat3 r;
  r.m = {{{t * u.x * u.x + c, t * u.x * u.y - s * u.z, t * u.x * u.z + s * u.y},
          {t * u.x * u.y + s * u.z, t * u.y * u.y + c, t * u.y * u.z - s * u.x},
          {t * u.x * u.z - s * u.y, t * u.y * u.z + s * u.x, t * u.z * u.z + c}}};
  return r;
}

// Ra(b1) Rb(b2) s = t: w = Rb(b2) s keeps its component along b and Ra(b1) w = t fixes its
// component along a, so w lies on the unit sphere and two planes: up to two solutions.
AngleSolutions solveTwoAxes(Vec3 a_in, Vec3 b_in, Vec3 s_in, Vec3 t_in,
                            std::array<double, 2> preset) {
  const Vec3 a = unit(a_in), b = unit(b_in), s = unit(s_in), t = unit(t_in);
  const bool has_a = norm(a) > 0, has_b = norm(b) > 0;
  if (!has_a && !has_b) {
    AngleSolutions r;
    if (norm(s - t) <= kSame) {
      r.count = 1;
      r.b[0] = preset;
    }
    return r;
  }
  if (!has_a) return oneAxis(b, s, t, preset[1], 1, preset[0]);
  if (!has_b) return oneAxis(a, s, t, preset[0], 0, preset[1]);
  const Vec3 n = cross(a, b);
  const double nn = dot(n, n);
  if (nn < kSame * kSame) {  // parallel axes act as one: b keeps its preset
    const Vec3 w = rotationAboutVector(b, preset[1]) * s;
    return oneAxis(a, w, t, preset[0], 0, preset[1]);
  }
  const double k = dot(a, b), ta = dot(t, a), sb = dot(s, b);
  const double c1 = (ta - k * sb) / nn, c2 = (sb - k * ta) / nn;
  const Vec3 base = c1 * a + c2 * b;
  const double rem = 1 - dot(base, base);
  AngleSolutions r;
  if (rem < -kSame) return r;
  const double c3 = std::sqrt(std::fmax(rem, 0.0) / nn);
  const int count = c3 * std::sqrt(nn) > kSame ? 2 : 1;
  for (int i = 0; i < count; ++i) {
    const Vec3 w = base + (i == 0 ? c3 : -c3) * n;
    const double b2 = angleAbout(b, s, w, preset[1]);
    const double b1 = angleAbout(a, w, t, preset[0]);
    r.b[static_cast<size_t>(r.count++)] = {b1, b2};
  }
  return r;
}

namespace {

struct Axes {
  Vec3 v1, v2;
  double off1 = 0, off2 = 0;
};

// A TCOFR angle on the Hirth grid and within the software limits (W1 2.5: limits evaluated
// unless both are zero; the angle may move by whole turns into them). False if it cannot.
bool fitAxis(const CarrierData& d, int axis, double& alpha, double preset) {
  const auto p = [&](int n) { return d.num[static_cast<size_t>(n + axis)]; };
  alpha = nearTurn(alpha, preset);
  if (p(28) > 0) alpha = p(26) + p(28) * std::round((alpha - p(26)) / p(28));
  const double lo = p(30), hi = p(32);
  if (lo == 0 && hi == 0) return true;
  if (alpha >= lo - kSame && alpha <= hi + kSame) return true;
  for (double turn : {-360.0, 360.0, -720.0, 720.0}) {
    if (alpha + turn >= lo - kSame && alpha + turn <= hi + kSame) {
      alpha += turn;
      return true;
    }
  }
  return false;
}

// TCOFR: the angles (a1, a2) that point the tool (+Z when not rotated) along the frame's axis
// `f` (BCS): type T R1 R2 z = f; P R1 R2 f = z (the table turns the frame's axis to the tool); M
// R1 z = R2 f. Of the solutions the one closest to $TC_CARR13/14 (W1 2.5).
void frameAngles(const CarrierData& d, const Axes& ax, char kind, Vec3 f, CarrierPose& pose) {
  const Vec3 z{0, 0, 1};
  const double p1 = d.num[13], p2 = d.num[14];
  AngleSolutions s;
  if (kind == 'M') {  // R2(-b2) R1(b1) z = f
    s = solveTwoAxes(ax.v2, ax.v1, z, f, {-(p2 - ax.off2), p1 - ax.off1});
    for (int i = 0; i < s.count; ++i) s.b[static_cast<size_t>(i)] = {s.b[i][1], -s.b[i][0]};
  } else if (kind == 'P') {
    s = solveTwoAxes(ax.v1, ax.v2, f, z, {p1 - ax.off1, p2 - ax.off2});
  } else {
    s = solveTwoAxes(ax.v1, ax.v2, z, f, {p1 - ax.off1, p2 - ax.off2});
  }
  double best = -1;
  for (int i = 0; i < s.count; ++i) {
    double a1 = s.b[static_cast<size_t>(i)][0] + ax.off1,
           a2 = s.b[static_cast<size_t>(i)][1] + ax.off2;
    if (!fitAxis(d, 0, a1, p1) || !fitAxis(d, 1, a2, p2)) continue;
    pose.solutions[static_cast<size_t>(2 * pose.solution_count)] = a1;
    pose.solutions[static_cast<size_t>(2 * pose.solution_count + 1)] = a2;
    ++pose.solution_count;
    const double dist = std::fabs(a1 - p1) + std::fabs(a2 - p2);
    if (best < 0 || dist < best) {
      best = dist;
      pose.angle1 = a1;
      pose.angle2 = a2;
    }
  }
  if (best < 0)
    raise(AlarmNumber::CarrierOrientation,
          fmt::format("toolholder {}: invalid orientation: no angles of the rotary axes turn the "
                      "tool along the frame ({:.6g}, {:.6g}, {:.6g})",
                      pose.number, f.x, f.y, f.z));
  if (pose.solutions[0] != pose.angle1 || pose.solutions[1] != pose.angle2) {
    std::swap(pose.solutions[0], pose.solutions[2]);  // $P_TCANG[1..2]: the pair taken
    std::swap(pose.solutions[1], pose.solutions[3]);
  }
}

}  // namespace

std::array<std::string, 2> ToolCarriers::axisNames(int m) const {
  if (m < 1 || m > count_) return {};
  return {data(m).axis1, data(m).axis2};
}

CarrierPose ToolCarriers::pose(int m, CarrierAngles mode, const Mat3& frame_linear, bool fine,
                               std::array<double, 2> axis_angles) const {
  CarrierPose pose;
  if (m == 0) return pose;
  if (m < 0 || m > count_)
    raise(AlarmNumber::CarrierNumber,
          fmt::format("toolholder number programmed incorrectly: TCARR={} (MD18088 "
                      "$MN_MM_NUM_TOOL_CARRIER = {})",
                      m, count_));
  const CarrierData& d = data(m);
  if (d.kind != 'T' && d.kind != 'P' && d.kind != 'M')
    raise(AlarmNumber::CarrierKind,
          fmt::format("toolholder {}: unknown kinematic type $TC_CARR23 = '{}' (T, P or M)", m,
                      d.kind == 0 ? std::string("0") : std::string(1, d.kind)));
  pose.number = m;
  pose.kind = d.kind;
  Axes ax{vec(d, 7, false, 0), vec(d, 10, false, 0), d.num[24] + (fine ? d.num[64] : 0.0),
          d.num[25] + (fine ? d.num[65] : 0.0)};
  // A rotary axis of the channel gives its position; a holder without one its $TC_CARR13/14.
  pose.angle1 = std::isnan(axis_angles[0]) ? d.num[13] : axis_angles[0];
  pose.angle2 = std::isnan(axis_angles[1]) ? d.num[14] : axis_angles[1];
  if (mode != CarrierAngles::Absolute) {
    const int col = mode == CarrierAngles::FrameZ ? 2 : mode == CarrierAngles::FrameY ? 1 : 0;
    const Vec3 f{frame_linear.m[0][static_cast<size_t>(col)],
                 frame_linear.m[1][static_cast<size_t>(col)],
                 frame_linear.m[2][static_cast<size_t>(col)]};
    frameAngles(d, ax, d.kind, unit(f), pose);
  }
  const Mat3 r1 = rotationAboutVector(ax.v1, pose.angle1 - ax.off1);
  const Mat3 r2 = rotationAboutVector(ax.v2, pose.angle2 - ax.off2);
  const Vec3 l1 = vec(d, 1, fine, 41), l2 = vec(d, 4, fine, 44), l3 = vec(d, 15, fine, 55),
             l4 = vec(d, 18, fine, 58);
  if (d.kind == 'T') {  // L' = l1 + R1 (l2 + R2 (l3 + L))
    pose.tool_rotation = r1 * r2;
    pose.tool_offset = l1 + r1 * (l2 + r2 * l3);
  } else if (d.kind == 'P') {  // table: l2 + R1 (l3 + R2 l4); the tool keeps l1
    pose.tool_offset = l1;
    pose.part_rotation = r1 * r2;
    pose.part_offset = l2 + r1 * (l3 + r2 * l4);
  } else {  // M: tool L' = l1 + R1 (l2 + L); table l3 + R2 l4
    pose.tool_rotation = r1;
    pose.tool_offset = l1 + r1 * l2;
    pose.part_rotation = r2;
    pose.part_offset = l3 + r2 * l4;
  }
  return pose;
}

}  // namespace ncoffset::tool
