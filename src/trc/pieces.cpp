// The elements of the radius compensation window (W1 2.4, details Q8): a block as a plane
// element, its equidistant (also with a compensation value that changes within the block), and
// a compensated element back as a block of the channel.
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

#include "core/cpu_features.hpp"
#include "core/inline_step.hpp"
#include "trc/compensation_internal.hpp"
#include "trc/radius_compensation.hpp"
#include "trc/usual_element.hpp"

namespace ncoffset::trc {

using core::MotionBlock;
using core::TrcStrategy;
namespace tol = geom::tol;
using geom::Element;
using geom::Vec2;

void RadiusCompensation::toMetric(Element& e) const {
  // A scaling frame: the machine's lengths (plane_metric.hpp).
  e.p0 = metric_.to(e.p0);
  e.p1 = metric_.to(e.p1);
  e.c = metric_.to(e.c);
}

Element RadiusCompensation::fromMetric(const Element& e) const {
  // From the machine's lengths back to the program's coordinates (plane_metric.hpp).
  Element back = e;
  back.p0 = metric_.from(e.p0);
  back.p1 = metric_.from(e.p1);
  back.c = metric_.from(e.c);
  return back;
}

MotionBlock RadiusCompensation::toBlock(const MotionBlock& like, const Element& e) const {
  // Every block compensation makes lies on the path of S: P - S at both ends (the approach and
  // retraction lines clear one, detail::keepTipAt). Not per element: emitPiece marks those.
  const std::uint8_t tip_at = like.has_tip ? core::kTipBoth : core::kTipNone;
  return core::withGeometry(
      like, core::planeGeometry(like, metric_.identity ? e : fromMetric(e), tip_at));
}

MotionBlock RadiusCompensation::atPoint(const MotionBlock& like, Vec2 at) const {
  Element e;
  e.p0 = e.p1 = at;
  return toBlock(like, e);
}

static_assert(std::is_trivially_copyable_v<MotionBlock>, "copyBlockWide copies its bytes");

#if defined(__x86_64__) && defined(__GNUC__)
namespace {
// The block's whole 32-byte runs (a fold: no loop left to unroll).
template <std::size_t... I>
[[gnu::target("avx"), gnu::always_inline]] inline void copyRuns(unsigned char* to,
                                                                const unsigned char* from,
                                                                std::index_sequence<I...>) {
  (_mm256_storeu_si256(reinterpret_cast<__m256i*>(to + 32 * I),
                       _mm256_loadu_si256(reinterpret_cast<const __m256i*>(from + 32 * I))),
   ...);
}
}  // namespace

[[gnu::target("avx")]] void RadiusCompensation::copyBlockWide(MotionBlock& to,
                                                              const MotionBlock& from) {
  constexpr std::size_t kSize = sizeof(MotionBlock), kRuns = kSize / 32;
  static_assert(kSize >= 32);
  auto* t = reinterpret_cast<unsigned char*>(&to);
  const auto* f = reinterpret_cast<const unsigned char*>(&from);
  copyRuns(t, f, std::make_index_sequence<kRuns>{});
  // The rest: the last 32 bytes (over part of the last run, which holds the same bytes).
  if constexpr (kSize % 32 != 0)
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(t + kSize - 32),
                        _mm256_loadu_si256(reinterpret_cast<const __m256i*>(f + kSize - 32)));
}

bool RadiusCompensation::wideCopyAvailable() {
  return core::cpuHasAvx();  // (called from a static initializer)
}
#else
void RadiusCompensation::copyBlockWide(MotionBlock& to, const MotionBlock& from) {
  to = from;
}
bool RadiusCompensation::wideCopyAvailable() {
  return false;
}
#endif

RadiusCompensation::Piece RadiusCompensation::compensate(const MotionBlock& m, double r0,
                                                         double r1) const {
  Piece p;
  compensateInto(p, m, r0, r1);
  return p;
}

void RadiusCompensation::compensateInto(Piece& p, const MotionBlock& m, double r0, double r1,
                                        long index, bool restart) const {
  if (r0 == r1 && metric_.identity && !general_paths_)  // the usual element (§36)
    return compensateUsual(p, m, r0, index, restart, kUnmeasured, planeAxes(m.plane));
  startPiece(p, r0, r1, index, restart);
  p.programmed = planeElement(m);
  if (!metric_.identity) toMetric(p.programmed);
  const double s = p.side;
  if (r0 == r1) {
    p.valid = geom::equidistantInto(p.programmed, s * r0, p.compensated);
  } else if (!p.programmed.arc) {
    // A new value in a line: from start + R_old n to end + R_new n (details Q8).
    Vec2 n = s * geom::leftNormal(p.programmed.startTangent());
    p.compensated = p.programmed;
    p.compensated.p0 = p.programmed.p0 + r0 * n;
    p.compensated.p1 = p.programmed.p1 + r1 * n;
  } else {
    // A new value in a circle: a spiral from radius r -+ R_old to r -+ R_new (details Q8).
    const Element& e = p.programmed;
    const double r = e.radius();
    const double k = e.ccw ? -s : s;  // the left side of a ccw arc is its inside
    const double ra = r + k * r0, rb = geom::length(e.p1 - e.c) + k * r1;
    if (ra <= tol::kPoint || rb <= tol::kPoint)
      raise(AlarmNumber::TrcCurvatureTooSmall,
            "curvature radius with variable compensation value too small");
    p.compensated = e;
    p.compensated.p0 = e.c + (ra / r) * (e.p0 - e.c);
    p.compensated.p1 = e.c + (rb / geom::length(e.p1 - e.c)) * (e.p1 - e.c);
  }
  keepRaw(p);
  copyBlock(p.block, m);
}

Element RadiusCompensation::cornerEquidistant(const Piece& p, bool at_end) const {
  if (p.r0 == p.r1) return p.compensated;
  double r = at_end ? p.r1 : p.r0;
  auto e = geom::equidistant(p.programmed, p.side * r);
  return e ? *e : p.compensated;
}

void RadiusCompensation::emitWithBlocks(const Piece& p, std::uint8_t tip_at) {
  for (const MotionBlock& t : p.transition) emit(t);
  if (metric_.identity)
    out_.element(p.block, p.compensated, tip_at);
  else
    out_.element(p.block, fromMetric(p.compensated), tip_at);
  for (const MotionBlock& w : p.waiting) emit(atPoint(w, p.compensated.p1));
}

}  // namespace ncoffset::trc
