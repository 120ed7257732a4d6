// Tool radius compensation modes (W1 2.4): the G groups of approach, corners and collision
// detection as named values.
#pragma once

namespace ncoffset {

// G group 17: approach and retraction behaviour.
enum class Approach : unsigned char { Norm, Kont, KontC, KontT };
// G group 18: outside corners. TransitionCircle = G450, Intersection = G451.
enum class CornerMode : unsigned char { TransitionCircle, Intersection };
// G group 23: collision (bottleneck) detection. CDOF, CDON, CDOF2.
enum class CollisionCheck : unsigned char { Cdof, Cdon, Cdof2 };

}  // namespace ncoffset
