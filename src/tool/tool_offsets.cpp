// W1 2.5 / spec §2.5: effective lengths and the length vector; spec §4: basic orientation;
// W1 2.11 / details §1: LENTOAX.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "ncoffset/tool.hpp"

namespace ncoffset {
namespace {

// SD42920 (FM 828D p1547): inversion of wear L1 / L2 by cutting edge position SL.
int wearSignByCutPos(int sl, int component) {
  if (component == 0) return (sl == 3 || sl == 4 || sl == 8) ? -1 : 1;
  if (component == 1) return (sl == 2 || sl == 3 || sl == 7) ? -1 : 1;
  return 1;
}

}  // namespace

EffectiveLengths effectiveLengths(const EdgeData& e, const ToolSettings& s) {
  EffectiveLengths r;
  for (int k = 0; k < 3; ++k) {
    auto i = static_cast<size_t>(k);
    r.geometry[i] = e.dp[3 + i] + e.dp[21 + i];
    double wear = e.dp[12 + i];
    if (s.wear_sign) wear = -wear;
    if (s.wear_sign_cutpos && isTurningOrGrindingType(e.type()))
      wear *= wearSignByCutPos(e.cuttingEdgePosition(), k);
    r.wear[i] = wear;
    r.total[i] = r.geometry[i] + wear;
  }
  r.radius = e.dp[6] + (s.wear_sign ? -e.dp[15] : e.dp[15]);
  return r;
}

Vec3 lengthVector(const EdgeData& e, const ToolSettings& s, Plane plane,
                  const std::array<bool, 3>& mirrored) {
  EffectiveLengths l = effectiveLengths(e, s);
  LengthAssignment a = assignLengths(e.type(), plane, s.length_const, s.length_type);
  Vec3 v;
  for (size_t k = 0; k < 3; ++k) {
    int axis = a.axis[k];
    double geo = l.geometry[k], wear = l.wear[k];
    if (mirrored[static_cast<size_t>(axis)]) {
      if (s.mirror_length) geo = -geo;
      if (s.mirror_wear) wear = -wear;
    }
    v[axis] += a.sign[k] * (geo + wear);
  }
  return v;
}

Vec3 toolOrientation(const EdgeData& e, const ToolSettings& s, Plane plane,
                     const std::array<bool, 3>& mirrored) {
  LengthAssignment a = assignLengths(e.type(), plane, s.length_const, s.length_type);
  bool turning = s.length_type == 1   ? false
                 : s.length_type == 2 ? true
                                      : isTurningOrGrindingType(e.type());
  // The orientation in the components L1, L2, L3 (DPV3, DPV4, DPV5).
  std::array<double, 3> c{e.dpv3, e.dpv4, e.dpv5};
  if (e.dpv >= 1 && e.dpv <= 6) {
    // The manual's table (FM-W1 11/2006 p131); its example for value 2 is an erratum
    // (docs/tool-offsets.md). Milling: 1 = L1, 2 = L2, 3 = L3 (+Z, +Y, +X in G17); turning:
    // 1 = L3, 2 = L2, 3 = L1 (+Y, +Z, +X in G18); 4..6 the opposite directions.
    int code = (e.dpv - 1) % 3;
    double v = e.dpv <= 3 ? 1 : -1;
    c = {0, 0, 0};
    static constexpr int kMilling[] = {0, 1, 2};
    static constexpr int kTurning[] = {2, 1, 0};
    c[static_cast<size_t>(turning ? kTurning[code] : kMilling[code])] = v;
  }
  Vec3 o;
  if (c[0] == 0 && c[1] == 0 && c[2] == 0) {
    // No orientation data: perpendicular to the plane (its applicate), or with the thousands
    // digit of SD42940 the applicate of the table's plane.
    if (a.constant_orientation) {
      // Milling tools point along L1's axis, turning tools along L3's axis (the applicate of
      // their home plane).
      o[a.axis[turning ? 2 : 0]] = 1;
    } else {
      o[planeAxes(plane).applicate] = 1;
    }
    return o;
  }
  for (size_t k = 0; k < 3; ++k) {
    int axis = a.axis[k];
    double v = a.sign[k] * c[k];
    if (mirrored[static_cast<size_t>(axis)] && s.mirror_length) v = -v;
    o[axis] += v;
  }
  double n = norm(o);
  return n > 0 ? (1.0 / n) * o : o;
}

std::array<double, 2> tipFromEdgeCentre(int sl, double r) {
  // P - S in (L1 axis, L2 axis): 1 (+,+) 2 (+,-) 3 (-,-) 4 (-,+) 5 (0,+) 6 (+,0) 7 (0,-) 8 (-,0).
  static constexpr int kDir[10][2] = {{0, 0}, {1, 1}, {1, -1}, {-1, -1}, {-1, 1},
                                      {0, 1}, {1, 0}, {0, -1}, {-1, 0},  {0, 0}};
  if (sl < 0 || sl > 9) return {0, 0};
  return {kDir[sl][0] * r, kDir[sl][1] * r};
}

Vec3 tipVector(const EdgeData& e, const ToolSettings& s, Plane plane, double r) {
  Vec3 v;
  // W1 "cutting edge position": relevant for turning and grinding tools only.
  if (!isTurningOrGrindingType(e.type())) return v;
  const std::array<double, 2> d = tipFromEdgeCentre(e.cuttingEdgePosition(), r);
  const LengthAssignment a = assignLengths(e.type(), plane, s.length_const, s.length_type);
  for (size_t k = 0; k < 2; ++k) v[a.axis[k]] += a.sign[k] * d[k];
  return v;
}

LentoaxResult lentoax(const EdgeData& e, const ToolSettings& s, Plane plane,
                      const std::array<bool, 3>& mirrored, const Mat3& frame_linear,
                      const std::string& coord_in, const Mat3& carrier) {
  LentoaxResult r;
  std::string coord;
  for (char ch : coord_in)
    coord.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(ch))));
  bool wcs;
  const bool tcs = coord == "TCS" || coord == "T";
  if (coord == "WCS" || coord == "W")
    wcs = true;
  else if (coord == "MCS" || coord == "M" || coord == "BCS" || coord == "B" || coord == "KCS" ||
           coord == "K" || tcs)
    wcs = false;
  else {
    r.status = -1;
    return r;
  }
  // Directions of the geometry components (DP3..5 only: wear rules do not count) in the BCS.
  LengthAssignment a = assignLengths(e.type(), plane, s.length_const, s.length_type);
  std::array<Vec3, 3> dir;
  for (size_t k = 0; k < 3; ++k) {
    int axis = a.axis[k];
    double sign = a.sign[k];
    if (mirrored[static_cast<size_t>(axis)] && s.mirror_length) sign = -sign;
    dir[k][axis] = sign;
    if (!tcs) dir[k] = carrier * dir[k];  // the toolholder turns the tool (docs/toolholders.md)
    if (wcs) {
      // Into the WCS: the inverse of the frame's linear part, normalised (scale drops out).
      Vec3 w = frame_linear.inverse() * dir[k];
      double n = norm(w);
      dir[k] = n > 0 ? (1.0 / n) * w : w;
    }
  }
  PlaneAxes pa = planeAxes(plane);
  const int axes[3] = {pa.abscissa, pa.ordinate, pa.applicate};
  bool parallel = true;
  for (size_t i = 0; i < 3; ++i) {
    int best = -1;
    double best_abs = 1e-9;
    for (size_t k = 0; k < 3; ++k) {
      double m = dir[k][axes[i]];
      if (std::fabs(m) < 1e-12) m = 0;
      r.matrix[i][k] = m;
      double am = std::fabs(m);
      if (am > 1e-9 && std::fabs(am - 1) > 1e-9) parallel = false;
      // Ties (e.g. 45 degrees): the lowest component number wins (details §1.3, to verify).
      if (am > best_abs + 1e-12) {
        best_abs = am;
        best = static_cast<int>(k);
      }
    }
    r.axind[i] = best < 0 ? 0 : (best + 1) * (r.matrix[i][static_cast<size_t>(best)] < 0 ? -1 : 1);
  }
  r.status = parallel ? 0 : 1;
  return r;
}

}  // namespace ncoffset
