// Frames (include/ncoffset/frame.hpp, geometry.hpp): RPY rotations, the frame's affine action,
// chaining and the additive (A...) commands, matrix helpers.
#include "ncoffset/frame.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ncoffset {
namespace {

constexpr double kTol = 1e-9;

::testing::AssertionResult near(Vec3 a, Vec3 b, double tol = kTol) {
  if (std::fabs(a.x - b.x) <= tol && std::fabs(a.y - b.y) <= tol && std::fabs(a.z - b.z) <= tol)
    return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "(" << a.x << ", " << a.y << ", " << a.z << ") vs ("
                                       << b.x << ", " << b.y << ", " << b.z << ")";
}

::testing::AssertionResult near(const Mat3& a, const Mat3& b, double tol = kTol) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::fabs(a.m[i][j] - b.m[i][j]) > tol)
        return ::testing::AssertionFailure()
               << "element [" << i << "][" << j << "]: " << a.m[i][j] << " vs " << b.m[i][j];
  return ::testing::AssertionSuccess();
}

TEST(Rotation, AboutEachAxisIsRightHanded) {
  EXPECT_TRUE(near(rotationAbout(2, 90) * Vec3{1, 0, 0}, {0, 1, 0}));
  EXPECT_TRUE(near(rotationAbout(0, 90) * Vec3{0, 1, 0}, {0, 0, 1}));
  EXPECT_TRUE(near(rotationAbout(1, 90) * Vec3{0, 0, 1}, {1, 0, 0}));
  EXPECT_TRUE(near(rotationAbout(2, -90) * Vec3{1, 0, 0}, {0, -1, 0}));
  double h = std::sqrt(0.5);
  EXPECT_TRUE(near(rotationAbout(2, 45) * Vec3{1, 0, 0}, {h, h, 0}));
}

TEST(Rotation, MultiplesOf90AreExact) {
  Mat3 r = rotationAbout(2, 90);
  EXPECT_EQ(r.m[0][0], 0.0);
  EXPECT_EQ(r.m[1][0], 1.0);
  Mat3 s = rotationAbout(0, -270);
  EXPECT_EQ(s.m[2][1], 1.0);
  EXPECT_EQ(s.m[1][1], 0.0);
  Mat3 t = rotationAbout(1, 540);
  EXPECT_EQ(t.m[0][0], -1.0);
}

TEST(Rotation, RpyOrderIsZThenYThenX) {
  Vec3 a{10, 20, 30};
  Mat3 expected = rotationAbout(2, 30) * rotationAbout(1, 20) * rotationAbout(0, 10);
  EXPECT_TRUE(near(rpyMatrix(a), expected));
  // ROT Z90 Y90: X axis -> Y' ... the point (0,0,1) goes to Rz(Ry(z)) = Rz(x) = y.
  EXPECT_TRUE(near(rpyMatrix({0, 90, 90}) * Vec3{0, 0, 1}, {0, 1, 0}));
}

TEST(Rotation, RpyAnglesRoundTrip) {
  const Vec3 cases[] = {{0, 0, 0},     {10, 20, 30},   {-170, 45, 100}, {179, -89, -179},
                        {90, 0, 0},    {0, 0, -90},    {30, -60, 150},  {-45, 89.5, 0},
                        {0.001, 0, 0}, {120, 10, -120}};
  for (Vec3 a : cases) {
    Vec3 b = rpyAngles(rpyMatrix(a));
    EXPECT_TRUE(near(b, a, 1e-8)) << a.x << " " << a.y << " " << a.z;
  }
}

