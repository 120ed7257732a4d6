// The state of contour definitions and the extra circle forms (PM-NC 12/2019 "Contour
// definitions", "Chamfer, rounding", "Polar coordinates", "Circular interpolation" CIP/CT;
// docs/contour-definitions.md). Kept out of BlockWords so that a block without these words pays
// nothing for them: BlockWords::contour says whether ContourWords holds anything.
#pragma once

#include <optional>

#include "interp/corner_stage.hpp"
#include "interp/modal_state.hpp"
#include "interp/motion_builder.hpp"

namespace ncoffset::interp {

enum class CircleForm : unsigned char { Plain, Cip, Ct };

// The contour words of one block.
struct ContourWords {
  CornerRequest::Kind corner = CornerRequest::Kind::None;  // CHF=, CHR=, RND=
  double corner_value = 0;                                 // mm
  std::optional<double> frc, frcm, rndm, ang, ap, rp;
  lang::AxisMode ap_mode = lang::AxisMode::Default, rp_mode = lang::AxisMode::Default;
  bool inter[3] = {false, false, false};  // I1=, J1=, K1= (CIP intermediate point)
  double inter_value[3] = {0, 0, 0};
  lang::AxisMode inter_mode[3] = {lang::AxisMode::Default, lang::AxisMode::Default,
                                  lang::AxisMode::Default};
  int pole = 0;                      // G110, G111, G112 in this block
  std::optional<CircleForm> circle;  // CIP or CT in this block
};

// The first block of a contour definition with two angles (`ANG=a1` alone): its end point is the
// intersection with the next block's line, so it is built when that block comes.
struct PendingLine {
  BlockWords words;
  ModalState modal;
  BlockContext at;
  CornerRequest request;
  Vec3 start;
  double angle = 0;  // degrees
};

struct ContourState {
  double rndm = 0;                        // RNDM= (0: off)
  double frcm = 0;                        // FRCM= (0: off)
  CircleForm circle = CircleForm::Plain;  // group 1: CIP/CT modal
  Vec3 pole;                              // WCS; the WCS zero until G110/G111/G112
  double ap = 0, rp = 0;                  // the last polar angle (degrees) and radius (mm)
  Plane polar_plane = Plane::G17;         // the plane AP belongs to
  std::optional<PendingLine> pending;
};

// Sets axis (or circle centre) `axis` of `w` to the absolute position `mm` as the words of a
// block would write it under `m` (G70 inch, diameter programming).
inline void setAbsoluteWord(BlockWords& w, const ModalState& m, int axis, double mm, bool centre) {
  const bool inch = m.units == Units::G70 || m.units == Units::G700;
  const double value = mm / (inch ? 25.4 : 1.0) / m.diam_abs[axis];
  (centre ? w.centre : w.axis)[axis] = true;
  (centre ? w.centre_value : w.axis_value)[axis] = value;
  (centre ? w.centre_mode : w.axis_mode)[axis] = lang::AxisMode::AC;
}

}  // namespace ncoffset::interp
