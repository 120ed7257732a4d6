// Sum offsets and setup offsets of a cutting edge (FM-W1 01/2015 18.11 "Sum offsets and setup
// offsets"; 08/2005 2.9): per edge up to MD18110 sets, selected by DL=n. `$TC_SCPxy[t,d]` is
// the sum offset, `$TC_ECPxy[t,d]` the setup offset (only with MD18112 bit 4) of DL number x,
// parameter y = 3..11 (the parameters of the wear DP12..DP20: L1, L2, L3, radius, ...). The
// name's number is 10 * x + y: `$TC_SCP13` is L1 of DL1, `$TC_SCP21` parameter 11 of DL1,
// `$TC_SCP23` L1 of DL2. For the length and radius rules both are wear (FM-W1 11/2006 2.8).
#pragma once

#include <array>
#include <map>
#include <string_view>
#include <tuple>

#include "ncoffset/tool.hpp"

namespace ncoffset::tool {

// The highest DL number a name can address (MD18110 is at most 6).
inline constexpr int kMaxSumOffsets = 6;

// What MD18110 and MD18112 configure.
struct SumOffsetLimits {
  int max_per_edge = kMaxSumOffsets;  // MD18110 $MN_MM_MAX_SUMCORR_PER_CUTTEDGE
  bool setup_offsets = false;         // MD18112 $MN_MM_KIND_OF_SUMCORR bit 4
};

// "$TC_SCP13" -> sum offset, DL 1, parameter 3; false for any other name.
struct SumOffsetName {
  bool setup = false;  // $TC_ECP..
  int dl = 0;          // 1..6
  int param = 0;       // 3..11
};
bool parseSumOffsetName(std::string_view name, SumOffsetName& out);

class SumOffsetMemory {
 public:
  using Set = std::array<double, 9>;  // parameters 3..11
  const Set* find(bool setup, int t, int d, int dl) const {
    const auto& m = setup ? setup_ : sum_;
    auto it = m.find({t, d, dl});
    return it == m.end() ? nullptr : &it->second;
  }
  Set& forWrite(bool setup, int t, int d, int dl) { return (setup ? setup_ : sum_)[{t, d, dl}]; }
  // DL `dl` of edge (t, d) is defined: one of its parameters was written.
  bool exists(int t, int d, int dl) const {
    return find(false, t, d, dl) != nullptr || find(true, t, d, dl) != nullptr;
  }

 private:
  std::map<std::tuple<int, int, int>, Set> sum_, setup_;
};

// Adds DL `dl` of edge (t, d) to the wear parameters of `e` (DP12..DP20 += SCP + ECP): the edge
// as its selection with DL sees it. The setup offsets count only with `limits.setup_offsets`;
// `sum`/`setup` choose the components (GETTCOR's S and E; a selection takes both).
void addSumOffsets(EdgeData& e, const SumOffsetMemory& m, int t, int d, int dl,
                   const SumOffsetLimits& limits, bool sum = true, bool setup = true);

}  // namespace ncoffset::tool
