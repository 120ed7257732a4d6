#include "out/time_estimate.hpp"

#include <algorithm>
#include <cmath>

#include "out/arc_geometry.hpp"

namespace ncoffset::out {
namespace {

// The path limit the axes give to a motion along `dir` (unit vector): each axis i may move at
// most limit[i], so the path at most min(limit[i] / |dir_i|).
double pathLimit(const Vec3& dir, const std::array<double, 3>& limit) {
  const double d[3] = {std::fabs(dir.x), std::fabs(dir.y), std::fabs(dir.z)};
  double v = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    if (d[i] > 1e-12) v = std::min(v, limit[static_cast<size_t>(i)] / d[i]);
  return v;
}

// The direction whose axis shares bound an arc: an arc in a plane moves both of the plane's
// axes at full share somewhere on it, so each in-plane axis counts with share 1 (the normal's
// axis with the helix share).
Vec3 limitingDirection(const Segment& s, double length) {
  if (!isArc(s)) {
    Vec3 d = s.end - s.start;
    return length > 0 ? (1.0 / length) * d : Vec3{};
  }
  const Vec3& n = s.normal;
  auto share = [](double c) { return std::fabs(c) > 0.999 ? 0.0 : 1.0; };
  return {share(n.x), share(n.y), share(n.z)};
}

}  // namespace

void TimeEstimate::setDynamics(const AxisDynamics& d) {
  for (size_t i = 0; i < 3; ++i) {
    if (d.max_velocity[i] > 0) dyn_.max_velocity[i] = d.max_velocity[i];
    if (d.max_acceleration[i] > 0) dyn_.max_acceleration[i] = d.max_acceleration[i];
  }
}

double trapezoidSeconds(double length, double v, double a) {
  if (length <= 0 || v <= 0) return 0;
  if (!(a > 0) || std::isinf(a)) return length / v;
  // Accelerating to v takes v/a seconds over v^2/(2a) mm, braking the same.
  if (length >= v * v / a) return length / v + v / a;
  return 2 * std::sqrt(length / a);  // a triangle: v is never reached
}

void TimeEstimate::segment(const Segment& s) {
  const double length = segmentLength(s);
  if (!(length > 0)) return;
  const Vec3 dir = limitingDirection(s, length);
  std::array<double, 3> vmax{}, amax{};
  for (size_t i = 0; i < 3; ++i) {
    vmax[i] = dyn_.max_velocity[i] / 60.0;        // mm/min -> mm/s
    amax[i] = dyn_.max_acceleration[i] * 1000.0;  // m/s2 -> mm/s2
  }
  const double v_axes = pathLimit(dir, vmax);
  const double a = pathLimit(dir, amax);
  double v = v_axes;
  if (s.has_feed) {
    switch (s.feed_unit) {
      case FeedUnit::MmPerMin:
        v = std::min(v_axes, s.feed / 60.0);
        break;
      case FeedUnit::MmPerRev:
        if (speed_ <= 0) {
          ++no_speed_;
          return;
        }
        v = std::min(v_axes, s.feed * speed_ / 60.0);
        break;
      case FeedUnit::InverseTime:  // F: 1/min, the block takes 1/F minutes
        v = s.feed > 0 ? std::min(v_axes, length * s.feed / 60.0) : v_axes;
        break;
    }
  }
  if (!(v > 0) || std::isinf(v)) return;
  const double plain = length / v;
  const double t = trapezoidSeconds(length, v, a);
  without_accel_ += plain;
  with_accel_ += t;
  if (!s.has_feed) rapid_ += t;
}

void TimeEstimate::dwell(const DwellEvent& e) {
  double t = e.seconds;
  if (e.revolutions > 0 && speed_ > 0) t += e.revolutions * 60.0 / speed_;
  dwell_ += t;
  with_accel_ += t;
  without_accel_ += t;
}

}  // namespace ncoffset::out
