#include "interp/variables.hpp"

#include <fmt/format.h>

#include <cmath>

#include "lang/evaluator.hpp"
#include "ncoffset/alarm.hpp"
#include "ncoffset/frame.hpp"

namespace ncoffset::interp {

using lang::Type;
using lang::Value;
using lang::VarType;

const char* varTypeName(VarType t) {
  switch (t) {
    case VarType::Int:
      return "INT";
    case VarType::Real:
      return "REAL";
    case VarType::Bool:
      return "BOOL";
    case VarType::String:
      return "STRING";
    case VarType::Char:
      return "CHAR";
    case VarType::Axis:
      return "AXIS";
    case VarType::Frame:
      return "FRAME";
  }
  return "?";
}

Value initialValue(VarType t) {
  switch (t) {
    case VarType::Int:
      return Value::integer(0);
    case VarType::Real:
      return Value::real(0);
    case VarType::Bool:
      return Value::boolean(false);
    case VarType::Char:
      return {Type::Char, 0, {}, {}};
    case VarType::String:
      return Value::string({});
    case VarType::Axis:
      return {Type::Axis, 0, "X", {}};
    case VarType::Frame:
      return {Type::Frame, 0, {}, std::make_shared<Frame>()};
  }
  return Value::real(0);
}

Value convertForStore(const Value& v, VarType t, int string_length, std::string_view name) {
  auto mismatch = [&]() -> Value {
    raise(AlarmNumber::TypeMismatch,
          fmt::format("operation not compatible with data type: {} value cannot be stored in {} "
                      "variable {}",
                      lang::typeName(v.type), varTypeName(t), name));
  };
  switch (t) {
    case VarType::Int:
      if (!v.isNumeric()) return mismatch();
      if (std::fabs(v.num) > 2147483647.0)
        raise(AlarmNumber::ValueRange,
              fmt::format("value range exceeded: {} does not fit INT {}", v.num, name));
      return Value::integer(lang::roundToInt(v.num) + 0.0);
    case VarType::Real:
      if (!v.isNumeric()) return mismatch();
      return Value::real(v.num);
    case VarType::Bool:
      if (!v.isNumeric()) return mismatch();
      return Value::boolean(v.num != 0);
    case VarType::Char:
      if (v.isNumeric()) {
        if (!(v.num >= 0 && v.num <= 255))
          raise(AlarmNumber::ValueRange,
                fmt::format("value range exceeded: {} does not fit CHAR {} (0..255)", v.num, name));
        return {Type::Char, lang::roundToInt(v.num), {}, {}};
      }
      if (v.type == Type::String && v.str.size() == 1)
        return {Type::Char, static_cast<double>(static_cast<unsigned char>(v.str[0])), {}, {}};
      return mismatch();
    case VarType::String: {
      if (v.type == Type::Frame || v.type == Type::Empty) return mismatch();
      std::string s = lang::toText(v);
      if (static_cast<int>(s.size()) > string_length)
        raise(
            AlarmNumber::ValueRange,
            fmt::format("value range exceeded: string of {} characters does not fit STRING[{}] {}",
                        s.size(), string_length, name));
      return Value::string(std::move(s));
    }
    case VarType::Axis:
      if (v.type == Type::Axis || v.type == Type::Symbol || v.type == Type::String)
        return {Type::Axis, 0, v.str, {}};
      return mismatch();
    case VarType::Frame:
      if (v.type != Type::Frame) return mismatch();
      return v;
  }
  return mismatch();
}

}  // namespace ncoffset::interp
