// Tool selection of the channel (W1 1, spec §1.1): T, D and M6 with MD22550
// TOOL_CHANGE_MODE and MD20270 CUTTING_EDGE_DEFAULT, the offset memory ($TC_DP.., $TC_DPV..,
// $TC_DPC.., $TC_TP..) and what the active edge gives the path: its radius, its length vector in
// the BCS and its orientation. Data and setting data act from the next edge selection (W1 2.5):
// the selection snapshots them.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lang/value.hpp"
#include "ncoffset/tool.hpp"
#include "tool/programmable_offsets.hpp"
#include "tool/sum_offsets.hpp"
#include "tool/tool_store.hpp"

namespace ncoffset::tool {

// What an edge selection takes from the channel: the setting data SD42900..SD42950, MD20270,
// and the mirroring of the frame active at the selection.
struct SelectionContext {
  ToolSettings settings;
  int default_edge = 1;  // MD20270: 0 no edge, > 0 that edge, -1 keep the old D number
  std::array<bool, 3> mirrored{false, false, false};
  int default_sum_offset = 0;  // MD20272: 0 none, > 0 that DL, -1 keep the DL number
};

// The tool words of one block.
struct ToolWords {
  std::optional<int> tool;          // T
  std::optional<int> edge;          // D
  bool tool_change = false;         // M6 (MD22560) for the master spindle
  std::optional<int> sum_offset{};  // DL= (sum_offsets.cpp)
};

// The D number structure (W1 "Free assignment of D numbers", "Flat D number structure"):
// MD18102 (1: flat, D without T), MD18105 (highest D number), MD18106 (edges per tool).
struct DNumberConfig {
  bool flat = false;
  int max_d = 9;
  int max_per_tool = 9;
  // CHKDNO, GETDNO, SETDNO, DZERO and $TC_DPCE act only when MD18105 > MD18106 (W1).
  bool freeNumbers() const { return max_d > max_per_tool; }
};

struct SettcorRequest;  // settcor.hpp

// A saved tool environment (TOOLENV, W1 "Working with tool environments"): what GETTCOR needs
// to evaluate the tool data later as at the TOOLENV call.
struct ToolEnvironment {
  std::string name;
  Plane plane = Plane::G17;
  ToolSettings settings;
  std::array<bool, 3> mirrored{false, false, false};
  Mat3 orientation;  // rotation and mirroring of the complete frame (WCS -> BCS, no scale)
  int t = 0, d = 0, dl = 0;
};

class ToolSelection {
 public:
  explicit ToolSelection(size_t max_edges) : max_edges_(max_edges) {}

  // D numbers (src/tool/d_numbers.cpp).
  void configure(const DNumberConfig& c) { dconf_ = c; }
  const DNumberConfig& dNumbers() const { return dconf_; }
  struct DCollision {
    int t1 = 0, t2 = 0, d = 0;
  };
  // CHKDNO(t1, t2, d) (0: all): true when unique; else the first collision in `c`.
  bool checkDNumbers(int t1, int t2, int d, DCollision& c) const;
  int getDNumber(int t, int ce) const;                    // GETDNO: 0 none, > 32000 invalidated
  bool setDNumber(int t, int ce, int d);                  // SETDNO
  void invalidateDNumbers();                              // DZERO
  int toolOfDNumber(int d, int& t) const;                 // GETACTTD: status 0, -1, -2, -5
  int toolOfName(const std::string& name, int& t) const;  // GETACTT: status 0, -1
  int cuttingEdgeNumber(int t, int d) const;              // $TC_DPCE[t,d]

  // Tool environments (src/tool/tool_environment.cpp).
  std::vector<ToolEnvironment>& environments() { return envs_; }
  const std::vector<ToolEnvironment>& environments() const { return envs_; }
  ToolEnvironment currentEnvironment(const ToolSettings& s, Plane plane,
                                     const std::array<bool, 3>& mirrored,
                                     const Mat3& orientation) const;
  // GETTCOR: fills len[0..10]; returns the status (0, -2 .. -9).
  int toolCorrection(std::span<lang::Value> len, const std::string& comp,
                     const ToolEnvironment& env) const;
  // SETTCOR (tool_environment_write.cpp): writes one component of env's T, D (DL); returns the
  // status (0, -3 .. -14), alarm 99010 for the parts not modelled.
  int setToolCorrection(const SettcorRequest& r, const ToolEnvironment& env);

