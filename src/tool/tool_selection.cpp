#include "tool/tool_selection.hpp"

#include <fmt/format.h>

#include "ncoffset/alarm.hpp"

namespace ncoffset::tool {

namespace {

[[noreturn]] void edgeMissing(int t, int d) {
  raise(AlarmNumber::EdgeNotExisting, fmt::format("T no. = {}, D no. = {} not existing", t, d));
}

}  // namespace

int ToolSelection::resolveName(const std::string& name) const {
  int t = tools_.findByName(name);
  if (!t)
    raise(AlarmNumber::ToolNotExisting,
          fmt::format("T= \"{}\" not existing (no tool with $TC_TP2=\"{}\")", name, name));
  return t;
}

void ToolSelection::execute(const ToolWords& w, bool change_on_t, const SelectionContext& ctx) {
  if (w.tool) {
    int t = *w.tool;
    // Flat D numbers: T names no tool in the offset memory (W1 "Flat D number structure").
    if (t != 0 && !dconf_.flat && !tools_.tool(t))
      raise(AlarmNumber::ToolNotExisting, fmt::format("T= {} not existing", t));
    if (change_on_t)
      changeTool(t, w.edge.has_value(), ctx);
    else
      preselected_tool_ = t;  // MD22550 = 1: T preselects, M6 changes
  }
  if (w.tool_change && !change_on_t && preselected_tool_ >= 0) {
    changeTool(preselected_tool_, w.edge.has_value(), ctx);
    preselected_tool_ = -1;
  }
  if (w.edge) selectEdge(*w.edge, ctx);
  if (w.sum_offset) selectSumOffset(*w.sum_offset, ctx);
}

void ToolSelection::changeTool(int t, bool edge_programmed, const SelectionContext& ctx) {
  active_tool_ = t;
  if (dconf_.flat) return;  // flat D numbers: only D selects an offset (docs/tool-offsets.md)
  if (t == 0) {
    selectEdge(0, ctx);
    return;
  }
  if (edge_programmed) return;  // the D of the block selects the edge
  // MD20270: 0 no edge, > 0 that edge, -1 keep the old D number.
  selectEdge(ctx.default_edge < 0 ? active_edge_ : ctx.default_edge, ctx);
}

void ToolSelection::selectEdge(int d, const SelectionContext& ctx) {
  if (d == 0) {
    active_edge_ = 0;
    active_dl_ = 0;  // D0 (and T0) switch the sum offset off too (W1 18.11)
    edge_ = EdgeSnapshot{};
    return;
  }
  const EdgeData* e = tools_.edge(edgeOwner(), d);
  if (!e) {
    if (dconf_.flat)
      raise(AlarmNumber::EdgeNotExisting, fmt::format("D no. = {} not existing (flat D)", d));
    edgeMissing(active_tool_, d);
  }
  active_edge_ = d;
  // MD20272: the DL a D selection brings (0 none, -1 the DL number before).
  if (ctx.default_sum_offset >= 0) active_dl_ = ctx.default_sum_offset;
  snapshot(*e, ctx);
}

void ToolSelection::snapshot(const EdgeData& e, const SelectionContext& ctx) {
  edge_.valid = true;
  edge_.data = e;
  if (active_dl_ > 0)
    addSumOffsets(edge_.data, sums_, active_tool_, active_edge_, active_dl_, sum_limits_);
  edge_.settings = ctx.settings;
  edge_.mirrored = ctx.mirrored;
  refreshRadius();
}

void ToolSelection::refreshRadius() {
  edge_.radius = effectiveLengths(edge_.data, edge_.settings).radius + programmed_.radius;
  const int sl = edge_.data.cuttingEdgePosition();
  edge_.has_tip =
      isTurningOrGrindingType(edge_.data.type()) && sl >= 1 && sl <= 8 && edge_.radius != 0.0;
  edge_.offset_cached = false;
}

void ToolSelection::cache(Plane plane) const {
  edge_.cached_offset =
      ncoffset::lengthVector(edge_.data, edge_.settings, plane, edge_.mirrored) +
      programmedVector(programmed_, edge_.data.type(), edge_.settings, plane, edge_.mirrored);
  edge_.cached_tip = ncoffset::tipVector(edge_.data, edge_.settings, plane, edge_.radius);
  edge_.cached_plane = plane;
  edge_.offset_cached = true;
  if (carrier_) {
    edge_.cached_offset = carrier_rotation_ * edge_.cached_offset + carrier_offset_;
    edge_.cached_tip = carrier_rotation_ * edge_.cached_tip;
  }
}

void ToolSelection::setCarrier(const Mat3& rotation, Vec3 offset, bool active) {
  carrier_ = active;
  carrier_rotation_ = active ? rotation : Mat3::identity();
  carrier_offset_ = active ? offset : Vec3{};
  edge_.offset_cached = false;
}

Vec3 ToolSelection::tipVector(Plane plane) const {
  if (!edge_.has_tip) return {};
  if (!cachedFor(plane)) cache(plane);
  return edge_.cached_tip;
}

EffectiveLengths ToolSelection::lengths(Plane plane) const {
  if (!edge_.valid) return {};
  // $P_TOOLL/$P_TOOLR: the edge with its DL (in the snapshot) and the programmed offsets.
  EffectiveLengths l = effectiveLengths(edge_.data, edge_.settings);
  const LengthAssignment a = assignLengths(edge_.data.type(), plane, edge_.settings.length_const,
                                           edge_.settings.length_type);
  const std::array<double, 3> c = programmedComponents(programmed_, a);
  for (size_t k = 0; k < 3; ++k) l.total[k] += c[k];
  l.radius = edge_.radius;
  return l;
}

Vec3 ToolSelection::orientation(Plane plane) const {
  Vec3 o;
  if (edge_.valid)
    o = toolOrientation(edge_.data, edge_.settings, plane, edge_.mirrored);
  else
    o[planeAxes(plane).applicate] = 1;
  return carrier_ ? carrier_rotation_ * o : o;
}

}  // namespace ncoffset::tool
