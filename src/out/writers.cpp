#include "out/writers.hpp"

#include "out/shortest_number.hpp"

namespace ncoffset::out {

void appendJsonString(fmt::memory_buffer& b, std::string_view s) {
  b.push_back('"');
  for (char c : s) {
    auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      b.push_back('\\');
      b.push_back(c);
    } else if (u < 0x20 || u >= 0x7f) {
      fmt::format_to(fmt::appender(b), "\\u{:04x}", u);
    } else {
      b.push_back(c);
    }
  }
  b.push_back('"');
}

void JsonLinesWriter::segment(const Segment& s) {
  auto& b = w_.buf();
  auto it = fmt::appender(b);
  fmt::format_to(it, "{{\"line\":{},\"file\":", s.line);
  appendJsonString(b, names_(s.file));
  const int d = decimals_;
  fmt::format_to(it, ",\"motion\":\"{}\",\"x\":{},\"y\":{},\"z\":{}", motionName(s.motion),
                 Number{s.end.x + 0.0, d}, Number{s.end.y + 0.0, d}, Number{s.end.z + 0.0, d});
  if (s.motion == Motion::G2 || s.motion == Motion::G3)
    fmt::format_to(it, ",\"cx\":{},\"cy\":{},\"cz\":{},\"normal\":[{},{},{}],\"turns\":{}",
                   Number{s.centre.x + 0.0, d}, Number{s.centre.y + 0.0, d},
                   Number{s.centre.z + 0.0, d}, Number{s.normal.x + 0.0, d},
                   Number{s.normal.y + 0.0, d}, Number{s.normal.z + 0.0, d}, s.turns);
  if (s.has_feed)
    fmt::format_to(it, ",\"feed\":{},\"feed_unit\":\"{}\"", Number{s.feed, d},
                   feedUnitName(s.feed_unit));
  if (s.motion == Motion::G34 || s.motion == Motion::G35)  // feed: the start lead (mm/rev)
    fmt::format_to(it, ",\"lead_change\":{}", Number{s.lead_change, d});
  if (!axes_.empty()) {  // the additional axes: "axes":{"A":90,...} (docs/output-formats.md)
    fmt::format_to(it, ",\"axes\":{{");
    for (size_t k = 0; k < axes_.names.size(); ++k) {
      if (k) b.push_back(',');
      appendJsonString(b, axes_.names[k]);
      fmt::format_to(it, ":{}", Number{axes_.positions[k] + 0.0, d});
    }
    b.push_back('}');
  }
  fmt::format_to(it, "}}\n");
  w_.lineDone();
}

void JsonLinesWriter::message(const SourceLoc& where, const std::string& text) {
  auto& b = w_.buf();
  fmt::format_to(fmt::appender(b), "{{\"message\":");
  appendJsonString(b, text);
  fmt::format_to(fmt::appender(b), ",\"file\":");
  appendJsonString(b, where.file);
  fmt::format_to(fmt::appender(b), ",\"line\":{}}}\n", where.line);
  w_.lineDone();
}

void JsonLinesWriter::warning(const SourceLoc& where, int number, const std::string& text) {
  auto& b = w_.buf();
  fmt::format_to(fmt::appender(b), "{{\"warning\":{},\"file\":", number);
  appendJsonString(b, where.file);
  fmt::format_to(fmt::appender(b), ",\"line\":{},\"text\":", where.line);
  appendJsonString(b, text);
  fmt::format_to(fmt::appender(b), "}}\n");
  w_.lineDone();
}

void JsonLinesWriter::eventHead(const char* type, int line, int file) {
  auto& b = w_.buf();
  fmt::format_to(fmt::appender(b), "{{\"type\":\"{}\",\"line\":{},\"file\":", type, line);
  appendJsonString(b, names_(file));
}

void JsonLinesWriter::tool(const ToolEvent& e) {
  static constexpr const char* kWord[] = {"T", "D", "M6"};
  eventHead("tool", e.line, e.file);
  const int d = decimals_;
  fmt::format_to(fmt::appender(w_.buf()),
                 ",\"word\":\"{}\",\"tool\":{},\"edge\":{},\"radius\":{},\"length\":[{},{},{}],"
                 "\"changed\":{}}}\n",
                 kWord[static_cast<int>(e.word)], e.tool, e.edge, Number{e.radius + 0.0, d},
                 Number{e.length.x + 0.0, d}, Number{e.length.y + 0.0, d},
                 Number{e.length.z + 0.0, d}, e.changed ? "true" : "false");
  w_.lineDone();
}

void JsonLinesWriter::mFunction(const MFunctionEvent& e) {
  eventHead("m", e.line, e.file);
  fmt::format_to(fmt::appender(w_.buf()), ",\"number\":{},\"spindle\":{}}}\n", e.number, e.spindle);
  w_.lineDone();
}

void JsonLinesWriter::dwell(const DwellEvent& e) {
  eventHead("dwell", e.line, e.file);
  fmt::format_to(fmt::appender(w_.buf()), ",\"seconds\":{},\"revolutions\":{}}}\n",
                 Number{e.seconds, decimals_}, Number{e.revolutions, decimals_});
  w_.lineDone();
}

void JsonLinesWriter::spindle(const SpindleEvent& e) {
  eventHead("spindle", e.line, e.file);
  fmt::format_to(fmt::appender(w_.buf()), ",\"speed\":{},\"spindle\":{}}}\n",
                 Number{e.speed, decimals_}, e.spindle);
  w_.lineDone();
}

void JsonLinesWriter::feed(const FeedEvent& e) {
  eventHead("feed", e.line, e.file);
  fmt::format_to(fmt::appender(w_.buf()), ",\"feed\":{}}}\n", Number{e.feed, decimals_});
  w_.lineDone();
}

void JsonLinesWriter::frame(const FrameEvent& e) {
  eventHead("frame", e.line, e.file);
  const auto& l = e.map.linear.m;
  const auto n = [this](double v) { return Number{v + 0.0, decimals_}; };
  fmt::format_to(fmt::appender(w_.buf()),
                 ",\"offset\":[{},{},{}],\"linear\":[[{},{},{}],[{},{},{}],[{},{},{}]]}}\n",
                 n(e.map.offset.x), n(e.map.offset.y), n(e.map.offset.z), n(l[0][0]), n(l[0][1]),
                 n(l[0][2]), n(l[1][0]), n(l[1][1]), n(l[1][2]), n(l[2][0]), n(l[2][1]),
                 n(l[2][2]));
  w_.lineDone();
}

void JsonLinesWriter::finish(const Alarm* alarm) {
  if (alarm) {
    auto& b = w_.buf();
    fmt::format_to(fmt::appender(b), "{{\"alarm\":{},\"file\":", alarm->number);
    appendJsonString(b, alarm->where.file);
    fmt::format_to(fmt::appender(b), ",\"line\":{},\"column\":{},\"text\":", alarm->where.line,
                   alarm->where.column);
    appendJsonString(b, alarm->text);
    fmt::format_to(fmt::appender(b), "}}\n");
  }
  w_.flush();
}

}  // namespace ncoffset::out
