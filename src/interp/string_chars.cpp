// Single characters of a STRING variable (PM-JP "String operations: read and write a single
// character"): STRG[i] reads the character at position i (from 0) as a CHAR; STRG[i]=c writes
// one. Only characters within the string's current length are addressed (else alarm 17020).
#include <fmt/format.h>

#include <cmath>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::Value;

namespace {
size_t charIndex(const std::string& s, std::span<const Value> idx, std::string_view name) {
  if (idx.size() != 1)
    raise(AlarmNumber::ArrayIndex1, fmt::format("{}[..]: a STRING takes one index", name));
  const double i = lang::toNumber(idx[0], "character index");
  if (!(i >= 0 && i < static_cast<double>(s.size())) || i != std::floor(i))
    raise(AlarmNumber::ArrayIndex1,
          fmt::format("illegal array index 1: {}[{}] (the string has {} characters)", name, i,
                      s.size()));
  return static_cast<size_t>(i);
}
}  // namespace

bool Interpreter::readStringChar(const UserVariable& v, std::span<const Value> idx,
                                 std::string_view name, Value& out) {
  if (v.type != lang::VarType::String) return false;
  const std::string& s = v.data[0].str;
  const size_t i = charIndex(s, idx, name);
  out = {lang::Type::Char, static_cast<double>(static_cast<unsigned char>(s[i])), {}, {}};
  return true;
}

bool Interpreter::writeStringChar(UserVariable& v, std::span<const Value> idx,
                                  std::string_view name, const Value& x) {
  if (v.type != lang::VarType::String) return false;
  std::string& s = v.data[0].str;
  const size_t i = charIndex(s, idx, name);
  if (x.type == lang::Type::Char || x.type == lang::Type::Int)
    s[i] = static_cast<char>(static_cast<unsigned char>(x.num));
  else if (x.type == lang::Type::String && x.str.size() == 1)
    s[i] = x.str[0];
  else
    raise(AlarmNumber::TypeMismatch,
          fmt::format("operation not compatible with data type: {}[{}] takes one character", name,
                      i));
  return true;
}

}  // namespace ncoffset::interp
