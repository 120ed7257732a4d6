// String functions (PM-JP "Flexible NC programming", "String operations"). Positions count from
// 0 (the first character); a search that finds nothing gives -1.
#include "lang/string_functions.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <string>

#include "lang/evaluator.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::lang {
namespace {

void want(std::string_view name, std::span<const Value> args, size_t low, size_t high) {
  if (args.size() < low || args.size() > high)
    raise(AlarmNumber::WrongCallParams,
          fmt::format("wrong number of parameters in call of {}: {} given", name, args.size()));
}

// A STRING parameter: a STRING, a CHAR or an AXIS value (never a number, PM-JP: the parameter
// types are fixed).
std::string text(std::string_view name, const Value& v) {
  if (v.type == Type::String || v.type == Type::Axis) return v.str;
  if (v.type == Type::Char) return std::string(1, static_cast<char>(v.num));
  raise(AlarmNumber::TypeMismatch,
        fmt::format("operation not compatible with data type: {} needs a STRING, not {}", name,
                    typeName(v.type)));
}

// A CHAR parameter: a CHAR value or a STRING of one character.
char character(std::string_view name, const Value& v) {
  if (v.type == Type::Char) return static_cast<char>(v.num);
  if (v.type == Type::String && v.str.size() == 1) return v.str[0];
  raise(AlarmNumber::TypeMismatch,
        fmt::format("operation not compatible with data type: {} needs one character", name));
}

// An INT parameter (a position or a count): whole and not negative.
size_t count(std::string_view name, const Value& v) {
  const double x = toNumber(v, "position");
  if (!(x >= 0 && x <= 1e9) || x != std::floor(x))
    raise(AlarmNumber::ValueRange,
          fmt::format("value range exceeded: {} in {} (whole, 0 or more)", x, name));
  return static_cast<size_t>(x);
}

Value position(size_t at) {
  return Value::integer(at == std::string::npos ? -1.0 : static_cast<double>(at));
}

bool search(std::string_view name, std::span<const Value> args, Value& out) {
  if (name == "INDEX" || name == "RINDEX") {
    want(name, args, 2, 2);
    const std::string s = text(name, args[0]);
    const char c = character(name, args[1]);
    out = position(name == "INDEX" ? s.find(c) : s.rfind(c));
  } else if (name == "MINDEX") {
    want(name, args, 2, 2);
    out = position(text(name, args[0]).find_first_of(text(name, args[1])));
  } else if (name == "MATCH") {
    want(name, args, 2, 2);
    out = position(text(name, args[0]).find(text(name, args[1])));
  } else if (name == "SUBSTR") {
    // SUBSTR(text, start[, count]): `count` characters from `start`, or the rest.
    want(name, args, 2, 3);
    const std::string s = text(name, args[0]);
    const size_t from = count(name, args[1]);
    const size_t n = args.size() == 3 ? count(name, args[2]) : std::string::npos;
    out = Value::string(from >= s.size() ? std::string() : s.substr(from, n));
  } else {
    return false;
  }
  return true;
}

}  // namespace

bool parseNumberText(std::string_view t, double& out) {
  auto blank = [](char c) { return c == ' ' || c == '\t'; };
  while (!t.empty() && blank(t.front())) t.remove_prefix(1);
  while (!t.empty() && blank(t.back())) t.remove_suffix(1);
  bool negative = false;
  if (!t.empty() && (t[0] == '+' || t[0] == '-')) {
    negative = t[0] == '-';
    t.remove_prefix(1);
  }
  size_t i = 0, digits = 0;
  std::string plain;  // digits and point, for from_chars
  for (; i < t.size() && (std::isdigit(static_cast<unsigned char>(t[i])) || t[i] == '.'); ++i) {
    if (t[i] != '.') ++digits;
    if (t[i] == '.' && plain.find('.') != std::string::npos) return false;
    plain += t[i];
  }
  if (digits == 0) return false;
  long exponent = 0;
  if (i < t.size()) {
    // 1.5EX3 (PM-NC "Constants": EX is the exponent of ten).
    if (t.substr(i, 2) != "EX" && t.substr(i, 2) != "ex") return false;
    i += 2;
    bool neg_exp = false;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) neg_exp = t[i++] == '-';
    const auto r = std::from_chars(t.data() + i, t.data() + t.size(), exponent);
    if (r.ec != std::errc() || r.ptr != t.data() + t.size() || exponent > 400) return false;
    if (neg_exp) exponent = -exponent;
  }
  double v = 0;
  const auto r = std::from_chars(plain.data(), plain.data() + plain.size(), v);
  if (r.ec != std::errc()) return false;
  v *= std::pow(10.0, static_cast<double>(exponent));
  if (!std::isfinite(v)) return false;
  out = negative ? -v : v;
  return true;
}

bool stringFunction(std::string_view name, std::span<const Value> args, Value& out) {
  if (search(name, args, out)) return true;
  if (name == "TOUPPER" || name == "TOLOWER") {
    want(name, args, 1, 1);
    std::string s = text(name, args[0]);
    for (char& c : s)
      c = static_cast<char>(name == "TOUPPER" ? std::toupper(static_cast<unsigned char>(c))
                                              : std::tolower(static_cast<unsigned char>(c)));
    out = Value::string(std::move(s));
  } else if (name == "NUMBER" || name == "ISNUMBER") {
    want(name, args, 1, 1);
    const std::string s = text(name, args[0]);
    double v = 0;
    const bool ok = parseNumberText(s, v);
    if (name == "ISNUMBER") {
      out = Value::boolean(ok);
    } else if (!ok) {
      raise(AlarmNumber::TypeMismatch,
            fmt::format("operation not compatible with data type: NUMBER(\"{}\"): no number", s));
    } else {
      out = Value::real(v);
    }
  } else if (name == "AXSTRING") {
    want(name, args, 1, 1);
    if (args[0].type != Type::Axis)
      raise(AlarmNumber::TypeMismatch,
            "operation not compatible with data type: AXSTRING needs an AXIS (X, Y, Z)");
    out = Value::string(args[0].str);
  } else if (name == "AXNAME") {
    want(name, args, 1, 1);
    // Any axis name (docs/language.md "Axes"): whether the channel has it is checked where the
    // AXIS value is used ($AA_IW[..], AX[..]=), which knows the channel's axes.
    std::string s = text(name, args[0]);
    for (auto& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    bool ok = !s.empty() && s.size() <= 8 && std::isalpha(static_cast<unsigned char>(s[0]));
    for (char c : s) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    if (!ok)
      raise(AlarmNumber::NameNotDefined,
            fmt::format("AXNAME(\"{}\"): \"{}\" is no axis name", s, s));
    out = {Type::Axis, 0, s, {}};
  } else {
    return false;
  }
  return true;
}

}  // namespace ncoffset::lang
