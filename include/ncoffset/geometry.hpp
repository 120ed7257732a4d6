// Small vector and matrix types for the compensation geometry (double precision, mm).
#pragma once

#include <array>
#include <cmath>
#include <numbers>

namespace ncoffset {

// pi and the degree conversions, the one definition of the tree.
inline constexpr double kPi = std::numbers::pi;
inline constexpr double kRadPerDegree = kPi / 180.0;
inline constexpr double kDegreePerRad = 180.0 / kPi;

struct Vec3 {
  double x = 0, y = 0, z = 0;
  double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  friend Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
  friend double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
  friend Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
  }
  friend double norm(Vec3 a) { return std::sqrt(dot(a, a)); }
};

// Row-major 3x3 matrix: m[row][col].
struct Mat3 {
  std::array<std::array<double, 3>, 3> m{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  static Mat3 identity() { return {}; }
  static Mat3 diagonal(Vec3 d) {
    Mat3 r;
    r.m = {{{d.x, 0, 0}, {0, d.y, 0}, {0, 0, d.z}}};
    return r;
  }
  friend Vec3 operator*(const Mat3& a, Vec3 v) {
    return {a.m[0][0] * v.x + a.m[0][1] * v.y + a.m[0][2] * v.z,
            a.m[1][0] * v.x + a.m[1][1] * v.y + a.m[1][2] * v.z,
            a.m[2][0] * v.x + a.m[2][1] * v.y + a.m[2][2] * v.z};
  }
  friend Mat3 operator*(const Mat3& a, const Mat3& b) {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        r.m[i][j] = a.m[i][0] * b.m[0][j] + a.m[i][1] * b.m[1][j] + a.m[i][2] * b.m[2][j];
    return r;
  }
  double determinant() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  }
  // Inverse by the adjugate; the caller guarantees a non-zero determinant.
  Mat3 inverse() const {
    double d = determinant();
    Mat3 r;
    r.m[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) / d;
    r.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / d;
    r.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / d;
    r.m[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) / d;
    r.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / d;
    r.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / d;
    r.m[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) / d;
    r.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / d;
    r.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / d;
    return r;
  }
  Mat3 transposed() const {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = m[j][i];
    return r;
  }
};

// An affine map p' = linear * p + offset (a frame's action on points).
struct Affine {
  Mat3 linear;
  Vec3 offset;
  Vec3 apply(Vec3 p) const { return linear * p + offset; }
  // Exactly the identity (no frame active, the usual case): the hot paths skip the products.
  bool isIdentity() const {
    return linear.m == Mat3::identity().m && offset.x == 0 && offset.y == 0 && offset.z == 0;
  }
  Affine inverse() const {
    Mat3 inv = linear.inverse();
    return {inv, -1.0 * (inv * offset)};
  }
  friend Affine operator*(const Affine& a, const Affine& b) {
    return {a.linear * b.linear, a.linear * b.offset + a.offset};
  }
};

// Working plane (G group 6). Axis indices 0=X, 1=Y, 2=Z of the geometry axes.
enum class Plane { G17, G18, G19 };

// W1 2.1 / spec §2.1: abscissa, ordinate, applicate of each plane.
struct PlaneAxes {
  int abscissa, ordinate, applicate;
};
constexpr PlaneAxes planeAxes(Plane p) {
  switch (p) {
    case Plane::G17:
      return {0, 1, 2};
    case Plane::G18:
      return {2, 0, 1};
    case Plane::G19:
      return {1, 2, 0};
  }
  return {0, 1, 2};
}

}  // namespace ncoffset
