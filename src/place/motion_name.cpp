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
    case Motion::G33:
      return "G33";
    case Motion::G34:
      return "G34";
    case Motion::G35:
      return "G35";
    case Motion::G331:
      return "G331";
    case Motion::G332:
      return "G332";
    case Motion::G63:
      return "G63";
  }
  return "G1";
}

int motionGNumber(Motion m) {
  static constexpr int kNumbers[] = {0, 1, 2, 3, 33, 34, 35, 331, 332, 63};
  return kNumbers[static_cast<int>(m)];
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
