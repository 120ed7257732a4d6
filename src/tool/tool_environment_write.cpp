// SETTCOR (W1 "Working with tool environments", "Changing tool components"; 828D FM 09/2011
// 18.12): writes one component of an edge ($TC_DP.., $TC_SCP.., $TC_ECP..) so that the tool
// changes as asked, in the tool environment GETTCOR reads in. The WCS directions use the same
// length vector as GETTCOR and the path (tool_offsets.cpp lengthVector), so what SETTCOR writes
// GETTCOR reads back. Like any write of the offset memory it acts from the next edge selection
// (W1 2.5). docs/tool-offsets.md section 14a.
#include <fmt/format.h>

#include <cmath>

#include "ncoffset/alarm.hpp"
#include "tool/settcor.hpp"
#include "tool/tool_selection.hpp"

namespace ncoffset::tool {

namespace {

// The nine parameters 3..11 (L1, L2, L3, radius, $TC_DP7..11 or their wear, sum and setup
// counterparts) of component `c`; the base dimension has only L1..L3.
std::array<double*, 9> componentParams(ToolComponent c, EdgeData& e, SumOffsetMemory::Set* set) {
  std::array<double*, 9> p{};
  for (size_t k = 0; k < 9; ++k) {
    switch (c) {
      case ToolComponent::Geometry:
        p[k] = &e.dp[3 + k];
        break;
      case ToolComponent::Wear:
        p[k] = &e.dp[12 + k];
        break;
      case ToolComponent::Base:
        p[k] = k < 3 ? &e.dp[21 + k] : nullptr;
        break;
      default:
        p[k] = &(*set)[k];
    }
  }
  return p;
}

// The map from the component's L1, L2, L3 to its contribution to the tool vector in the
// environment: column k is the vector of L_k = 1 under the rules the path uses (plane,
// SD42900..SD42950, mirroring; sum and setup offsets count as wear), turned into the WCS unless
// `tool_coords`. A signed permutation times the frame's rotation: orthonormal.
Mat3 componentMap(const EdgeData& e, ToolComponent c, const ToolEnvironment& env,
                  bool tool_coords) {
  Mat3 a;
  for (size_t k = 0; k < 3; ++k) {
    EdgeData unit;
    unit.dp[1] = e.dp[1];
    unit.dp[2] = e.dp[2];
    const size_t slot = c == ToolComponent::Geometry ? 3 : c == ToolComponent::Base ? 21 : 12;
    unit.dp[slot + k] = 1;
    Vec3 col = lengthVector(unit, env.settings, env.plane, env.mirrored);
    if (!tool_coords) col = env.orientation * col;
    for (int r = 0; r < 3; ++r) a.m[r][k] = col[r];
  }
  return a;
}

// The new L1..L3 for _CORCOMP 0 (one geometry axis) and 1 (the vector): Val1's contribution in
// the WCS (or TCS) takes the value (units digit 0) or gets it added (1).
std::array<double, 3> directedLengths(const std::array<double, 3>& old, const Mat3& a,
                                      const SettcorRequest& r, Plane plane) {
  Vec3 w = a * Vec3{old[0], old[1], old[2]};
  const bool add = r.cormode % 10 == 1;
  if (r.corcomp == 0) {
    w[r.geoax] = (add ? w[r.geoax] : 0.0) + r.value[0];
  } else {  // _CORVAL: abscissa, ordinate, applicate of the environment's plane
    const PlaneAxes pa = planeAxes(plane);
    const int axes[3] = {pa.abscissa, pa.ordinate, pa.applicate};
    for (size_t i = 0; i < 3; ++i) w[axes[i]] = (add ? w[axes[i]] : 0.0) + r.value[i];
  }
  const Vec3 l = a.inverse() * w;
  return {l[0] + 0.0, l[1] + 0.0, l[2] + 0.0};
}

}  // namespace

int ToolSelection::setToolCorrection(const SettcorRequest& r, const ToolEnvironment& env) {
  SettcorComponents c;
  if (int st = parseSettcorComponents(r.comp, c)) return st;
  if (int st = checkSettcorModes(r.corcomp, r.cormode)) return st;
  if (!settcorModelled(c, r.cormode))
    raise(AlarmNumber::NotModelled,
          c.count == 2 ? std::string("SETTCOR with two components in _COMP (Val1 and Val2, which "
                                     "_CORMODE's algorithms combine) is not modelled by ncoffset")
                       : fmt::format("SETTCOR with _CORMODE {} is not modelled by ncoffset: only "
                                     "0 (Val1 takes the value) and 1 (the value is added)",
                                     r.cormode));
  if (r.corcomp == 0 && (r.geoax < 0 || r.geoax > 2)) return -13;
  if (env.t < 0 || env.t > kMaxTool || (!dconf_.flat && !tools_.tool(env.t))) return -4;
  if (env.d <= 0 || env.d > dconf_.max_d) return -5;
  if (env.dl < 0 || env.dl > sum_limits_.max_per_edge) return -6;
  const int t = dconf_.flat ? 0 : env.t;
  if (!tools_.edge(t, env.d)) return -5;
  const bool sum = c.val1 == ToolComponent::Sum || c.val1 == ToolComponent::Setup;
  if (c.val1 == ToolComponent::Setup && !sum_limits_.setup_offsets) return -14;
  // A DL the edge does not have is invalid whatever the component (as for GETTCOR); S and E
  // need one.
  if (env.dl > 0 ? !sums_.exists(t, env.d, env.dl) : sum) return -6;
  if (c.val1 == ToolComponent::Base && r.corcomp >= 6) return -3;  // no radius, no DP7..11 [M]

  EdgeData& e = tools_.edgeForWrite(t, env.d);
  SumOffsetMemory::Set* set =
      sum ? &sums_.forWrite(c.val1 == ToolComponent::Setup, t, env.d, env.dl) : nullptr;
  const std::array<double*, 9> p = componentParams(c.val1, e, set);
  const bool add = r.cormode % 10 == 1;
  std::array<double, 9> next;
  for (size_t k = 0; k < 9; ++k) next[k] = p[k] ? *p[k] : 0.0;
  if (r.corcomp <= 1) {
    const Mat3 a = componentMap(e, c.val1, env, c.tool_coords);
    const auto l = directedLengths({next[0], next[1], next[2]}, a, r, env.plane);
    for (size_t k = 0; k < 3; ++k) next[k] = l[k];
  } else if (r.corcomp == 2) {  // L1, L2, L3 of Val1, in the tool's own components
    for (size_t k = 0; k < 3; ++k) next[k] = (add ? next[k] : 0.0) + r.value[k];
  } else {  // 3..5 one length, 6 the radius, 7..11 $TC_DP7..11 (or their counterparts)
    const auto k = static_cast<size_t>(r.corcomp - 3);
    next[k] = (add ? next[k] : 0.0) + r.value[0];
  }
  for (size_t k = 0; k < 9; ++k)
    if (!(std::fabs(next[k]) <= 1e9))
      raise(AlarmNumber::ValueRange,
            fmt::format("value range exceeded: SETTCOR gives parameter {} the value {}", k + 3,
                        next[k]));
  // The parameters SETTCOR writes: L1..L3 for _CORCOMP 0..2, else the one it names.
  const size_t first = r.corcomp <= 2 ? 0 : static_cast<size_t>(r.corcomp - 3);
  const size_t last = r.corcomp <= 2 ? 2 : first;
  for (size_t k = first; k <= last; ++k) {
    *p[k] = next[k];
    if (!sum) chainGrindingEdges(t, env.d, static_cast<int>(p[k] - e.dp.data()));  // $TC_TPG2
  }
  return 0;
}

}  // namespace ncoffset::tool
