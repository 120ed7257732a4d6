// CYCLE85 to CYCLE89 (boring) as NC programs written from the motion sequences of PG Cycles
// 11.02, 2.1.7 to 2.1.11 (docs/cycles.md).
#include "cycles/builtin_cycles.hpp"
#include "cycles/cycle_text.hpp"

namespace ncoffset::cycles {
namespace {

constexpr std::string_view kDefs = R"(DEF STRING[1] _A1, _A2, _A3
DEF REAL _Z, _F
)";

// The spindle direction SDIR 3/4 (M3/M4) for the boring cycles that stop the spindle.
constexpr std::string_view kSdir = R"(IF _SDIR==3
M3
ENDIF
IF _SDIR==4
M4
ENDIF
)";

// CYCLE85(RTP, RFP, SDIS, DP, DPR, DTB, FFR, RFF): G0 to RFP + SDIS, G1 to the depth at FFR,
// dwell DTB, G1 back to RFP + SDIS at RFF, G0 to RTP; F is the caller's again.
const std::string& cycle85() {
  static const std::string text = joined(
      {R"(PROC CYCLE85(REAL _RTP, REAL _RFP, REAL _SDIS, REAL _DP, REAL _DPR, REAL _DTB, REAL _FFR, REAL _RFF) SAVE
)",
       kDefs, kPlaneAxes, kFinalDepth, R"(_F=$P_F
G0 AX[_A3]=_RFP+_SDIS
G1 AX[_A3]=_Z F=_FFR
)",
       kDwellDtb, R"(G1 AX[_A3]=_RFP+_SDIS F=_RFF
G0 AX[_A3]=_RTP
F=_F
M17
)"});
  return text;
}

// CYCLE86(RTP, RFP, SDIS, DP, DPR, DTB, SDIR, RPA, RPO, RPAP, POSS): G0 to RFP + SDIS, G1 to
// the depth (spindle SDIR), dwell DTB, oriented spindle stop at POSS, G0 lift-off by RPA, RPO,
// RPAP (incremental in the plane's axes and the applicate), G0 in the applicate to RFP + SDIS,
// G0 to RTP and back to the hole's position in the plane in one block.
const std::string& cycle86() {
  static const std::string text = joined(
      {R"(PROC CYCLE86(REAL _RTP, REAL _RFP, REAL _SDIS, REAL _DP, REAL _DPR, REAL _DTB, INT _SDIR, REAL _RPA, REAL _RPO, REAL _RPAP, REAL _POSS) SAVE
)",
       kDefs, kPlaneAxes, kFinalDepth, R"(G0 AX[_A3]=_RFP+_SDIS
)",
       kSdir, R"(G1 AX[_A3]=_Z
)",
       kDwellDtb, R"(SPOS=_POSS
G0 G91 AX[_A1]=_RPA AX[_A2]=_RPO AX[_A3]=_RPAP
G0 G90 AX[_A3]=_RFP+_SDIS
G0 G91 AX[_A1]=-_RPA AX[_A2]=-_RPO AX[_A3]=_RTP-_RFP-_SDIS
G90
M17
)"});
  return text;
}

// CYCLE87(RTP, RFP, SDIS, DP, DPR, SDIR): G0 to RFP + SDIS, G1 to the depth (spindle SDIR),
// spindle stop M5 and programmed stop M0, after the NC start G0 to RTP.
const std::string& cycle87() {
  static const std::string text =
      joined({R"(PROC CYCLE87(REAL _RTP, REAL _RFP, REAL _SDIS, REAL _DP, REAL _DPR, INT _SDIR) SAVE
)",
              kDefs, kPlaneAxes, kFinalDepth, R"(G0 AX[_A3]=_RFP+_SDIS
)",
              kSdir, R"(G1 AX[_A3]=_Z
M5
M0
G0 AX[_A3]=_RTP
M17
)"});
  return text;
}

// CYCLE88(RTP, RFP, SDIS, DP, DPR, DTB, SDIR): as CYCLE87 with the dwell DTB at the depth.
const std::string& cycle88() {
  static const std::string text = joined(
      {R"(PROC CYCLE88(REAL _RTP, REAL _RFP, REAL _SDIS, REAL _DP, REAL _DPR, REAL _DTB, INT _SDIR) SAVE
)",
       kDefs, kPlaneAxes, kFinalDepth, R"(G0 AX[_A3]=_RFP+_SDIS
)",
       kSdir, R"(G1 AX[_A3]=_Z
)",
       kDwellDtb, R"(M5
M0
G0 AX[_A3]=_RTP
M17
)"});
  return text;
}

// CYCLE89(RTP, RFP, SDIS, DP, DPR, DTB): G0 to RFP + SDIS, G1 to the depth, dwell DTB, G1 back
// to RFP + SDIS at the same feed, G0 to RTP.
const std::string& cycle89() {
  static const std::string text =
      joined({R"(PROC CYCLE89(REAL _RTP, REAL _RFP, REAL _SDIS, REAL _DP, REAL _DPR, REAL _DTB) SAVE
)",
              kDefs, kPlaneAxes, kFinalDepth, R"(G0 AX[_A3]=_RFP+_SDIS
G1 AX[_A3]=_Z
)",
              kDwellDtb, R"(G1 AX[_A3]=_RFP+_SDIS
G0 AX[_A3]=_RTP
M17
)"});
  return text;
}

}  // namespace

std::string_view boringCycleText(std::string_view name) {
  if (name == "CYCLE85") return cycle85();
  if (name == "CYCLE86") return cycle86();
  if (name == "CYCLE87") return cycle87();
  if (name == "CYCLE88") return cycle88();
  if (name == "CYCLE89") return cycle89();
  return {};
}

}  // namespace ncoffset::cycles
