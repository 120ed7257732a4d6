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

}  // namespace ncoffset
