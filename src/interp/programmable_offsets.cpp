// The channel's words for the sum offsets and the programmable tool offsets: DL= (FM-W1 01/2015
// 18.11) and TOFFL, TOFFL[1..3], TOFF[axis], TOFFR with their reads $P_TOFFL, $P_TOFF, $P_TOFFR
// (PM Fundamentals 12/2019 2.5 "Programmable tool offset"). docs/tool-offsets.md sections 10, 11.
#include <fmt/format.h>

#include <cmath>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"
#include "out/vars_json.hpp"

namespace ncoffset::interp {

using lang::Value;

namespace {

double offsetValue(const Value& v, std::string_view name) {
  const double x = lang::toNumber(v, "tool offset");
  if (!(std::fabs(x) <= 1e9))
    raise(AlarmNumber::ValueRange, fmt::format("value range exceeded: {}={}", name, x));
  return x;
}

// TOFFL[n] (n 1..3; without an index n = 0, which acts like 1).
size_t lengthIndex(std::string_view name, std::span<const Value> idx, bool indexed, int lo) {
  if (!indexed) return 0;
  if (idx.size() != 1)
    raise(AlarmNumber::ArrayIndex1, fmt::format("{} takes one index (1..3)", name));
  const double n = lang::toNumber(idx[0], "length component");
  if (n != std::floor(n) || n < lo || n > 3)
    raise(AlarmNumber::ArrayIndex1,
          fmt::format("illegal array index: {}[{}] ({}..3: the length components)", name, n, lo));
  return static_cast<size_t>(n);
}

}  // namespace

bool Interpreter::offsetWordWrite(std::string_view name, std::span<const Value> idx, bool indexed,
                                  const Value& v) {
  if (name == "DL") {
    if (indexed) raise(AlarmNumber::ArrayIndex1, "DL takes no index");
    const double dl = lang::toNumber(v, "DL");
    if (dl < 0 || dl != std::floor(dl) || dl > 1e6)
      raise(AlarmNumber::ValueRange,
            fmt::format("value range exceeded: DL={} (sum offset numbers are whole, 0..6)", dl));
    words_.sum_offset = static_cast<int>(dl);  // acts after the block's T and D
    return true;
  }
  if (name != "TOFFL" && name != "TOFF" && name != "TOFFR") return false;
  tool::ProgrammedOffsets p = tools_.programmed();
  const double x = toMm(offsetValue(v, name));  // a length: inch under G70/G700
  if (name == "TOFFL") {
    p.length[lengthIndex(name, idx, indexed, 1)] = x;
  } else if (name == "TOFF") {
    if (!indexed || idx.size() != 1) raise(AlarmNumber::ArrayIndex1, "TOFF needs [axis]");
    p.axis[static_cast<size_t>(axisIndexOf(idx[0]))] = x;
  } else {
    if (indexed) raise(AlarmNumber::ArrayIndex1, "TOFFR takes no index");
    p.radius = x;
  }
  tools_.setProgrammed(p);
  return true;
}

bool Interpreter::offsetWordRead(std::string_view name, std::span<const Value> idx, bool indexed,
                                 Value& out) {
  const tool::ProgrammedOffsets& p = tools_.programmed();
  if (name == "$P_TOFFL") {
    out = Value::real(p.length[lengthIndex(name, idx, indexed, 0)]);
  } else if (name == "$P_TOFF") {
    if (!indexed || idx.size() != 1) raise(AlarmNumber::ArrayIndex1, "$P_TOFF needs [axis]");
    out = Value::real(p.axis[static_cast<size_t>(axisIndexOf(idx[0]))]);
  } else if (name == "$P_TOFFR") {
    if (indexed) raise(AlarmNumber::ArrayIndex1, "$P_TOFFR takes no index");
    out = Value::real(p.radius);
  } else {
    return false;
  }
  return true;
}

out::OffsetReadout Interpreter::offsetReadout() const {
  out::OffsetReadout r;
  const tool::ProgrammedOffsets& p = tools_.programmed();
  r.toffl = p.length;
  r.toff = {p.axis[0], p.axis[1], p.axis[2]};
  r.toffr = p.radius;
  r.dl = tools_.activeSumOffset();
  if (r.dl <= 0) return r;
  const tool::SumOffsetMemory& m = tools_.sumOffsets();
  const int t = tools_.activeTool(), d = tools_.activeEdge();
  for (bool setup : {false, true})
    if (const tool::SumOffsetMemory::Set* set = m.find(setup, t, d, r.dl))
      for (size_t k = 0; k < 4; ++k) (setup ? r.setup : r.sum)[k] = (*set)[k];
  return r;
}

// What an edge or DL selection takes from the channel (W1 2.5: the setting data and the mirroring
// at the selection; MD20270, MD20272) and what MD18110/MD18112 allow.
tool::SelectionContext Interpreter::selectionContext() const {
  tool::SelectionContext ctx;
  ctx.settings.mirror_length = data_.get(sd_mirror_length_) != 0;
  ctx.settings.mirror_wear = data_.get(sd_mirror_wear_) != 0;
  ctx.settings.wear_sign_cutpos = data_.get(sd_cutpos_) != 0;
  ctx.settings.wear_sign = data_.get(sd_wear_sign_) != 0;
  ctx.settings.length_const = static_cast<long>(data_.get(sd_length_const_));
  ctx.settings.length_type = static_cast<long>(data_.get(sd_length_type_));
  ctx.default_edge = static_cast<int>(data_.get(md_default_edge_));
  ctx.default_sum_offset = static_cast<int>(data_.get("$MC_SUMCORR_DEFAULT"));
  ctx.mirrored = frames_.active().mirror;
  return ctx;
}

void Interpreter::syncSumOffsetLimits() {
  tool::SumOffsetLimits l;
  l.max_per_edge = static_cast<int>(data_.get("$MN_MM_MAX_SUMCORR_PER_CUTTEDGE"));
  l.setup_offsets = (static_cast<long long>(data_.get("$MN_MM_KIND_OF_SUMCORR")) & 16) != 0;
  tools_.setSumOffsetLimits(l);
}

}  // namespace ncoffset::interp
