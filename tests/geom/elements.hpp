// Lines and arcs for the geometry tests.
#pragma once

#include "geom/contour.hpp"

namespace ncoffset::geom::test {

inline Element line(Vec2 p0, Vec2 p1) {
  Element e;
  e.p0 = p0;
  e.p1 = p1;
  return e;
}

inline Element arc(Vec2 p0, Vec2 p1, Vec2 c, bool ccw) {
  Element e = line(p0, p1);
  e.arc = true;
  e.c = c;
  e.ccw = ccw;
  return e;
}

}  // namespace ncoffset::geom::test
