// The glue between the channel and the tool selection (src/tool/tool_selection.hpp): the
// context an edge selection snapshots, and the caller's arrays for LENTOAX.
#include <fmt/format.h>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::Type;
using lang::Value;

tool::SelectionContext Interpreter::selectionContext() const {
  tool::SelectionContext ctx;
  ctx.settings.mirror_length = data_.get(sd_mirror_length_) != 0;
  ctx.settings.mirror_wear = data_.get(sd_mirror_wear_) != 0;
  ctx.settings.wear_sign_cutpos = data_.get(sd_cutpos_) != 0;
  ctx.settings.wear_sign = data_.get(sd_wear_sign_) != 0;
  ctx.settings.length_const = static_cast<long>(data_.get(sd_length_const_));
  ctx.settings.length_type = static_cast<long>(data_.get(sd_length_type_));
  ctx.default_edge = static_cast<int>(data_.get(md_default_edge_));
  ctx.mirrored = frames_.active().mirror;
  return ctx;
}

void Interpreter::executeToolWords() {
  if (!words_.tool && !words_.edge && !words_.tool_change) return;  // the usual block
  tools_.execute({words_.tool, words_.edge, words_.tool_change}, data_.get(md_change_mode_) == 0,
                 selectionContext());
  if (events_) toolEvent();
}

std::span<Value> Interpreter::arrayArgument(std::string_view fn, const Value& v, bool integer,
                                            int rows, int cols, const char* what) {
  const lang::VarType type = integer ? lang::VarType::Int : lang::VarType::Real;
  if (v.type != Type::ArrayRef)
    raise(AlarmNumber::WrongCallParams, fmt::format("{}: {} must be an array variable", fn, what));
  UserVariable* var = vars_.find(v.str);
  if (!var || var->type != type || var->dims[0] != rows || var->dims[1] != cols)
    raise(AlarmNumber::WrongCallParams,
          fmt::format("{}: {} must be DEF {} {}[{}]", fn, what,
                      type == lang::VarType::Int ? "INT" : "REAL", v.str,
                      cols ? fmt::format("{},{}", rows, cols) : fmt::format("{}", rows)));
  return var->data;
}

Value Interpreter::callLentoax(std::span<const Value> args) {
  auto array = [&](const Value& v, bool integer, int rows, int cols,
                   const char* what) -> std::span<Value> {
    return arrayArgument("LENTOAX", v, integer, rows, cols, what);
  };
  return tools_.callLentoax(args, array, modal_.plane, frames_.map().linear);
}

}  // namespace ncoffset::interp
