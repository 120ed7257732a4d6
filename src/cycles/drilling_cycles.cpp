// CYCLE81, CYCLE82, CYCLE83 as NC programs written from the motion sequences of the
// Programming Guide Cycles (PG Cycles 11.02, 2.1.2 to 2.1.4; docs/cycles.md). The parameter
// lists are the manual's, with the newer versions' trailing parameters accepted (GMODE,
// DMODE, AMODE: 0 or left out is the manual's behaviour; another GMODE or AMODE is 99010).
#include "cycles/builtin_cycles.hpp"
#include "cycles/cycle_text.hpp"

namespace ncoffset::cycles {
namespace {

constexpr std::string_view kNewModes = R"(IF (_GMODE<>0) OR (_AMODE<>0)
_NCO_NOT_MODELLED("the depth modes GMODE and AMODE of the newer cycle versions")
ENDIF
)";

// CYCLE81(RTP, RFP, SDIS, DP, DPR): G0 to the reference plane plus the safety distance, G1 to
// the final depth at the caller's feed, G0 to the retraction plane.
const std::string& cycle81() {
  static const std::string text = joined(
      {R"(PROC CYCLE81(REAL _RTP, REAL _RFP, REAL _SDIS, REAL _DP, REAL _DPR, INT _GMODE, INT _DMODE, INT _AMODE) SAVE
DEF STRING[1] _A1, _A2, _A3
DEF REAL _Z
)",
       kNewModes, kPlaneAxes, kFinalDepth, R"(G0 AX[_A3]=_RFP+_SDIS
G1 AX[_A3]=_Z
G0 AX[_A3]=_RTP
M17
)"});
  return text;
}

// CYCLE82(RTP, RFP, SDIS, DP, DPR, DTB): as CYCLE81 with the dwell DTB at the final depth.
const std::string& cycle82() {
  static const std::string text = joined(
      {R"(PROC CYCLE82(REAL _RTP, REAL _RFP, REAL _SDIS, REAL _DP, REAL _DPR, REAL _DTB, INT _GMODE, INT _DMODE, INT _AMODE) SAVE
DEF STRING[1] _A1, _A2, _A3
DEF REAL _Z
)",
       kNewModes, kPlaneAxes, kFinalDepth, R"(G0 AX[_A3]=_RFP+_SDIS
G1 AX[_A3]=_Z
)",
       kDwellDtb, R"(G0 AX[_A3]=_RTP
M17
)"});
  return text;
}

// CYCLE83's first stroke and degression (PG Cycles 11.02, 2.1.4, parameters FDEP, FDPR, DAM;
// the newer versions' DAM < 0, a degression factor, with _MDEP the smallest stroke).
constexpr std::string_view kCycle83Setup = R"(_TOT=_RFP-_Z
_STEP=_TOT
IF $P_SUBPAR[6]
_STEP=_RFP-_FDEP
ENDIF
IF _FDPR<>0
_STEP=ABS(_FDPR)
ENDIF
IF _STEP<=0
_STEP=_TOT
ENDIF
_FAC=0
_MIN=_DAM
IF _DAM<0
_FAC=-_DAM
_MIN=_MDEP
IF _MDEP<=0
_NCO_NOT_MODELLED("a degression factor (CYCLE83 DAM < 0) without a minimum drilling depth _MDEP")
ENDIF
ENDIF
_ANT=0.6
IF _TOT>30
_ANT=MINVAL(_TOT/50,7)
ENDIF
IF _DIS1>0
_ANT=_DIS1
ENDIF
_VR=1
IF _VRT>0
_VR=_VRT
ENDIF
_FR=1
IF _FRF>0
_FR=_FRF
ENDIF
_F=$P_F
_CUR=0
_N=0
_SPLIT=0
)";