  // Executes T, M6 and D of a block (MD22550 = 0: T changes the tool; 1: T preselects, M6
  // changes). Alarms 17191 (tool not existing), 17181 (edge not existing).
  void execute(const ToolWords& w, bool change_on_t, const SelectionContext& ctx);
  // The tool whose $TC_TP2 identifier is `name` (T="name"), alarm 17191 if none.
  int resolveName(const std::string& name) const;

  int activeTool() const { return active_tool_; }
  // The offset memory as it is now (the HTML report's tool table).
  const ToolStore& store() const { return tools_; }
  int activeEdge() const { return active_edge_; }
  // The active sum/setup offset number DL (0: none) and what it adds (sum_offsets.cpp).
  int activeSumOffset() const { return active_dl_; }
  const SumOffsetMemory& sumOffsets() const { return sums_; }
  void setSumOffsetLimits(const SumOffsetLimits& l) { sum_limits_ = l; }
  // TOFFL, TOFF, TOFFR (programmable_offsets.cpp): they act at once on the active edge and stay
  // over a tool change.
  const ProgrammedOffsets& programmed() const { return programmed_; }
  void setProgrammed(const ProgrammedOffsets& p);
  bool hasEdge() const { return edge_.valid; }
  // The compensation radius of the active edge (edge + wear), 0 without an edge.
  // (CUT2DD/CUT2DFD: the radius minus $TC_DP6, the standard tool's: only the deviation is
  // compensated, docs/radius-compensation.md "CUT2D, CUT2DF"; set by setDifferential, so that the
  // block pays nothing for it.)
  double radius() const {
    return edge_.valid ? edge_.radius - differential_ * edge_.data.dp[6] : 0.0;
  }
  void setDifferential(bool on) { differential_ = on ? 1.0 : 0.0; }
  // The BCS vector from the tool tip to the carrier reference point in `plane` (zero without
  // an edge), computed once per selection and plane.
  // (Inline: asked for every linear block.)
  Vec3 lengthVector(Plane plane) const {
    if (!edge_.valid) return {};
    if (!cachedFor(plane)) cache(plane);
    return edge_.cached_offset;
  }
  // The BCS vector P - S of a turning or grinding edge with SL 1..8 in `plane` (zero otherwise;
  // docs/cutting-edge-positions.md), computed with the length vector, once per selection and
  // plane. `hasTip()`: the active edge has one (false for every milling tool).
  Vec3 tipVector(Plane plane) const;
  bool hasTip() const { return edge_.has_tip; }
  // $P_TOOLL / $P_TOOLR: the effective lengths (zero without an edge).
  // (`plane`: where TOFF[axis] acts, docs/tool-offsets.md section 11.)
  EffectiveLengths lengths(Plane plane = Plane::G17) const;
  // $P_TOOLO: the unit orientation (without an edge the plane's applicate).
  Vec3 orientation(Plane plane) const;

  // The active toolholder's action on the tool (W1 2.5, docs/toolholders.md): the length vector
  // becomes rotation * L + offset, the orientation rotation * o. Set at TCARR and at a change of
  // G group 42; the cached vectors are recomputed once, not per block.
  void setCarrier(const Mat3& rotation, Vec3 offset, bool active);
  const Mat3& carrierRotation() const { return carrier_rotation_; }

  // $P_TOOLNO, $P_TOOL, $P_TOOLP, $P_TOOLR, $P_TOOLL[k], $P_TOOLO[k] and the $TC_.. data. False
  // for a name that is no tool variable.
  bool read(std::string_view name, std::span<const lang::Value> idx, bool indexed, Plane plane,
            lang::Value& out) const;
  bool write(std::string_view name, std::span<const lang::Value> idx, bool indexed,
             const lang::Value& v);

