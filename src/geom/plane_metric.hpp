// Lengths in the compensation plane as a frame makes them (docs/radius-compensation.md, "Frames:
// SCALE"). The tool radius is physical: radius compensation keeps R in the machine, not in the
// program's coordinates. A frame whose linear part preserves lengths in the plane (rotation,
// mirroring) leaves them as they are; a scale (SCALE, ASCALE, a scaling settable frame) does not.
// PlaneMetric maps the plane's program coordinates (a, o) to coordinates in which lengths are
// the machine's: p' = M p with M upper triangular and M^T M = G, the Gram matrix of the images
// of the plane's unit vectors (so |M v| = |frame v| for every vector v of the plane, and M keeps
// the plane's sense of rotation: G41 stays left of the travel as programmed, a mirroring frame
// turns the side over in the machine).
#pragma once

#include <cmath>

#include "geom/arc.hpp"
#include "geom/tolerance.hpp"

namespace ncoffset::geom {

struct PlaneMetric {
  bool identity = true;
  double m11 = 1, m12 = 0, m22 = 1;

  // From the Gram matrix [[g11, g12], [g12, g22]] of the plane's unit vectors' images.
  static PlaneMetric fromGram(double g11, double g12, double g22) {
    PlaneMetric m;
    // A frame of length-preserving parts, up to the rounding of its products.
    if (std::fabs(g11 - 1) < tol::kNumeric && std::fabs(g22 - 1) < tol::kNumeric &&
        std::fabs(g12) < tol::kNumeric)
      return m;
    m.identity = false;
    m.m11 = std::sqrt(g11);
    m.m12 = g12 / m.m11;
    m.m22 = std::sqrt(g22 - m.m12 * m.m12);
    return m;
  }
  Vec2 to(Vec2 p) const { return identity ? p : Vec2{m11 * p.a + m12 * p.o, m22 * p.o}; }
  Vec2 from(Vec2 q) const {
    if (identity) return q;
    const double o = q.o / m22;
    return {(q.a - m12 * o) / m11, o};
  }
};

}  // namespace ncoffset::geom