TEST(Rotation, RpyAnglesUseUniqueRanges) {
  // Z 270 is reported as Z -90; the matrix is kept.
  Vec3 a = rpyAngles(rpyMatrix({0, 0, 270}));
  EXPECT_TRUE(near(a, {0, 0, -90}));
  // Y beyond 90: X 0 Y 120 Z 0 == X 180 Y 60 Z 180.
  Vec3 b = rpyAngles(rpyMatrix({0, 120, 0}));
  EXPECT_TRUE(near(rpyMatrix(b), rpyMatrix({0, 120, 0})));
  EXPECT_LE(std::fabs(b.y), 90.0);
  EXPECT_NEAR(b.y, 60, 1e-9);
  EXPECT_NEAR(std::fabs(b.x), 180, 1e-9);
  EXPECT_NEAR(std::fabs(b.z), 180, 1e-9);
  Vec3 c = rpyAngles(rpyMatrix({180, 0, 0}));
  EXPECT_NEAR(std::fabs(c.x), 180, 1e-9);
  EXPECT_NEAR(c.y, 0, 1e-9);
  EXPECT_NEAR(c.z, 0, 1e-9);
}

TEST(Rotation, GimbalLockPutsEverythingIntoX) {
  for (double y : {90.0, -90.0}) {
    Vec3 in{10, y, 25};
    Vec3 a = rpyAngles(rpyMatrix(in));
    EXPECT_EQ(a.y, y);
    EXPECT_EQ(a.z, 0);
    EXPECT_TRUE(near(rpyMatrix(a), rpyMatrix(in)));
  }
  EXPECT_NEAR(rpyAngles(rpyMatrix({10, 90, 25})).x, -15, 1e-9);
  EXPECT_NEAR(rpyAngles(rpyMatrix({10, -90, 25})).x, 35, 1e-9);
  // Nearly locked: still the same matrix.
  Vec3 near_lock{40, 90 - 1e-7, -30};
  EXPECT_TRUE(near(rpyMatrix(rpyAngles(rpyMatrix(near_lock))), rpyMatrix(near_lock), 1e-8));
}

TEST(FrameTest, IdentityByDefault) {
  Frame f;
  EXPECT_TRUE(f.isIdentity());
  EXPECT_TRUE(near(f.affine().apply({1, 2, 3}), {1, 2, 3}));
  f.fine.x = 1e-3;
  EXPECT_FALSE(f.isIdentity());
  Frame g;
  g.mirror[2] = true;
  EXPECT_FALSE(g.isIdentity());
  Frame h;
  h.scale.y = 2;
  EXPECT_FALSE(h.isIdentity());
}

TEST(FrameTest, AffineAppliesMirrorScaleRotationTranslationInOrder) {
  Frame f;
  f.coarse = {1, 2, 3};
  f.fine = {0.5, 0, 0};
  f.rotation = {0, 0, 90};
  f.scale = {2, 2, 2};
  f.mirror = {true, false, false};
  // (1,0,0) -> mirror X (-1,0,0) -> scale (-2,0,0) -> Rz90 (0,-2,0) -> + (1.5,2,3)
  EXPECT_TRUE(near(f.affine().apply({1, 0, 0}), {1.5, 0, 3}));
  // (0,1,0) -> (0,1,0) -> (0,2,0) -> (-2,0,0) -> (-0.5,2,3)
  EXPECT_TRUE(near(f.affine().apply({0, 1, 0}), {-0.5, 2, 3}));
  EXPECT_TRUE(near(f.affine().apply({0, 0, 1}), {1.5, 2, 5}));
  EXPECT_LT(f.affine().linear.determinant(), 0);
}

TEST(FrameTest, TranslationOnly) {
  Frame f;
  f.coarse = {10, 20, 30};
  EXPECT_TRUE(near(f.affine().apply({1, 1, 1}), {11, 21, 31}));
  Affine inv = f.affine().inverse();
  EXPECT_TRUE(near(inv.apply({11, 21, 31}), {1, 1, 1}));
}

TEST(FrameTest, NonUniformScale) {
  Frame f;
  f.scale = {2, 3, 4};
  f.rotation = {0, 0, 90};
  EXPECT_TRUE(near(f.affine().apply({1, 1, 1}), {-3, 2, 4}));
}

