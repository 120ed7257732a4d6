// Bottleneck detection of radius compensation (W1 2.4.8, spec §5.5, details Q5): a new element
// is intersected with earlier elements of the window (CDOF: when two consecutive equidistants
// do not meet; CDON: always); the elements in between are omitted with warning 10763, and a
// junction that no block within MD20240 closes is alarm 10751.
#include <cmath>

#include "trc/compensation_internal.hpp"
#include "trc/radius_compensation.hpp"

namespace ncoffset::trc {

using core::TrcStrategy;
namespace tol = geom::tol;
using geom::Element;
using geom::Vec2;

void RadiusCompensation::bridge(Piece& next, bool needed) {
  // `next` is the window's last element.
  if (!next.valid || window_.size() < 3 || (!needed && settings_.collision != CollisionCheck::Cdon))
    return;
  // Search back from the element before the last one (the last one was tried as the corner);
  // CDOF stops at the first intersection found, CDON keeps searching and takes the last found
  // (W1 2.4.8, details Q5).
  const long oldest = next.index - settings_.check_blocks;
  // The later element at its start value (details Q8); with a constant value it is the piece
  // itself, with its box (no copy).
  Element changed;
  if (next.r0 != next.r1) changed = cornerEquidistant(next, false);
  const Element& later = next.r0 == next.r1 ? next.compensated : changed;
  const geom::Box later_box = next.r0 == next.r1 ? next.box() : geom::Box(later);
  std::optional<std::pair<size_t, Vec2>> found;
  size_t start = window_.size() - 2;
  if (!window_[start].valid) {
    // Elements without equidistant just before `next` (an inside arc with r = R): where the
    // valid element before them ends, `next` may start (tol::kPoint); they meet there.
    size_t j = start;
    while (j > 0 && !window_[j].valid) --j;
    const Piece& c = window_[j];
    if (c.index >= oldest && !c.emitted && (!c.approach || needed) &&
        geom::length(c.compensated.p1 - later.p0) < tol::kPoint) {
      found = {j, c.compensated.p1};
      start = settings_.collision == CollisionCheck::Cdon ? j : 0;  // CDON searches on
    }
  }
  for (size_t j = start; j-- > 0;) {
    Piece& c = window_[j];  // (not const: its box is computed at the first use)
    if (c.index < oldest || c.emitted) break;
    if (!c.valid || (c.approach && !needed)) continue;
    // The element itself, then for an approach line with G461 a circle of the tool radius about
    // the end point of the uncompensated approach block, with G462 the line's extension; both
    // only to find an intersection (W1 2.4.10, details Q7).
    std::optional<geom::Crossing> best;
    if (c.box().overlaps(later_box))
      best = bridgeCrossing(c, c.compensated, false, later, next.side);
    if (!best && c.approach && (c.strategy == TrcStrategy::G461 || c.strategy == TrcStrategy::G462))
      best = bridgeCrossing(c, approachExtension(c, std::fabs(next.r0)), true, later, next.side);
    if (!best) continue;
    found = {j, best->p};
    if (settings_.collision != CollisionCheck::Cdon) break;
  }
  if (!found) return;
  auto [j, at] = *found;
  window_[j].compensated.p1 = at;
  next.compensated.p0 = at;
  next.transition.clear();
  next.open_before = false;
  omitAfter(j, at, true);
}

Element RadiusCompensation::approachExtension(const Piece& c, double r) {
  // G461: a circle of the tool radius about the end point of the uncompensated approach block.
  if (c.strategy == TrcStrategy::G461) return geom::fullCircle(c.programmed.p1, r);
  // G462: the first element's equidistant extended backwards from the approach point along its
  // start tangent, the mirror image of the retraction's extension (details Q7).
  Element extension;
  extension.p0 = c.compensated.p1;
  extension.p1 = c.compensated.p1 - c.first_tangent;
  return extension;
}

std::optional<geom::Crossing> RadiusCompensation::bridgeCrossing(
    const Piece& c, const Element& target, bool extension, const Element& later, double side) {
  auto accept = [&](const geom::Crossing& x) {
    const bool on_target = extension ? (!target.arc ? x.u1 * x.len1 > -tol::kPoint : true)
                                     : tol::insideElement(x.u1, x.len1);
    if (!on_target || !tol::onElement(x.u2, x.len2) || !tol::beforeEnd(x.u2, x.len2)) return false;
    // Like an inside corner: the later element turns towards the compensation side.
    // (With an extension the approach becomes the straight line to the point.)
    const Vec2 t1 = extension    ? geom::unit(x.p - c.compensated.p0)
                    : target.arc ? geom::tangentAt(target, x.p)
                                 : geom::unit(target.p1 - target.p0);
    return !(side * geom::cross(t1, geom::tangentAt(later, x.p)) < tol::kTurn);
  };
  // Nearest the start of the later element.
  return geom::nearestCrossing(target, later, accept, [](const geom::Crossing& x) { return x.u2; });
}

void RadiusCompensation::omitAfter(size_t keep, Vec2 at, bool keep_last) {
  PlaneAxes pa = planeAxes(sel_plane_);
  const size_t end = keep_last ? window_.size() - 1 : window_.size();
  for (size_t i = keep + 1; i < end; ++i) {
    Piece& p = window_[i];
    out_.warning(p.block, toInt(AlarmNumber::TrcBlockOmitted),
                 "path component of the block in the compensation plane becomes zero: block "
                 "omitted by bottleneck detection of tool radius compensation");
    // Everything but the plane motion runs at the intersection, in program order (Q5).
    if (std::fabs(p.block.end[pa.applicate] - p.block.start[pa.applicate]) > tol::kPoint)
      window_[keep].waiting.push_back(atPoint(p.block, at));
    for (auto& w : p.waiting) window_[keep].waiting.push_back(std::move(w));
  }
  if (keep_last && end > keep + 1) window_[keep + 1] = std::move(window_.back());
  window_.truncate(keep_last ? keep + 2 : keep + 1);
}

void RadiusCompensation::checkOpen(long next_index) const {
  for (size_t i = 1; i < window_.size(); ++i) {
    const Piece& p = window_[i];
    if (!p.open_before && p.valid) continue;
    const Piece& pred = window_[i - 1];
    if (pred.index < next_index - settings_.check_blocks)
      detail::collision(p.valid ? pred.block.line : p.block.line, settings_.check_blocks);
  }
}

}  // namespace ncoffset::trc
