#include "out/vars_json.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <ostream>

#include "ncoffset/frame.hpp"
#include "out/writers.hpp"

namespace ncoffset::out {

namespace {
// Strings through the one JSON escaper of the writers.
void writeString(std::ostream& out, std::string_view s) {
  fmt::memory_buffer b;
  appendJsonString(b, s);
  out.write(b.data(), static_cast<std::streamsize>(b.size()));
}

void jsonValue(std::ostream& out, const lang::Value& v) {
  switch (v.type) {
    case lang::Type::Bool:
      out << (v.num != 0 ? "true" : "false");
      break;
    case lang::Type::Int:
    case lang::Type::Char:
      out << fmt::format("{}", static_cast<long long>(v.num));
      break;
    case lang::Type::Real:
      out << fmt::format("{}", v.num);
      break;
    case lang::Type::Frame: {
      const Frame& f = *v.frame;
      auto vec = [](Vec3 p) { return fmt::format("[{},{},{}]", p.x, p.y, p.z); };
      out << "{\"trans\":" << vec(f.coarse) << ",\"fine\":" << vec(f.fine)
          << ",\"rot\":" << vec(f.rotation) << ",\"scale\":" << vec(f.scale)
          << fmt::format(",\"mirror\":[{},{},{}]}}", f.mirror[0], f.mirror[1], f.mirror[2]);
      break;
    }
    default:
      writeString(out, v.str);
  }
}

void jsonVariable(std::ostream& out, const interp::UserVariable& v) {
  if (!v.isArray()) {
    jsonValue(out, v.data[0]);
    return;
  }
  size_t rows = static_cast<size_t>(v.dims[0]);
  size_t cols = static_cast<size_t>(v.dims[1]);
  out << '[';
  for (size_t i = 0; i < rows; ++i) {
    if (i) out << ',';
    if (cols == 0) {
      jsonValue(out, v.data[i]);
      continue;
    }
    out << '[';
    for (size_t j = 0; j < cols; ++j) {
      if (j) out << ',';
      jsonValue(out, v.data[i * cols + j]);
    }
    out << ']';
  }
  out << ']';
}
}  // namespace

void writeVariablesJson(std::ostream& out, const VariablesReport& report) {
  out << "{\"R\": {";
  bool first = true;
  for (const auto& [i, value] : report.r) {
    out << (first ? "" : ", ") << '"' << i << "\": " << fmt::format("{}", value);
    first = false;
  }
  out << '}';
  const ToolReadout& t = report.tool;
  const Vec3 l = t.lengths, o = t.orientation, len = t.length_bcs;
  out << fmt::format(
      ", \"$P_TOOLNO\": {}, \"$P_TOOL\": {}, \"$P_TOOLL\": [{},{},{}], \"$P_TOOLR\": {}, "
      "\"$P_TOOLO\": [{},{},{}], \"$TOOL_LENGTH_BCS\": [{},{},{}]",
      t.tool, t.edge, l.x, l.y, l.z, t.radius, o.x + 0.0, o.y + 0.0, o.z + 0.0, len.x + 0.0,
      len.y + 0.0, len.z + 0.0);
  // The D-number state: the active offset as $P_AD shows it (its CE last), the environments.
  out << ", \"$P_AD\": [";
  for (size_t k = 0; k < t.active_offset.size(); ++k)
    out << (k ? "," : "") << fmt::format("{}", t.active_offset[k] + 0.0);
  out << fmt::format("], \"$P_TOOLENVN\": {}", t.environments);
  const OffsetReadout& s = report.offsets;
  out << fmt::format(
      ", \"DL\": {}, \"$SUM_OFFSET\": [{}], \"$SETUP_OFFSET\": [{}], \"$P_TOFFL\": [{}], "
      "\"$P_TOFF\": [{},{},{}], \"$P_TOFFR\": {}",
      s.dl, fmt::join(s.sum, ","), fmt::join(s.setup, ","), fmt::join(s.toffl, ","), s.toff.x,
      s.toff.y, s.toff.z, s.toffr);
  // Smooth approach: P3 and P4 of the last evaluated approach (WCS), $P_APDV.
  const Vec3 apr = report.approach.apr, aep = report.approach.aep;
  out << fmt::format(", \"$P_APR\": [{},{},{}], \"$P_AEP\": [{},{},{}], \"$P_APDV\": {}",
                     apr.x + 0.0, apr.y + 0.0, apr.z + 0.0, aep.x + 0.0, aep.y + 0.0, aep.z + 0.0,
                     report.approach.valid ? 1 : 0);
  for (const auto& [k, v] : report.variables) {
    out << ", ";
    writeString(out, k);
    out << ": ";
    jsonVariable(out, *v);
  }
  out << "}\n";
}

}  // namespace ncoffset::out
