// K2 frames: component model and its action on points. RPY convention (MD10600 = 1):
// rotation about Z, then about the new Y', then about the new X''.
#include "ncoffset/frame.hpp"

#include <cmath>

namespace ncoffset {
namespace {
constexpr double kDeg = kRadPerDegree;

// Exact values for multiples of 90 degrees keep the geometry free of 1e-17 noise.
void sinCos(double degrees, double& s, double& c) {
  double r = std::fmod(degrees, 360.0);
  if (r < 0) r += 360.0;
  if (r == 0) {
    s = 0;
    c = 1;
    return;
  }
  if (r == 90) {
    s = 1;
    c = 0;
    return;
  }
  if (r == 180) {
    s = 0;
    c = -1;
    return;
  }
  if (r == 270) {
    s = -1;
    c = 0;
    return;
  }
  s = std::sin(degrees * kDeg);
  c = std::cos(degrees * kDeg);
}
}  // namespace

Mat3 rotationAbout(int axis, double degrees) {
  double s, c;
  sinCos(degrees, s, c);
  Mat3 r;
  switch (axis) {
    case 0:
      r.m = {{{1, 0, 0}, {0, c, -s}, {0, s, c}}};
      break;
    case 1:
      r.m = {{{c, 0, s}, {0, 1, 0}, {-s, 0, c}}};
      break;
    default:
      r.m = {{{c, -s, 0}, {s, c, 0}, {0, 0, 1}}};
      break;
  }
  return r;
}

Mat3 rpyMatrix(Vec3 deg) {
  return rotationAbout(2, deg.z) * rotationAbout(1, deg.y) * rotationAbout(0, deg.x);
}

Vec3 rpyAngles(const Mat3& r) {
  // R = Rz(c) Ry(b) Rx(a): r20 = -sin b, r21 = cos b sin a, r22 = cos b cos a,
  // r10 = sin c cos b, r00 = cos c cos b.
  double sb = -r.m[2][0];
  sb = std::fmax(-1.0, std::fmin(1.0, sb));
  Vec3 out;
  if (std::fabs(sb) > 1 - 1e-12) {
    // Gimbal lock: put everything into the rotation about X.
    out.y = sb > 0 ? 90 : -90;
    out.z = 0;
    out.x = std::atan2(sb > 0 ? r.m[0][1] : -r.m[0][1], r.m[1][1]) / kDeg;
  } else {
    out.y = std::asin(sb) / kDeg;
    out.x = std::atan2(r.m[2][1], r.m[2][2]) / kDeg;
    out.z = std::atan2(r.m[1][0], r.m[0][0]) / kDeg;
  }
  auto clean = [](double v) {
    double n = std::round(v * 1e9) / 1e9;
    return std::fabs(v - n) < 1e-9 ? n + 0.0 : v;
  };
  return {clean(out.x), clean(out.y), clean(out.z)};
}

bool Frame::isIdentity() const {
  for (int i = 0; i < 3; ++i) {
    if (coarse[i] != 0 || fine[i] != 0 || rotation[i] != 0 || scale[i] != 1 ||
        mirror[static_cast<size_t>(i)])
      return false;
  }
  return true;
}

Mat3 Frame::rotationMatrix() const {
  return rpyMatrix(rotation);
}

Affine Frame::affine() const {
  Vec3 sm{scale.x * (mirror[0] ? -1 : 1), scale.y * (mirror[1] ? -1 : 1),
          scale.z * (mirror[2] ? -1 : 1)};
  return {rotationMatrix() * Mat3::diagonal(sm), coarse + fine};
}

Frame chain(const Frame& a, const Frame& b) {
  Frame r = a;
  // Coarse with coarse and fine with fine, each carried by a's rotation, scale and mirror
  // (a TRANS never becomes a fine offset; PM-NC p315).
  const Mat3 la = a.affine().linear;
  r.coarse = a.coarse + la * b.coarse;
  r.fine = a.fine + la * b.fine;
  if (b.rotation.x != 0 || b.rotation.y != 0 || b.rotation.z != 0)
    r.addRotation(b.rotationMatrix());
  r.addScale(b.scale);
  for (int i = 0; i < 3; ++i)
    if (b.mirror[static_cast<size_t>(i)]) r.addMirror(i);
  return r;
}

void Frame::addTranslation(Vec3 t) {
  // The offset is given in the inner system: rotated, scaled and mirrored like a point.
  Affine f = affine();
  fine = fine + f.linear * t;
}

void Frame::addRotation(const Mat3& r) {
  // The rotation acts inside the scaled and mirrored system: R·S·M·r = (R·M·r·M)·S·M, since a
  // diagonal mirror M is its own inverse and a (uniform) scale commutes with rotations.
  Mat3 m = Mat3::diagonal({mirror[0] ? -1.0 : 1.0, mirror[1] ? -1.0 : 1.0, mirror[2] ? -1.0 : 1.0});
  rotation = rpyAngles(rotationMatrix() * (m * r * m));
}

void Frame::addScale(Vec3 s) {
  scale = {scale.x * s.x, scale.y * s.y, scale.z * s.z};
}

void Frame::addMirror(int axis) {
  auto a = static_cast<size_t>(axis);
  mirror[a] = !mirror[a];
}

}  // namespace ncoffset