// CYCLE83's strokes up to the dwell after each (the rest follows in kCycle83Return). From the
// second stroke on (DAM not 0): the stroke before less DAM, at least DAM (a factor: times
// -DAM, at least _MDEP); where the rest of the hole is more than that stroke but not more than
// twice it, the rest is drilled in two equal strokes (PG Cycles 2.1.4, DAM: "the last two
// strokes are divided equally"; docs/cycles.md). The last stroke ends exactly at the depth.
constexpr std::string_view kCycle83Strokes = R"(G0 AX[_A3]=_RFP+_SDIS
WHILE _CUR<_TOT-0.000001
IF (_N>0) AND (_DAM<>0) AND (_SPLIT==0)
IF _FAC>0
_STEP=MAXVAL(_STEP*_FAC,_MIN)
ELSE
_STEP=MAXVAL(_STEP-_DAM,_DAM)
ENDIF
IF (_TOT-_CUR>_STEP+0.000001) AND (_TOT-_CUR<=2*_STEP+0.000001)
_STEP=(_TOT-_CUR)/2
_SPLIT=1
ENDIF
ENDIF
_NEXT=MINVAL(_CUR+_STEP,_TOT)
IF _NEXT>_TOT-0.000001
_NEXT=_TOT
ENDIF
IF (_VARI==1) AND (_N>0)
G0 AX[_A3]=_RFP-_CUR+_ANT
ENDIF
IF _N==0
G1 AX[_A3]=_RFP-_NEXT F=_F*_FR
ELSE
G1 AX[_A3]=_RFP-_NEXT F=_F
ENDIF
_DW=_DTB
IF (_NEXT>=_TOT) AND (_DTD<>0)
_DW=_DTD
ENDIF
IF _DW>0
G4 F=_DW
ENDIF
IF _DW<0
G4 S=-_DW
ENDIF
)";

// After each stroke but the last: chip removal G0 out to RFP + SDIS and the dwell DTS; chip
// breaking the G1 retraction. At the end G0 to RTP and the caller's F again.
constexpr std::string_view kCycle83Return = R"(_CUR=_NEXT
IF _CUR<_TOT-0.000001
IF _VARI==1
G0 AX[_A3]=_RFP+_SDIS
IF _DTS>0
G4 F=_DTS
ENDIF
IF _DTS<0
G4 S=-_DTS
ENDIF
ELSE
G1 AX[_A3]=_RFP-_CUR+_VR F=_F
ENDIF
ENDIF
_N=_N+1
ENDWHILE
G0 AX[_A3]=_RTP
F=_F
M17
)";

// CYCLE83(RTP, RFP, SDIS, DP, DPR, FDEP, FDPR, DAM, DTB, DTS, FRF, VARI, _AXN, _MDEP, _VRT,
// _DTD, _DIS1): deep-hole drilling in strokes. The first stroke to FDEP (or FDPR below RFP) at
// F * FRF, the further ones as kCycle83Strokes says. After each stroke the dwell DTB (after the
// last one _DTD where not 0; > 0 seconds, < 0 revolutions). VARI 0 (chip breaking): a G1
// retraction of 1 mm (_VRT where given) at the caller's feed. VARI 1 (chip removal): G0 to
// RFP + SDIS, the dwell DTS, G0 back to the depth reached less the anticipation distance
// (0.6 mm up to 30 mm of depth, depth / 50 beyond, at most 7 mm; _DIS1 where given). At the end
// G0 to RTP; F is the caller's again.
const std::string& cycle83() {
  static const std::string text = joined(
      {R"(PROC CYCLE83(REAL _RTP, REAL _RFP, REAL _SDIS, REAL _DP, REAL _DPR, REAL _FDEP, REAL _FDPR, REAL _DAM, REAL _DTB, REAL _DTS, REAL _FRF, INT _VARI, INT _AXN, REAL _MDEP, REAL _VRT, REAL _DTD, REAL _DIS1, INT _GMODE, INT _DMODE, INT _AMODE) SAVE
DEF STRING[1] _A1, _A2, _A3
DEF REAL _Z, _TOT, _STEP, _CUR, _NEXT, _ANT, _F, _FR, _MIN, _VR, _FAC, _DW
DEF INT _N, _SPLIT
)",
       kNewModes, kPlaneAxes, kToolAxis, kFinalDepth, kCycle83Setup, kCycle83Strokes,
       kCycle83Return});
  return text;
}

}  // namespace

std::string_view drillingCycleText(std::string_view name) {
  if (name == "CYCLE81") return cycle81();
  if (name == "CYCLE82") return cycle82();
  if (name == "CYCLE83") return cycle83();
  return {};
}

}  // namespace ncoffset::cycles
