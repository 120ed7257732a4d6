#include "out/html_report.hpp"

#include <cmath>

namespace ncoffset::out {
namespace {
// Bit for bit: the same segment passed through two sinks, not a computed comparison.
bool samePoint(const Vec3& a, const Vec3& b) {
  return a.x == b.x && a.y == b.y && a.z == b.z;
}
}  // namespace

HtmlReport::HtmlReport(std::FILE* f, View view, std::string program, std::string coords,
                       int decimals, ReportContext context)
    : w_(f),
      f_(f),
      view_(view),
      program_(std::move(program)),
      coords_(std::move(coords)),
      decimals_(decimals),
      context_(std::move(context)),
      output_(decimals),
      programmed_(decimals) {}

void HtmlReport::segment(const Segment& s) {
  if (finished_) return;
  if (!dynamics_known_) {  // the init files have run by the first motion
    dynamics_known_ = true;
    if (context_.dynamics) time_.setDynamics(context_.dynamics());
  }
  // The programmed segment of this block, where it is the same segment: a flag, not a copy.
  bool same = false;
  if (!held_.empty()) {
    const Segment& p = held_.front();
    same = p.line == s.line && p.file == s.file && p.motion == s.motion &&
           p.has_feed == s.has_feed && samePoint(p.start, s.start) && samePoint(p.end, s.end) &&
           (!isArc(s) ||
            (samePoint(p.centre, s.centre) && samePoint(p.normal, s.normal) && p.turns == s.turns));
    if (same) held_.pop_front();
  }
  output_.add(s, tool_slot_, same);
  ++counts_[static_cast<size_t>(s.motion)];
  if (skip_first_ && !first_seen_) [[unlikely]] {  // from an assumed start: only where it ends
    box_.add(s.end);
  } else {
    (s.has_feed ? cut_length_ : rapid_length_) += segmentLength(s);  // rapid: no feed (path.hpp)
    box_.add(s);
    time_.segment(s);
  }
  first_seen_ = true;
  if (tool_slot_ >= 0) ++tools_[static_cast<size_t>(tool_slot_)].segments;
}

void HtmlReport::programmed(const Segment& s) {
  if (finished_) return;
  if (held_.size() >= kHeld) {
    programmed_.add(held_.front(), tool_slot_);
    held_.pop_front();
  }
  held_.push_back(s);
}

void HtmlReport::message(const SourceLoc& where, const std::string& text) {
  note(where, 0, text);
}

void HtmlReport::warning(const SourceLoc& where, int number, const std::string& text) {
  note(where, number, text);
}

void HtmlReport::note(const SourceLoc& where, int number, const std::string& text) {
  if (finished_) return;
  if (notes_.size() < static_cast<size_t>(kMaxNotes))
    notes_.push_back({where, number, text, output_.size()});
  else
    ++notes_dropped_;
}

// A slot per tool, edge and offset (radius and length vector): a changed offset of the same
// edge is a row of its own, so the table shows what each block ran with.
void HtmlReport::tool(const ToolEvent& e) {
  if (finished_) return;
  auto same = [&e](const ToolSlot& t) {
    return t.tool == e.tool && t.edge == e.edge && t.radius == e.radius &&
           t.length.x == e.length.x && t.length.y == e.length.y && t.length.z == e.length.z;
  };
  int slot = -1;
  for (size_t i = 0; i < tools_.size() && slot < 0; ++i)
    if (same(tools_[i])) slot = static_cast<int>(i);
  if (slot < 0 && tools_.size() < static_cast<size_t>(kMaxToolSlots)) {
    ToolSlot t;
    t.tool = e.tool, t.edge = e.edge, t.radius = e.radius, t.length = e.length;
    if (context_.edge && e.tool > 0 && e.edge > 0) t.data = context_.edge(e.tool, e.edge);
    tools_.push_back(std::move(t));
    slot = static_cast<int>(tools_.size()) - 1;
  }
  if (slot < 0) return;  // more combinations than the table lists: the last one stays
  ToolSlot& t = tools_[static_cast<size_t>(slot)];
  if (t.uses.size() < static_cast<size_t>(kMaxUses)) {
    std::string name = context_.file_name ? context_.file_name(e.file) : std::string();
    t.uses.push_back({std::move(name), e.line});
  } else {
    ++t.more_uses;
  }
  if (slot != tool_slot_ && changes_.size() < static_cast<size_t>(kMaxToolChanges))
    changes_.push_back({output_.size(), slot});
  tool_slot_ = slot;
}

void HtmlReport::frame(const FrameEvent& e) {
  if (finished_ || frames_.size() >= kMaxFrames) return;
  frames_.push_back({output_.size(), e.map.offset});
}

void HtmlReport::finish(const Alarm* alarm) {
  if (finished_) return;
  for (const Segment& p : held_) programmed_.add(p, tool_slot_);
  held_.clear();
  finished_ = true;
  writeHead();
  writeSummary(alarm);
  writeTools();
  writeNotes(alarm);
  writeData(alarm);
  w_.flush();
}

int HtmlReport::fileIndex(const std::string& name) const {
  if (!context_.file_count || !context_.file_name) return -1;
  for (int i = 0, n = context_.file_count(); i < n; ++i)
    if (context_.file_name(i) == name) return i;
  return -1;
}

}  // namespace ncoffset::out
