#include "ncoffset/path.hpp"

namespace ncoffset {

const char* motionName(Motion m) {
  switch (m) {
    case Motion::G0:
      return "G0";
    case Motion::G1:
      return "G1";
    case Motion::G2:
      return "G2";
    case Motion::G3:
      return "G3";
  }
  return "G1";
}

const char* feedUnitName(FeedUnit u) {
  switch (u) {
    case FeedUnit::MmPerMin:
      return "mm/min";
    case FeedUnit::MmPerRev:
      return "mm/rev";
    case FeedUnit::InverseTime:
      return "1/min";
  }
  return "mm/min";
}

}  // namespace ncoffset