TEST(FrameTest, AddTranslationActsInTheRotatedSystem) {
  Frame f;
  f.coarse = {100, 0, 0};
  f.rotation = {0, 0, 90};
  f.addTranslation({10, 0, 0});
  EXPECT_TRUE(near(f.coarse, {100, 0, 0}));
  EXPECT_TRUE(near(f.coarse + f.fine, {100, 10, 0}));
  EXPECT_TRUE(near(f.affine().apply({0, 0, 0}), {100, 10, 0}));
  EXPECT_TRUE(near(f.affine().apply({1, 0, 0}), {100, 11, 0}));
}

TEST(FrameTest, AddTranslationIsScaledAndMirrored) {
  Frame f;
  f.scale = {2, 2, 2};
  f.mirror = {false, true, false};
  f.addTranslation({1, 1, 0});
  EXPECT_TRUE(near(f.coarse + f.fine, {2, -2, 0}));
}

TEST(FrameTest, AddRotationComposesAngles) {
  Frame f;
  f.rotation = {0, 0, 30};
  f.addRotation(rotationAbout(2, 60));
  EXPECT_TRUE(near(f.rotation, {0, 0, 90}));

  Frame g;
  g.rotation = {0, 0, 90};
  g.addRotation(rotationAbout(0, 90));  // AROT X90 inside ROT Z90
  EXPECT_TRUE(near(g.rotationMatrix(), rotationAbout(2, 90) * rotationAbout(0, 90)));
  EXPECT_TRUE(near(g.rotation, {90, 0, 90}));

  // A rotation keeps the translation.
  Frame h;
  h.coarse = {5, 0, 0};
  h.addRotation(rotationAbout(2, 90));
  EXPECT_TRUE(near(h.affine().apply({1, 0, 0}), {5, 1, 0}));
}

TEST(FrameTest, AddRotationInsideAMirroredSystem) {
  // Spec §7: an A-command after MIRROR is expressed in the mirrored system, so
  // MIRROR X0 + AROT Z30 maps p to Mirror(X) * Rz(30) * p (the rotation turns the other way
  // when seen in the parent system).
  Frame f;
  f.mirror = {true, false, false};
  f.addRotation(rotationAbout(2, 30));
  Mat3 expected = Mat3::diagonal({-1, 1, 1}) * rotationAbout(2, 30);
  EXPECT_TRUE(near(f.affine().linear, expected));
  EXPECT_TRUE(near(f.affine().apply({1, 0, 0}), expected * Vec3{1, 0, 0}));
}

TEST(FrameTest, ChainWithMirrorInTheOuterFrame) {
  Frame a;
  a.mirror = {false, true, false};
  a.coarse = {0, 5, 0};
  Frame b;
  b.rotation = {0, 0, 30};
  b.coarse = {2, 1, 0};
  Frame c = chain(a, b);
  for (Vec3 p : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{2, -3, 1}})
    EXPECT_TRUE(near(c.affine().apply(p), a.affine().apply(b.affine().apply(p))));
}

TEST(FrameTest, AddScaleAndMirror) {
  Frame f;
  f.addScale({2, 3, 1});
  f.addScale({0.5, 2, 4});
  EXPECT_TRUE(near(f.scale, {1, 6, 4}));
  f.addMirror(0);
  EXPECT_TRUE(f.mirror[0]);
  f.addMirror(0);
  EXPECT_FALSE(f.mirror[0]);
  f.addMirror(2);
  EXPECT_TRUE(f.mirror[2]);
}

TEST(FrameTest, ChainEqualsCompositionOfActions) {
  Frame a;
  a.coarse = {10, 0, 0};
  a.rotation = {0, 0, 90};
  a.scale = {2, 2, 2};
  Frame b;
  b.coarse = {5, 1, 0};
  b.fine = {0, 0, 1};
  b.rotation = {30, 0, 0};
  b.scale = {1, 1, 3};
  Frame c = chain(a, b);
  for (Vec3 p : {Vec3{0, 0, 0}, Vec3{1, 2, 3}, Vec3{-4, 0.5, 7}}) {
    Vec3 expected = a.affine().apply(b.affine().apply(p));
    EXPECT_TRUE(near(c.affine().apply(p), expected));
  }
  // The left frame is not changed.
  EXPECT_TRUE(near(a.coarse, {10, 0, 0}));
}