  // LENTOAX(_AXIND, _MATRIX[, _COORD]) (W1 2.11): `array` finds the caller's INT[3] and
  // REAL[3,3] variables (it raises the call's alarm for anything else).
  using ArrayLookup = std::function<std::span<lang::Value>(const lang::Value& ref, bool integer,
                                                           int rows, int cols, const char* what)>;
  lang::Value callLentoax(std::span<const lang::Value> args, const ArrayLookup& array, Plane plane,
                          const Mat3& frame_linear) const;

 private:
  void changeTool(int t, bool edge_programmed, const SelectionContext& ctx);
  void selectEdge(int d, const SelectionContext& ctx);
  // DL=n after the block's T/D (W1 18.11: like a D selection); alarm 17182 for a bad DL.
  void selectSumOffset(int dl, const SelectionContext& ctx);
  // Takes the active edge's data (with its DL) and the setting data into the snapshot.
  void snapshot(const EdgeData& e, const SelectionContext& ctx);
  // The radius (edge, wear, DL, TOFFR) and what depends on it, after a change.
  void refreshRadius();
  bool readSumOffset(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                     lang::Value& out) const;
  bool writeSumOffset(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                      const lang::Value& v);
  // Recomputes the cached length and tip vectors for `plane` (the plane changed).
  void cache(Plane plane) const;
  bool cachedFor(Plane plane) const { return edge_.offset_cached && edge_.cached_plane == plane; }

  // The edge a D selects: of the active tool, or with flat D numbers (MD18102 = 1) of the one
  // flat table (kept as tool 0).
  int edgeOwner() const { return dconf_.flat ? 0 : active_tool_; }
  void createEdge(int t, int d);  // counts and numbers a new edge (MD18106, $TC_DPCE)
  void setCuttingEdgeNumber(int t, int d, double ce);
  // Grinding tools (src/tool/grinding.cpp): $TC_TPG1..9 with their ranges, and the chaining
  // rule $TC_TPG2 that keeps $TC_DPn of the wheel's edges D1 and D2 equal.
  void writeGrindingData(int t, int n, double x);
  void chainGrindingEdges(int t, int d, int n);
  // $P_AD[1..26]: the active offset's $TC_DP1..25 and its cutting edge number (W1).
  // $P_TOOLENVN (number of saved environments), $P_TOOLENV[n] (the name of the n-th).
  bool readEnvironment(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                       lang::Value& out) const;
  bool readActiveOffset(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                        lang::Value& out) const;

  ToolStore tools_;
  DNumberConfig dconf_;
  double differential_ = 0;  // 1 with CUT2DD/CUT2DFD
  std::vector<ToolEnvironment> envs_;
  size_t max_edges_;
  size_t edges_ = 0;  // cutting edges in the offset memory
  int active_tool_ = 0;
  int active_edge_ = 0;
  int preselected_tool_ = -1;
  bool carrier_ = false;  // a toolholder is active (TCARR=m, m > 0)
  Mat3 carrier_rotation_;
  Vec3 carrier_offset_;
  SumOffsetMemory sums_;
  SumOffsetLimits sum_limits_;
  int active_dl_ = 0;
  ProgrammedOffsets programmed_;
  struct EdgeSnapshot {
    bool valid = false;
    EdgeData data;
    ToolSettings settings;
    std::array<bool, 3> mirrored{false, false, false};
    double radius = 0;     // effective radius (edge + wear), fixed with the snapshot
    bool has_tip = false;  // type 400..599 with SL 1..8 and a radius: P != S
    // lengthVector() for `cached_plane` (computed once per edge and plane, not per block).
    mutable bool offset_cached = false;
    mutable Plane cached_plane = Plane::G17;
    mutable Vec3 cached_offset;
    mutable Vec3 cached_tip;  // tipVector() for `cached_plane`
  } edge_;
};

}  // namespace ncoffset::tool
