// The machining time estimate of the HTML report (issue 21 item 3). An estimate, not the
// control's time: every block is taken alone as a trapezoid that starts and ends at standstill
// (as with exact stop G60/G9), at its feed (G94 mm/min; G95 mm/rev times the last programmed
// spindle speed S; G93 inverse time: 1/F minutes for the block) or, for rapid traverse, at the
// path velocity the axes allow ($MA_MAX_AX_VELO, MD32000), accelerated with the path
// acceleration the axes allow ($MA_MAX_AX_ACCEL, MD32300). The time without acceleration (each
// block at its velocity throughout) is kept too: a machine in continuous-path mode (G64) lies
// between the two. Dwells (G4 F, G4 S) are added. docs/output-formats.md "Time estimate".
#pragma once

#include <array>

#include "ncoffset/path.hpp"

namespace ncoffset::out {

struct AxisDynamics {
  std::array<double, 3> max_velocity{10000, 10000, 10000};  // mm/min, MD32000 per X, Y, Z
  std::array<double, 3> max_acceleration{1, 1, 1};          // m/s2, MD32300 per X, Y, Z
};

class TimeEstimate {
 public:
  // Values that are not positive numbers keep the default (an unknown machine datum).
  void setDynamics(const AxisDynamics& d);
  void segment(const Segment& s);
  void spindle(const SpindleEvent& e) {
    if (e.spindle <= 1) speed_ = e.speed;  // the master spindle (no address extension or S1)
  }
  void dwell(const DwellEvent& e);

  double seconds() const { return with_accel_; }            // trapezoid per block
  double secondsNoAccel() const { return without_accel_; }  // velocity throughout
  double rapidSeconds() const { return rapid_; }
  double dwellSeconds() const { return dwell_; }
  // G95 blocks without a spindle speed: not in the estimate.
  long long blocksWithoutSpeed() const { return no_speed_; }

 private:
  AxisDynamics dyn_;
  double speed_ = 0;  // rev/min
  double with_accel_ = 0, without_accel_ = 0, rapid_ = 0, dwell_ = 0;
  long long no_speed_ = 0;
};

// The time (s) of `length` mm at `v` mm/s with acceleration `a` mm/s2 from and to standstill.
double trapezoidSeconds(double length, double v, double a);

}  // namespace ncoffset::out
