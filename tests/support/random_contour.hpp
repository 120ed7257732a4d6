// Random closed contours for the radius-compensation property test
// (tests/trc/compensation_property_test.cpp) and the differential test against LinuxCNC's rs274
// (tests/differential/differential.py, through tests/support/random_contour_main.cpp): one
// generator for both.
//
// A contour is a star-shaped polygon (5 to 9 vertices 30 to 60 mm from a centre), traversed
// counter-clockwise or clockwise. Each edge is a line, an arc bulging outwards or inwards, or an
// ogee (two arcs tangent to each other in the middle of the edge); a corner between two lines
// may be rounded by a tangent fillet. So the contour has tangent joins (fillets, ogees) and
// non-tangent ones, convex and concave for the tool. Plane G17 or G18, G41 or G42, tool radius R
// from 0.5 to 5 mm, G450 or G451, CDON or CDOF.
//
// Features are larger than R: an arc the tool runs inside has a radius of at least R + 0.5 mm,
// every element is long enough for the trimming at its inside corners, corners turn at most
// 120 degrees (inside) or 150 degrees (outside) and keep 1 degree away from MD20230 (10 degrees)
// and MD20210 (100 degrees), and elements that are not neighbours keep more than 2R + 0.5 mm
// apart: a path at distance R without gouge exists (checked here, without the compensation
// code).
//
// The ideal contour is the same for every rounding. Rounded to d decimals, every coordinate is
// a multiple of 10^-d mm; an arc's centre is the multiple within two steps of the ideal centre
// that makes its start and end radius most nearly equal (as a post-processor that fits I/J to its
// rounded end points does), so a tangent join stays tangent up to the rounding of the
// coordinates.
#pragma once

#include <string>
#include <vector>

namespace ncoffset::test {

struct Pt {
  double a = 0, o = 0;  // abscissa, ordinate of the plane
};

struct ContourElement {
  bool arc = false;
  Pt end;
  Pt centre;  // arcs: absolute
  bool ccw = false;
  bool tangent_start = false;  // designed tangent to the previous element
};

struct RandomContour {
  int index = 0;
  bool g18 = false;                // plane (a, o) = (Z, X), else G17 (X, Y)
  bool left = true;                // G41, else G42
  bool ccw = true;                 // the contour's traversal sense
  bool g451 = false;               // corner mode, else G450
  bool cdon = false;               // bottleneck detection, else CDOF
  double radius = 1;               // tool radius R (3 decimals)
  int decimals = 6;                // of every coordinate
  Pt start;                        // P0, where the first element starts (and the last one ends)
  Pt approach;                     // where the tool comes from and goes back to
  double curve_insert_limit = -1;  // MD20230 to write (< 0: the default)
  std::vector<ContourElement> elements;
  bool toolOutside() const { return ccw != left; }
};

struct GeneratorOptions {
  // For the differential test against LinuxCNC (tests/differential/README.md): no designed
  // corners below 15 degrees outside and 5 degrees inside, G450 and CDOF, MD20230 = 0 written
  // into the program (LinuxCNC inserts an arc at every convex corner).
  bool differential = false;
};

// The ideal contour `index` of the run `seed`, rounded to `decimals` (3, 4 or 6).
RandomContour randomContour(unsigned seed, int index, int decimals, const GeneratorOptions& opt);

// The SINUMERIK program: tool, plane, approach from `approach` with G41/G42 NORM to the start,
// the elements, the first two elements once more (so that every corner lies between two blocks
// that are neither the first nor the last), G40 back. Line numbers: contourLine(k) is the line
// of element k (0-based; k = n, n + 1 are the first two elements repeated).
std::string programText(const RandomContour& c);
int contourLine(const RandomContour& c, int k);

// The contour as plain text for other programs (differential.py): a header line
// `contour INDEX PLANE SIDE RADIUS DECIMALS CORNER CDON|CDOF`, `start A O`, `approach A O`, then
// one line per element: `line A O` or `arc A O CA CO ccw|cw`. Numbers with `decimals` decimals.
std::string description(const RandomContour& c);

}  // namespace ncoffset::test
