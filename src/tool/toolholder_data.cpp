// The toolholder data blocks $TC_CARR1..65[m] (W1 2.5.2 "System variables"; PGA "List of system
// variables"): reads and writes from init files and programs.
#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>

#include "lang/evaluator.hpp"
#include "ncoffset/alarm.hpp"
#include "tool/toolholder.hpp"

namespace ncoffset::tool {

using lang::Type;
using lang::Value;

namespace {

// The parameter number of "$TC_CARRn" (0 for another name; -1 for $TC_CARR names that are no
// parameter: 47..54 and 61..63 "are not defined and produce an alarm", W1 2.5.2).
int parameterNumber(std::string_view name) {
  constexpr std::string_view kPrefix = "$TC_CARR";
  if (name.substr(0, kPrefix.size()) != kPrefix) return 0;
  std::string_view num = name.substr(kPrefix.size());
  int n = 0;
  auto res = std::from_chars(num.data(), num.data() + num.size(), n);
  if (num.empty() || res.ec != std::errc() || res.ptr != num.data() + num.size()) return -1;
  if (n < 1 || n > 65 || (n >= 47 && n <= 54) || (n >= 61 && n <= 63)) return -1;
  return n;
}

int holderIndex(const Value& v, int count) {
  double m = lang::toNumber(v, "toolholder number");
  if (m != std::floor(m) || m < 0 || m > count)
    raise(AlarmNumber::ArrayIndex1,
          fmt::format("illegal array index: toolholder {} outside 0..{} (MD18088 "
                      "$MN_MM_NUM_TOOL_CARRIER)",
                      m, count));
  return static_cast<int>(m);
}

std::string upperText(const Value& v, std::string_view name) {
  if (v.isNumeric() && v.num == 0 && v.type != Type::Char) return {};  // "initialized with zero"
  if (!v.isText())
    raise(AlarmNumber::TypeMismatch,
          fmt::format("operation not compatible with data type: {} takes an axis name", name));
  std::string s = v.str;
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

char kindOf(const Value& v) {
  if (v.type == Type::String || v.type == Type::Symbol)
    return v.str.size() == 1 ? static_cast<char>(std::toupper(static_cast<unsigned char>(v.str[0])))
                             : '?';
  if (v.isNumeric()) {
    const double c = v.num;
    return c >= 0 && c < 128 ? static_cast<char>(std::toupper(static_cast<int>(c))) : '?';
  }
  raise(AlarmNumber::TypeMismatch,
        "operation not compatible with data type: $TC_CARR23 takes a CHAR (\"T\", \"P\", \"M\")");
}

// $TC_CARRn[m]: the parameter number n and holder m (false for a name that is no $TC_CARR).
bool address(std::string_view name, std::span<const Value> idx, bool indexed, int count, int& n,
             int& m) {
  n = parameterNumber(name);
  if (n == 0) return false;
  if (n < 0) raise(AlarmNumber::NameNotDefined, fmt::format("name {} not defined", name));
  if (!indexed || idx.size() != 1)
    raise(AlarmNumber::ArrayIndex1, fmt::format("{} needs [toolholder number]", name));
  m = holderIndex(idx[0], count);
  return true;
}

}  // namespace

const CarrierData& ToolCarriers::data(int m) const {
  static const CarrierData kZero;
  auto it = blocks_.find(m);
  return it == blocks_.end() ? kZero : it->second;
}

bool ToolCarriers::read(std::string_view name, std::span<const Value> idx, bool indexed,
                        Value& out) const {
  int n = 0, m = 0;
  if (!address(name, idx, indexed, count_, n, m)) return false;
  if (m == 0) raise(AlarmNumber::ArrayIndex1, fmt::format("{}[0] can only be cleared", name));
  const CarrierData& d = data(m);
  if (n == 21 || n == 22) {
    out = {Type::Axis, 0, n == 21 ? d.axis1 : d.axis2, {}};
  } else if (n == 23) {
    out = {Type::Char, static_cast<double>(static_cast<unsigned char>(d.kind)), {}, {}};
  } else if (n >= 34 && n <= 36) {
    out = Value::string(n == 34 ? d.name : n == 35 ? d.user_axis1 : d.user_axis2);
  } else {
    out = n == 37 ? Value::integer(d.num[37]) : Value::real(d.num[static_cast<size_t>(n)]);
  }
  return true;
}

bool ToolCarriers::write(std::string_view name, std::span<const Value> idx, bool indexed,
                         const Value& v) {
  int n = 0, m = 0;
  if (!address(name, idx, indexed, count_, n, m)) return false;
  if (m == 0) {  // $TC_CARR1[0]=0: every data block back to zero (W1 2.5.2)
    if (n != 1 || !v.isNumeric() || v.num != 0)
      raise(AlarmNumber::ArrayIndex1,
            fmt::format("{}[0]: only $TC_CARR1[0]=0 (clear all) is allowed", name));
    blocks_.clear();
    return true;
  }
  CarrierData& d = blocks_[m];
  if (n == 21 || n == 22) {
    (n == 21 ? d.axis1 : d.axis2) = upperText(v, name);
  } else if (n == 23) {
    d.kind = kindOf(v);
  } else if (n >= 34 && n <= 36) {
    if (v.type != Type::String)
      raise(AlarmNumber::TypeMismatch,
            fmt::format("operation not compatible with data type: {} takes a STRING", name));
    if (v.str.size() > 32)
      raise(AlarmNumber::ValueRange, fmt::format("value range exceeded: {} (32 characters)", name));
    (n == 34 ? d.name : n == 35 ? d.user_axis1 : d.user_axis2) = v.str;
  } else {
    const double x = lang::toNumber(v, "toolholder data");
    if (!(std::fabs(x) <= 1e9))
      raise(AlarmNumber::ValueRange, fmt::format("value range exceeded: {}[{}] = {}", name, m, x));
    d.num[static_cast<size_t>(n)] = n == 37 ? std::trunc(x) : x;
  }
  return true;
}

}  // namespace ncoffset::tool