TEST(FrameTest, ChainWithMirrorInTheInnerFrame) {
  Frame a;
  a.coarse = {0, 10, 0};
  a.rotation = {0, 0, 45};
  Frame b;
  b.mirror = {true, false, false};
  b.coarse = {1, 0, 0};
  Frame c = chain(a, b);
  for (Vec3 p : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{2, -3, 1}})
    EXPECT_TRUE(near(c.affine().apply(p), a.affine().apply(b.affine().apply(p))));
}

TEST(FrameTest, ChainWithIdentity) {
  Frame a;
  a.coarse = {1, 2, 3};
  a.rotation = {10, 20, 30};
  Frame id;
  EXPECT_TRUE(near(chain(a, id).affine().apply({4, 5, 6}), a.affine().apply({4, 5, 6})));
  EXPECT_TRUE(near(chain(id, a).affine().apply({4, 5, 6}), a.affine().apply({4, 5, 6})));
}

// ---- matrix helpers --------------------------------------------------------------------------

TEST(Mat3Test, InverseAndDeterminant) {
  Mat3 m;
  m.m = {{{2, 1, 0}, {0, 3, -1}, {4, 0, 5}}};
  EXPECT_DOUBLE_EQ(m.determinant(), 2 * 15 - 1 * (0 + 4) + 0);
  EXPECT_TRUE(near(m * m.inverse(), Mat3::identity(), 1e-12));
  EXPECT_TRUE(near(m.inverse() * m, Mat3::identity(), 1e-12));
  Mat3 r = rpyMatrix({10, 20, 30});
  EXPECT_TRUE(near(r.inverse(), r.transposed(), 1e-12));
  EXPECT_NEAR(r.determinant(), 1, 1e-12);
  EXPECT_TRUE(near(Mat3::diagonal({2, 4, -1}).inverse(), Mat3::diagonal({0.5, 0.25, -1})));
}

TEST(Mat3Test, AffineInverseAndProduct) {
  Affine a{rpyMatrix({0, 0, 90}) * Mat3::diagonal({2, 2, 2}), {1, 2, 3}};
  Affine inv = a.inverse();
  Vec3 p{3, -1, 2};
  EXPECT_TRUE(near(inv.apply(a.apply(p)), p));
  Affine b{rotationAbout(0, 30), {0, 5, 0}};
  EXPECT_TRUE(near((a * b).apply(p), a.apply(b.apply(p))));
}

TEST(Vec3Test, Operations) {
  Vec3 a{1, 2, 3}, b{4, 5, 6};
  EXPECT_DOUBLE_EQ(dot(a, b), 32);
  EXPECT_TRUE(near(cross(Vec3{1, 0, 0}, Vec3{0, 1, 0}), {0, 0, 1}));
  EXPECT_DOUBLE_EQ(norm(Vec3{3, 4, 0}), 5);
  a[2] = 7;
  EXPECT_EQ(a.z, 7);
  EXPECT_TRUE(near(b - a, {3, 3, -1}));
}

TEST(PlaneTest, AxesOfEachPlane) {
  PlaneAxes g17 = planeAxes(Plane::G17), g18 = planeAxes(Plane::G18), g19 = planeAxes(Plane::G19);
  EXPECT_EQ(g17.abscissa, 0);
  EXPECT_EQ(g17.ordinate, 1);
  EXPECT_EQ(g17.applicate, 2);
  EXPECT_EQ(g18.abscissa, 2);
  EXPECT_EQ(g18.ordinate, 0);
  EXPECT_EQ(g18.applicate, 1);
  EXPECT_EQ(g19.abscissa, 1);
  EXPECT_EQ(g19.ordinate, 2);
  EXPECT_EQ(g19.applicate, 0);
}

}  // namespace
}  // namespace ncoffset
