// HOLES1, HOLES2, CYCLE801 and CYCLE802 as NC programs written from PG Cycles 11.02, 2.3
// ("Drilling pattern cycles") and the SINUMERIK Operate position patterns (docs/cycles.md):
// each moves with G0 in the plane to its positions; the drilling cycle called modally (MCALL)
// before runs after each of these blocks (the MCALL mechanism of the interpreter), so each hole
// reports the line of the pattern's call.
#include "cycles/builtin_cycles.hpp"
#include "cycles/cycle_text.hpp"

namespace ncoffset::cycles {
namespace {

constexpr std::string_view kDefs = R"(DEF STRING[1] _A1, _A2, _A3
DEF REAL _CA, _SA, _D, _PA, _PO, _DF, _DL
DEF INT _K, _I, _J
)";

// HOLES1(SPCA, SPCO, STA1, FDIS, DBH, NUM): NUM holes on a line through the reference point
// (SPCA, SPCO) at the angle STA1 to the abscissa, the first FDIS from the reference point, the
// next DBH apart. The row starts at the end nearer to where the tool stands (the manual: "to
// avoid unnecessary idle travel"; equal distances: the first hole).
const std::string& holes1() {
  static const std::string text = joined(
      {R"(PROC HOLES1(REAL _SPCA, REAL _SPCO, REAL _STA1, REAL _FDIS, REAL _DBH, INT _NUM) SAVE
)",
       kDefs, kPlaneAxes, R"(_CA=COS(_STA1)
_SA=SIN(_STA1)
_PA=$P_EP[_A1]
_PO=$P_EP[_A2]
_D=_FDIS+(_NUM-1)*_DBH
_DF=POT(_SPCA+_FDIS*_CA-_PA)+POT(_SPCO+_FDIS*_SA-_PO)
_DL=POT(_SPCA+_D*_CA-_PA)+POT(_SPCO+_D*_SA-_PO)
FOR _K=0 TO _NUM-1
_I=_K
IF _DL<_DF
_I=_NUM-1-_K
ENDIF
_D=_FDIS+_I*_DBH
G0 AX[_A1]=_SPCA+_D*_CA AX[_A2]=_SPCO+_D*_SA
ENDFOR
M17
)"});
  return text;
}

// HOLES2(CPA, CPO, RAD, STA1, INDA, NUM): NUM holes on the circle of radius RAD about (CPA,
// CPO), the first at the angle STA1 to the abscissa, the next INDA further (INDA 0: the full
// circle divided by NUM), each reached with G0 on a straight line.
const std::string& holes2() {
  static const std::string text =
      joined({R"(PROC HOLES2(REAL _CPA, REAL _CPO, REAL _RAD, REAL _STA1, REAL _INDA, INT _NUM) SAVE
)",
              kDefs, kPlaneAxes, R"(_D=_INDA
IF (_D==0) AND (_NUM>0)
_D=360/_NUM
ENDIF
FOR _K=0 TO _NUM-1
G0 AX[_A1]=_CPA+_RAD*COS(_STA1+_K*_D) AX[_A2]=_CPO+_RAD*SIN(_STA1+_K*_D)
ENDFOR
M17
)"});
  return text;
}

// CYCLE801(_SPCA, _SPCO, _STA, _DIS1, _DIS2, _NUM1, _NUM2): a grid of _NUM1 columns _DIS1
// apart along the direction _STA and _NUM2 rows _DIS2 apart perpendicular to it, from the
// reference point; row by row, every other row backwards (a meander).
const std::string& cycle801() {
  static const std::string text = joined(
      {R"(PROC CYCLE801(REAL _SPCA, REAL _SPCO, REAL _STA, REAL _DIS1, REAL _DIS2, INT _NUM1, INT _NUM2) SAVE
)",
       kDefs, kPlaneAxes, R"(_CA=COS(_STA)
_SA=SIN(_STA)
FOR _J=0 TO _NUM2-1
FOR _K=0 TO _NUM1-1
_I=_K
IF _J MOD 2==1
_I=_NUM1-1-_K
ENDIF
G0 AX[_A1]=_SPCA+_I*_DIS1*_CA-_J*_DIS2*_SA AX[_A2]=_SPCO+_I*_DIS1*_SA+_J*_DIS2*_CA
ENDFOR
ENDFOR
M17
)"});
  return text;
}

// CYCLE802(_I1, _I2, _X0, _Y0, ..., _X8, _Y8): up to nine positions in the plane, in order; the
// list ends at the first position whose two coordinates are both left out. _I1 and _I2 (the
// HMI's selection words) are accepted and not used.
const std::string& cycle802() {
  static const std::string text = joined(
      {R"(PROC CYCLE802(INT _I1, INT _I2, REAL _X0, REAL _Y0, REAL _X1, REAL _Y1, REAL _X2, REAL _Y2, REAL _X3, REAL _Y3, REAL _X4, REAL _Y4, REAL _X5, REAL _Y5, REAL _X6, REAL _Y6, REAL _X7, REAL _Y7, REAL _X8, REAL _Y8) SAVE
)",
       kDefs, R"(DEF REAL _P[18]
)",
       kPlaneAxes,
       R"(_P[0]=SET(_X0,_Y0,_X1,_Y1,_X2,_Y2,_X3,_Y3,_X4,_Y4,_X5,_Y5,_X6,_Y6,_X7,_Y7,_X8,_Y8)
_K=0
WHILE (_K<9) AND ($P_SUBPAR[3+2*_K] OR $P_SUBPAR[4+2*_K])
G0 AX[_A1]=_P[2*_K] AX[_A2]=_P[2*_K+1]
_K=_K+1
ENDWHILE
M17
)"});
  return text;
}

}  // namespace

std::string_view holePatternText(std::string_view name) {
  if (name == "HOLES1") return holes1();
  if (name == "HOLES2") return holes2();
  if (name == "CYCLE801") return cycle801();
  if (name == "CYCLE802") return cycle802();
  return {};
}

}  // namespace ncoffset::cycles
