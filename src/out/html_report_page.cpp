// The parts of the HTML report's page (html_report.hpp): the static tables (they read without
// the script) and the data and script the interactive parts are made from.
#include <cmath>

#include "out/html_report.hpp"
#include "out/shortest_number.hpp"

namespace ncoffset::out {
namespace {

#include "out/report_assets.inc"

void append(fmt::memory_buffer& b, std::string_view s) {
  b.append(s.data(), s.data() + s.size());
}

// `<td>FILE:LINE</td>` that the page links to the program text.
void appendLocCell(fmt::memory_buffer& b, const SourceLoc& where, int file) {
  fmt::format_to(fmt::appender(b), "<td class=\"nco-goto\" data-file=\"{}\" data-line=\"{}\">",
                 file, where.line);
  appendXmlEscaped(b, where.file);
  fmt::format_to(fmt::appender(b), ":{}</td>", where.line);
}

const char* viewName(View v) {
  switch (v) {
    case View::XY:
      return "xy";
    case View::ZX:
      return "zx";
    case View::YZ:
      return "yz";
  }
  return "xy";
}

// h:mm:ss.s
std::string duration(double seconds) {
  const long long whole = static_cast<long long>(seconds);
  return fmt::format("{}:{:02}:{:04.1f}", whole / 3600, (whole / 60) % 60,
                     seconds - static_cast<double>(whole - whole % 60));
}

}  // namespace

void HtmlReport::writeHead() {
  auto& b = w_.buf();
  append(
      b,
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>ncoffset: ");
  appendXmlEscaped(b, program_);
  append(b, "</title>\n<style>\n");
  for (std::string_view piece : kReportCss) append(b, piece);
  append(b, "</style>\n</head>\n<body>\n<header><h1>ncoffset: ");
  appendXmlEscaped(b, program_);
  append(b,
         "</h1><span id=\"nco-status\">The interactive drawing needs JavaScript.</span>"
         "</header>\n<main id=\"nco-app\">\n<section id=\"nco-source\"><div id=\"nco-tabs\"></div>"
         "<div id=\"nco-src\" class=\"nco-vlist\" tabindex=\"0\"></div></section>\n"
         "<section id=\"nco-drawing\"><div id=\"nco-toolbar\"></div>"
         "<svg id=\"nco-svg\" xmlns=\"http://www.w3.org/2000/svg\"></svg>"
         "<div id=\"nco-tip\" hidden></div></section>\n</main>\n<section id=\"nco-info\">\n");
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
    appendXmlEscaped(b, alarm->where.file);
    fmt::format_to(it, ":{}: ", alarm->where.line);
    appendXmlEscaped(b, alarm->text);
  } else {
    append(b, ">ran to the end");
  }
  append(b, "</td></tr>\n");
  long long total = 0;
  for (long long c : counts_) total += c;
  fmt::format_to(it, "<tr><th>segments</th><td>{} (G0 {}, G1 {}, G2 {}, G3 {}", total, counts_[0],
                 counts_[1], counts_[2], counts_[3]);
  for (size_t k = 4; k < counts_.size(); ++k)  // thread and tapping lines, where there are any
    if (counts_[k] > 0)
      fmt::format_to(it, ", {} {}", motionName(static_cast<Motion>(k)), counts_[k]);
  append(b, ")</td></tr>\n");
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
  fmt::format_to(it,
                 "<tr><th>time estimate</th><td class=\"n\" id=\"nco-time\">{} "
                 "(without acceleration {}; rapid {}, dwell {})</td></tr>\n",
                 duration(time_.seconds()), duration(time_.secondsNoAccel()),
                 duration(time_.rapidSeconds()), duration(time_.dwellSeconds()));
  append(b,
         "</table>\n<p class=\"nco-note\">The time is an estimate, not the control's: each block "
         "is a trapezoid from standstill to standstill (as with exact stop G60) at its feed "
         "(G95: times the last spindle speed S; G93: 1/F minutes), rapid traverse at the path "
         "velocity the axes allow by $MA_MAX_AX_VELO, accelerated by $MA_MAX_AX_ACCEL; dwells "
         "added. In continuous-path mode (G64) the machine lies between the two times.");
  if (time_.blocksWithoutSpeed())
    fmt::format_to(it, " {} G95 blocks without a spindle speed are not in it.",
                   time_.blocksWithoutSpeed());
  append(b, "</p>\n");
}

void HtmlReport::writeTools() {
  auto& b = w_.buf();
  auto it = fmt::appender(b);
  append(b, "<h2>Tools</h2>\n");
  if (tools_.empty()) {
    append(b, "<p>No tool selected.</p>\n");
    return;
  }
  append(b,
         "<table class=\"tools\">\n<tr><th>T</th><th>D</th><th>type</th><th>L1</th><th>L2</th>"
         "<th>L3</th><th>R</th><th>cutting edge position</th><th>segments</th><th>selected in"
         "</th></tr>\n");
  for (size_t i = 0; i < tools_.size(); ++i) {
    const ToolSlot& t = tools_[i];
    fmt::format_to(it, "<tr data-slot=\"{}\"><td>{}</td><td>{}</td>", i, t.tool, t.edge);
    if (t.data) {
      fmt::format_to(it, "<td>{}</td>", t.data->type());
      for (int k = 3; k <= 5; ++k)
        fmt::format_to(it, "<td class=\"n\">{}</td>", Number{t.data->dp[static_cast<size_t>(k)]});
      fmt::format_to(it, "<td class=\"n\">{}</td><td>{}</td>", Number{t.radius},
                     t.data->cuttingEdgePosition());
    } else {
      fmt::format_to(it, "<td></td><td></td><td></td><td></td><td class=\"n\">{}</td><td></td>",
                     Number{t.radius});
    }
    fmt::format_to(it, "<td class=\"n\">{}</td><td>", t.segments);
    for (size_t k = 0; k < t.uses.size(); ++k) {
      const SourceLoc& u = t.uses[k];
      fmt::format_to(it, "{}<span class=\"nco-goto\" data-file=\"{}\" data-line=\"{}\">",
                     k ? ", " : "", fileIndex(u.file), u.line);
      appendXmlEscaped(b, u.file);
      fmt::format_to(it, ":{}</span>", u.line);
    }
    if (t.more_uses) fmt::format_to(it, " and {} more", t.more_uses);
    append(b, "</td></tr>\n");
  }
  append(b,
         "</table>\n<p class=\"nco-note\">R: the edge's compensation radius with wear; type, L1 "
         "to L3 and the cutting edge position as $TC_DP1, $TC_DP3..5 and $TC_DP2 were when the "
         "edge was selected.</p>\n");
}

void HtmlReport::writeNotes(const Alarm* alarm) {
  auto& b = w_.buf();
  append(b, "<h2>Warnings, messages and alarm</h2>\n");
  if (notes_.empty() && !alarm) {
    append(b, "<p>None.</p>\n");
  } else {
    append(b, "<table class=\"notes\">\n<tr><th>where</th><th>kind</th><th>text</th></tr>\n");
    for (const Note& n : notes_) {
      append(b, "<tr>");
      appendLocCell(b, n.where, fileIndex(n.where.file));
      if (n.number)
        fmt::format_to(fmt::appender(b), "<td>warning {}</td><td>", n.number);
      else
        append(b, "<td>message</td><td>");
      appendXmlEscaped(b, n.text);
      append(b, "</td></tr>\n");
      w_.lineDone();
    }
    if (alarm) {
      append(b, "<tr class=\"alarm\">");
      appendLocCell(b, alarm->where, fileIndex(alarm->where.file));
      fmt::format_to(fmt::appender(b), "<td>alarm {}</td><td>", alarm->number);
      appendXmlEscaped(b, alarm->text);
      append(b, "</td></tr>\n");
    }
    append(b, "</table>\n");
  }
  if (notes_dropped_)
    fmt::format_to(fmt::appender(b), "<p>{} more warnings and messages are not listed.</p>\n",
                   notes_dropped_);
  append(b, "<h2>Segments</h2>\n<div id=\"nco-seglist\" class=\"nco-vlist\"></div>\n</section>\n");
}

// The data the script draws from: `<script type="application/json" id="nco-data">` (layout in
// docs/output-formats.md "HTML"), then the script.
void HtmlReport::writeData(const Alarm* alarm) {
  auto& b = w_.buf();
  auto it = fmt::appender(b);
  fmt::format_to(it,
                 "<script type=\"application/json\" id=\"nco-data\">{{\"view\":\"{}\","
                 "\"coords\":\"{}\",\"decimals\":{},\"skip_first\":{},\"program\":",
                 viewName(view_), coords_ == "wcs" ? "wcs" : "mcs", decimals_,
                 skip_first_ ? "true" : "false");
  appendScriptString(b, program_);
  writeFiles();
  append(b, ",\n\"out\":");
  output_.copyTo(b, f_);
  append(b, ",\n\"prog\":");
  programmed_.copyTo(b, f_);
  append(b, ",\n\"tools\":[");
  for (size_t i = 0; i < tools_.size(); ++i) {
    const ToolSlot& t = tools_[i];
    fmt::format_to(it, "{}{{\"t\":{},\"d\":{},\"r\":{},\"l\":[{},{},{}],\"type\":{},\"sl\":{}}}",
                   i ? "," : "", t.tool, t.edge, Number{t.radius}, Number{t.length.x + 0.0},
                   Number{t.length.y + 0.0}, Number{t.length.z + 0.0}, t.data ? t.data->type() : 0,
                   t.data ? t.data->cuttingEdgePosition() : 0);
  }
  append(b, "],\"changes\":[");
  for (size_t i = 0; i < changes_.size(); ++i)
    fmt::format_to(it, "{}[{},{}]", i ? "," : "", changes_[i].segment, changes_[i].slot);
  append(b, "],\n\"frames\":[");
  for (size_t i = 0; i < frames_.size(); ++i)
    fmt::format_to(it, "{}[{},{},{},{}]", i ? "," : "", frames_[i].segment,
                   Number{frames_[i].origin.x + 0.0}, Number{frames_[i].origin.y + 0.0},
                   Number{frames_[i].origin.z + 0.0});
  append(b, "],\n\"notes\":[");
  for (size_t i = 0; i < notes_.size(); ++i) {
    const Note& n = notes_[i];
    fmt::format_to(it, "{}[{},{},{},", i ? "," : "", fileIndex(n.where.file), n.where.line,
                   n.number);
    appendScriptString(b, n.text);
    fmt::format_to(it, ",{}]", n.segment);
  }
  append(b, "],\"alarm\":");
  if (alarm) {
    fmt::format_to(it, "[{},{},{},", fileIndex(alarm->where.file), alarm->where.line,
                   alarm->number);
    appendScriptString(b, alarm->text);
    fmt::format_to(it, ",{}]", output_.size());
  } else {
    append(b, "null");
  }
  append(b, "}</script>\n<script>\n");
  for (std::string_view piece : kReportJs) {
    append(b, piece);
    w_.lineDone();
  }
  append(b, "</script>\n</body>\n</html>\n");
}

// "files":[names],"src":[texts]: every file of the run with its text as it was read.
void HtmlReport::writeFiles() {
  auto& b = w_.buf();
  const int n = context_.file_count ? context_.file_count() : 0;
  append(b, ",\"files\":[");
  for (int i = 0; i < n; ++i) {
    if (i) b.push_back(',');
    appendScriptString(b, context_.file_name(i));
  }
  append(b, "],\n\"src\":[");
  for (int i = 0; i < n; ++i) {
    if (i) b.push_back(',');
    std::string_view text = context_.file_text ? context_.file_text(i) : std::string_view();
    b.push_back('"');
    constexpr size_t kPiece = 1 << 16;
    for (size_t at = 0; at < text.size(); at += kPiece) {
      appendScriptString(b, text.substr(at, kPiece), false);
      w_.lineDone();
    }
    b.push_back('"');
  }
  b.push_back(']');
}

}  // namespace ncoffset::out
