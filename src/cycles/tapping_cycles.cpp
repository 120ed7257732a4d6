// CYCLE84 (rigid tapping) and CYCLE840 (tapping with compensating chuck) as NC programs written
// from the motion sequences of PG Cycles 11.02, 2.1.5 and 2.1.6 (docs/cycles.md).
#include "cycles/builtin_cycles.hpp"
#include "cycles/cycle_text.hpp"

namespace ncoffset::cycles {
namespace {

// The lead _L from MPIT (metric thread size M3..M48: the ISO coarse pitch, ISO 261; its sign
// is the hand) or PIT (the lead itself); none is the control's cycle alarm 61001 "thread lead
// incorrect" (PG Cycles "Cycle alarms" [M]).
constexpr std::string_view kLead = R"(IF (_PTAB<>0) AND (_PTAB<>1)
_NCO_NOT_MODELLED("a thread lead in threads per inch or inch, _PTAB 2 or 3")
ENDIF
_L=ABS(_PIT)
IF _MPIT<>0
_M=ROUND(ABS(_MPIT))
_L=0
FOR _K=0 TO 20
IF _M==_MS[_K]
_L=_MP[_K]
ENDIF
ENDFOR
ENDIF
IF _L<=0
SETAL(61001)
ENDIF
)";

constexpr std::string_view kLeadDefs = R"(DEF STRING[1] _A1, _A2, _A3
DEF REAL _Z, _L
DEF INT _M, _K
DEF INT _MS[21]=SET(3,4,5,6,8,10,12,14,16,18,20,22,24,27,30,33,36,39,42,45,48)
DEF REAL _MP[21]=SET(0.5,0.7,0.8,1,1.25,1.5,1.75,2,2,2.5,2.5,2.5,3,3,3.5,3.5,4,4,4.5,4.5,5)
)";

// The spindle direction after the cycle (SDAC 3, 4, 5: M3, M4, M5).
constexpr std::string_view kSdac = R"(IF _SDAC==3
M3
ENDIF
IF _SDAC==4
M4
ENDIF
IF _SDAC==5
M5
ENDIF
)";

// CYCLE84(RTP, RFP, SDIS, DP, DPR, DTB, SDAC, MPIT, PIT, POSS, SST, SST1, _AXN, _PTAB,
// _TECHNO, _VARI, _DAM, _VRT): G0 to RFP + SDIS, oriented spindle stop at POSS, G331 to the
// final depth at speed SST, dwell DTB, G332 back to RFP + SDIS at SST1 (SST where 0; the
// spindle reverses), G0 to RTP, spindle direction SDAC.
const std::string& cycle84() {
  static const std::string text = joined(
      {R"(PROC CYCLE84(REAL _RTP, REAL _RFP, REAL _SDIS, REAL _DP, REAL _DPR, REAL _DTB, INT _SDAC, REAL _MPIT, REAL _PIT, REAL _POSS, REAL _SST, REAL _SST1, INT _AXN, INT _PTAB, INT _TECHNO, INT _VARI, REAL _DAM, REAL _VRT) SAVE
)",
       kLeadDefs, kPlaneAxes, kToolAxis, kLead, kFinalDepth, R"(IF _VARI>1
_NCO_NOT_MODELLED("CYCLE84 with chip breaking or chip removal, _VARI 2 or 3")
ENDIF
IF _SST1==0
_SST1=_SST
ENDIF
G0 AX[_A3]=_RFP+_SDIS
SPOS=_POSS
G331 AX[_A3]=_Z K=_L S=_SST
)",
       kDwellDtb, R"(G332 AX[_A3]=_RFP+_SDIS K=_L S=_SST1
G0 AX[_A3]=_RTP
)",
       kSdac, "M17\n"});
  return text;
}

// CYCLE840(RTP, RFP, SDIS, DP, DPR, DTB, SDR, SDAC, ENC, MPIT, PIT, _AXN, _PTAB, _TECHNO): G0
// to RFP + SDIS; with encoder (ENC 0) G33 to the final depth with the lead, dwell DTB, G33 back
// to RFP + SDIS (the spindle reversed: SDR 3/4, or automatically with SDR 0); without encoder
// (ENC 1) the same two lines as G63 at the caller's feed; G0 to RTP, spindle direction SDAC.
const std::string& cycle840() {
  static const std::string text = joined(
      {R"(PROC CYCLE840(REAL _RTP, REAL _RFP, REAL _SDIS, REAL _DP, REAL _DPR, REAL _DTB, INT _SDR, INT _SDAC, INT _ENC, REAL _MPIT, REAL _PIT, INT _AXN, INT _PTAB, INT _TECHNO) SAVE
)",
       kLeadDefs, kPlaneAxes, kToolAxis, R"(IF _ENC==1
_PIT=1
ENDIF
)",
       kLead, kFinalDepth, R"(G0 AX[_A3]=_RFP+_SDIS
IF _ENC==1
G1 G63 AX[_A3]=_Z
)",
       kDwellDtb, R"(G1 G63 AX[_A3]=_RFP+_SDIS
ELSE
G33 AX[_A3]=_Z K=_L
)",
       kDwellDtb, R"(G33 AX[_A3]=_RFP+_SDIS K=_L
ENDIF
G0 AX[_A3]=_RTP
)",
       kSdac, "M17\n"});
  return text;
}

}  // namespace

std::string_view tappingCycleText(std::string_view name) {
  if (name == "CYCLE84") return cycle84();
  if (name == "CYCLE840") return cycle840();
  return {};
}

}  // namespace ncoffset::cycles
