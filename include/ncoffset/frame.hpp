// Frames (K2 / PM-NC "Coordinate transformations (frames)"): translation, rotation, scale and
// mirror of the geometry axes X, Y, Z, composed in the control's fixed component order.
#pragma once

#include <array>

#include "ncoffset/geometry.hpp"

namespace ncoffset {

// A frame as the control stores it: per geometry axis a coarse and a fine translation, a
// rotation angle (RPY: about Z, then Y', then X''), a scale factor and a mirror flag.
// It maps child (inner) coordinates to parent coordinates:
//   p_parent = (coarse + fine) + Rz(rz) * Ry(ry) * Rx(rx) * Scale * Mirror * p_child
struct Frame {
  Vec3 coarse;
  Vec3 fine;
  Vec3 rotation;  // degrees about X, Y, Z
  Vec3 scale{1, 1, 1};
  std::array<bool, 3> mirror{false, false, false};

  bool isIdentity() const;
  Mat3 rotationMatrix() const;
  // The whole action on points.
  Affine affine() const;

  // Frame chain operator `A:B` (K2 "chaining frames"): B acts inside A.
  friend Frame chain(const Frame& a, const Frame& b);

  // Programmable-frame commands (PM-NC 309): the non-A forms replace the frame, the A forms act
  // in the already transformed system.
  void addTranslation(Vec3 t);      // ATRANS: t in the current (inner) system
  void addRotation(const Mat3& r);  // AROT
  void addScale(Vec3 s);            // ASCALE
  void addMirror(int axis);         // AMIRROR
};

// Frame chain operator `A:B` (K2): B acts inside A.
Frame chain(const Frame& a, const Frame& b);

// Rotation matrices for the RPY convention. Angles in degrees.
Mat3 rotationAbout(int axis, double degrees);
Mat3 rpyMatrix(Vec3 degrees);
// Angles (about X, Y, Z) of a rotation matrix in the control's unique ranges
// (-180 <= x <= 180, -90 < y < 90 (±90 at the singularity), -180 <= z <= 180).
Vec3 rpyAngles(const Mat3& r);

}  // namespace ncoffset
