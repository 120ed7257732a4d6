#include "out/html_report.hpp"

#include "out/shortest_number.hpp"

namespace ncoffset::out {
namespace {

void append(fmt::memory_buffer& b, std::string_view s) {
  b.append(s.data(), s.data() + s.size());
}

void appendLoc(fmt::memory_buffer& b, const SourceLoc& where) {
  appendXmlEscaped(b, where.file);
  fmt::format_to(fmt::appender(b), ":{}", where.line);
}

constexpr std::string_view kStyle =
    "<style>\n"
    "body{font-family:sans-serif;margin:1.5em;color:#222}\n"
    "table{border-collapse:collapse;margin:0.5em 0}\n"
    "th,td{border:1px solid #ccc;padding:2px 8px}\n"
    "th{background:#eee;text-align:left}\n"
    "td.n{text-align:right;font-variant-numeric:tabular-nums}\n"
    ".alarm{color:#b00000;font-weight:bold}\n"
    ".drawing svg{max-width:100%;height:auto;border:1px solid #ddd}\n"
    "</style>\n";

}  // namespace

HtmlReport::HtmlReport(std::FILE* f, View view, std::string program, std::string coords,
                       int decimals)
    : w_(f),
      svg_(f, view, false, decimals),
      program_(std::move(program)),
      coords_(std::move(coords)),
      decimals_(decimals) {}

void HtmlReport::segment(const Segment& s) {
  if (finished_) return;
  svg_.segment(s);
  long long n = counts_[0] + counts_[1] + counts_[2] + counts_[3];
  ++counts_[static_cast<size_t>(s.motion)];
  if (skip_first_) [[unlikely]] {  // from an assumed start position: only where it ends
    skip_first_ = false;
    box_.add(s.end);
  } else {
    (s.has_feed ? cut_length_ : rapid_length_) += segmentLength(s);  // rapid: no feed (path.hpp)
    box_.add(s);
  }
  if (n < kMaxRows) {
    auto it = fmt::appender(rows_);
    fmt::format_to(it,
                   "<tr><td class=\"n\">{}</td><td>{}</td><td class=\"n\">{}</td>"
                   "<td class=\"n\">{}</td><td class=\"n\">{}</td><td class=\"n\">",
                   s.line, motionName(s.motion), Number{s.end.x + 0.0, decimals_},
                   Number{s.end.y + 0.0, decimals_}, Number{s.end.z + 0.0, decimals_});
    if (s.has_feed) fmt::format_to(it, "{}", Number{s.feed, decimals_});
    append(rows_, "</td></tr>\n");
  }
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
    notes_.push_back({where, number, text});
  else
    ++notes_dropped_;
}

void HtmlReport::finish(const Alarm* alarm) {
  if (finished_) return;
  finished_ = true;
  auto& b = w_.buf();
  append(
      b,
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>ncoffset: ");
  appendXmlEscaped(b, program_);
  append(b, "</title>\n");
  append(b, kStyle);
  append(b, "</head>\n<body>\n<h1>ncoffset: ");
  appendXmlEscaped(b, program_);
  append(b, "</h1>\n");
  writeSummary(alarm);
  append(b, "<h2>Drawing</h2>\n<div class=\"drawing\">\n");
  w_.flush();  // the drawing is written by the SVG writer into the same file
  svg_.finish(alarm);
  append(b, "</div>\n<h2>Segments</h2>\n");
  long long total = counts_[0] + counts_[1] + counts_[2] + counts_[3];
  if (total == 0) {
    append(b, "<p>No segment.</p>\n");
  } else {
    append(b,
           "<table class=\"segments\">\n<tr><th>line</th><th>motion</th><th>x</th><th>y</th>"
           "<th>z</th><th>feed</th></tr>\n");
    b.append(rows_.data(), rows_.data() + rows_.size());
    append(b, "</table>\n");
    if (total > kMaxRows)
      fmt::format_to(fmt::appender(b),
                     "<p>The first {} segments are listed; {} more are not.</p>\n", kMaxRows,
                     total - kMaxRows);
  }
  append(b, "</body>\n</html>\n");
  w_.flush();
}

void HtmlReport::writeSummary(const Alarm* alarm) {
  auto& b = w_.buf();
  auto it = fmt::appender(b);
  append(b, "<h2>Summary</h2>\n<table class=\"summary\">\n");
  fmt::format_to(it, "<tr><th>coordinates</th><td>{}</td></tr>\n",
                 coords_ == "wcs" ? "WCS (workpiece, tool tip)" : "MCS (machine axes)");
  append(b, "<tr><th>result</th><td");
  if (alarm) {
    fmt::format_to(it, " class=\"alarm\">alarm {} at ", alarm->number);
    appendLoc(b, alarm->where);
    append(b, ": ");
    appendXmlEscaped(b, alarm->text);
  } else {
    append(b, ">ran to the end");
  }
  append(b, "</td></tr>\n");
  long long total = counts_[0] + counts_[1] + counts_[2] + counts_[3];
  fmt::format_to(it, "<tr><th>segments</th><td>{} (G0 {}, G1 {}, G2 {}, G3 {})</td></tr>\n", total,
                 counts_[0], counts_[1], counts_[2], counts_[3]);
  fmt::format_to(it,
                 "<tr><th>path length rapid (G0)</th><td class=\"n\">{:.3f} mm</td></tr>\n"
                 "<tr><th>path length at feed</th><td class=\"n\">{:.3f} mm</td></tr>\n",
                 rapid_length_, cut_length_);
  for (int i = 0; i < 3; ++i) {
    fmt::format_to(it, "<tr><th>{} range</th><td class=\"n\">", "XYZ"[i]);
    if (box_.empty())
      append(b, "&#8211;");
    else
      fmt::format_to(it, "{} &#8230; {}", Number{box_.lo[i] + 0.0, decimals_},
                     Number{box_.hi[i] + 0.0, decimals_});
    append(b, "</td></tr>\n");
  }
  append(b, "</table>\n");
  fmt::format_to(it, "<h2>Warnings and messages</h2>\n");
  if (notes_.empty()) {
    append(b, "<p>None.</p>\n");
    return;
  }
  append(b, "<table class=\"notes\">\n<tr><th>where</th><th>kind</th><th>text</th></tr>\n");
  for (const Note& n : notes_) {
    append(b, "<tr><td>");
    appendLoc(b, n.where);
    if (n.number)
      fmt::format_to(it, "</td><td>warning {}</td><td>", n.number);
    else
      append(b, "</td><td>message</td><td>");
    appendXmlEscaped(b, n.text);
    append(b, "</td></tr>\n");
    w_.lineDone();
  }
  append(b, "</table>\n");
  if (notes_dropped_)
    fmt::format_to(it, "<p>{} more warnings and messages are not listed.</p>\n", notes_dropped_);
}

}  // namespace ncoffset::out
