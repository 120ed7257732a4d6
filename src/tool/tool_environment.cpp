// Tool environments and GETTCOR (W1 2.10 "Working with tool environments"): the state a
// TOOLENV saves, and the tool's length components, radius and further parameters evaluated in
// such an environment in a chosen coordinate system. The length vector is the one the path
// uses (tool_offsets.cpp lengthVector), so GETTCOR agrees with LENTOAX and $P_TOOLL.
#include <fmt/format.h>

#include <cctype>
#include <cmath>

#include "lang/evaluator.hpp"
#include "ncoffset/alarm.hpp"
#include "tool/tool_selection.hpp"

namespace ncoffset::tool {

using lang::Value;

namespace {

// The components of _COMP (W1: C adapter/base, E setup, G geometry, S sum, W wear; any case,
// blanks allowed, each at most once) and the coordinate system after a colon.
struct Components {
  bool base = false, geometry = false, wear = false, sum = false, setup = false;
  char coord = 'M';  // M (default), B, W, K, T
};

// Status -3 (invalid or repeated character) or -9 (a colon without a coordinate system).
int parseComponents(const std::string& text, Components& c) {
  bool any = false, colon = false, coord_seen = false;
  for (char raw : text) {
    const char ch = static_cast<char>(std::toupper(static_cast<unsigned char>(raw)));
    if (ch == ' ' || ch == '\t') continue;
    if (colon) {
      if (coord_seen || (ch != 'M' && ch != 'B' && ch != 'W' && ch != 'K' && ch != 'T')) return -9;
      c.coord = ch;
      coord_seen = true;
      continue;
    }
    if (ch == ':') {
      colon = true;
      continue;
    }
    bool* flag = ch == 'C'   ? &c.base
                 : ch == 'G' ? &c.geometry
                 : ch == 'W' ? &c.wear
                 : ch == 'S' ? &c.sum
                 : ch == 'E' ? &c.setup
                             : nullptr;
    if (!flag || *flag) return -3;
    *flag = any = true;
  }
  if (colon && !coord_seen) return -9;
  if (!any) c.base = c.geometry = c.wear = true;  // no component: the whole tool [D]
  return 0;
}

// The edge with only the components asked for: the others zeroed (the sum and setup offsets
// are added by the caller, docs/tool-offsets.md section 14).
EdgeData selectComponents(const EdgeData& e, const Components& c) {
  EdgeData out = e;
  for (size_t k = 0; k < 3; ++k) {
    if (!c.geometry) out.dp[3 + k] = 0;
    if (!c.wear) out.dp[12 + k] = 0;
    if (!c.base) out.dp[21 + k] = 0;
  }
  if (!c.geometry) out.dp[6] = 0;
  if (!c.wear) out.dp[15] = 0;
  for (size_t k = 0; k < 5; ++k) {
    if (!c.geometry) out.dp[7 + k] = 0;
    if (!c.wear) out.dp[16 + k] = 0;
  }
  return out;
}

}  // namespace

ToolEnvironment ToolSelection::currentEnvironment(const ToolSettings& s, Plane plane,
                                                  const std::array<bool, 3>& mirrored,
                                                  const Mat3& frame_linear) const {
  ToolEnvironment env;
  env.plane = plane;
  // The offset in force was computed with the data of its selection (W1 2.5).
  env.settings = edge_.valid ? edge_.settings : s;
  env.mirrored = edge_.valid ? edge_.mirrored : mirrored;
  // WCS directions of the BCS axes, normalised: the frame's rotation and mirroring without its
  // scale (W1 2.10.2), the same map LENTOAX uses.
  const Mat3 inv = frame_linear.inverse();
  for (int i = 0; i < 3; ++i) {
    Vec3 axis;
    axis[i] = 1;
    Vec3 w = inv * axis;
    const double n = norm(w);
    if (n > 0) w = (1.0 / n) * w;
    for (int r = 0; r < 3; ++r) env.orientation.m[r][i] = w[r];
  }
  env.t = active_tool_;
  env.d = active_edge_;
  env.dl = active_dl_;
  return env;
}

int ToolSelection::toolCorrection(std::span<Value> len, const std::string& comp,
                                  const ToolEnvironment& env) const {
  Components c;
  if (int st = parseComponents(comp, c)) return st;
  for (auto& v : len) v = Value::real(0);
  if (env.t < 0 || env.t > kMaxTool || (!dconf_.flat && env.t != 0 && !tools_.tool(env.t)))
    return -4;
  if (env.d < 0 || env.d > dconf_.max_d) return -5;
  if (env.dl < 0 || env.dl > sum_limits_.max_per_edge) return -6;
  if (env.d == 0 || (!dconf_.flat && env.t == 0)) return 0;  // no offset: all zero [D]
  const EdgeData* e = tools_.edge(dconf_.flat ? 0 : env.t, env.d);
  if (!e) return -5;
  EdgeData sel = selectComponents(*e, c);
  if (env.dl > 0) {  // S and E: the DL's sets are wear DP12..DP20 (section 10)
    const int t = dconf_.flat ? 0 : env.t;
    if (!sums_.exists(t, env.d, env.dl)) return -6;
    addSumOffsets(sel, sums_, t, env.d, env.dl, sum_limits_, c.sum, c.setup);
  }
  const EffectiveLengths l = ncoffset::effectiveLengths(sel, env.settings);
  Vec3 v = ncoffset::lengthVector(sel, env.settings, env.plane, env.mirrored);
  if (c.coord == 'W') v = env.orientation * v;
  const PlaneAxes pa = planeAxes(env.plane);
  len[0] = Value::real(e->dp[1]);
  len[1] = Value::real(e->dp[2]);
  len[2] = Value::real(v[pa.abscissa] + 0.0);
  len[3] = Value::real(v[pa.ordinate] + 0.0);
  len[4] = Value::real(v[pa.applicate] + 0.0);
  len[5] = Value::real(l.radius);
  for (size_t k = 0; k < 5; ++k) len[6 + k] = Value::real(sel.dp[7 + k] + sel.dp[16 + k]);
  return 0;
}

bool ToolSelection::readEnvironment(std::string_view name, std::span<const Value> idx, bool indexed,
                                    Value& out) const {
  if (name == "$P_TOOLENVN") {
    if (indexed) raise(AlarmNumber::ArrayIndex1, "$P_TOOLENVN takes no index");
    out = Value::integer(static_cast<double>(envs_.size()));
    return true;
  }
  if (name != "$P_TOOLENV") return false;
  if (!indexed || idx.size() != 1) raise(AlarmNumber::ArrayIndex1, "$P_TOOLENV needs [n]");
  const double n = lang::toNumber(idx[0], "index");
  if (n != std::floor(n) || n < 1 || n > static_cast<double>(envs_.size()))
    raise(
        AlarmNumber::ArrayIndex1,
        fmt::format("illegal array index: $P_TOOLENV[{}] (1..$P_TOOLENVN = {})", n, envs_.size()));
  out = Value::string(envs_[static_cast<size_t>(n) - 1].name);
  return true;
}

}  // namespace ncoffset::tool
