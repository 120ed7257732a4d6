// Values of the NC language (PM-F "Data types"): INT, REAL, BOOL, CHAR, STRING, AXIS, FRAME.
#pragma once

#include <memory>
#include <string>

namespace ncoffset {
struct Frame;
}

namespace ncoffset::lang {

enum class Type : unsigned char {
  Int,
  Real,
  Bool,
  Char,
  String,
  Axis,
  Frame,
  Symbol,
  ArrayRef,
  Empty
};
const char* typeName(Type t);

// A value. Numbers (INT, REAL, BOOL, CHAR) live in `num`; STRING and AXIS names and symbols
// (bare names such as `X` or `TR` inside `$P_UIFR[1,X,TR]`) in `str`; FRAME in `frame`.
struct Value {
  Type type = Type::Real;
  double num = 0;
  std::string str;
  std::shared_ptr<const Frame> frame;

  static Value real(double v) { return {Type::Real, v, {}, {}}; }
  static Value integer(double v) { return {Type::Int, v, {}, {}}; }
  static Value boolean(bool v) { return {Type::Bool, v ? 1.0 : 0.0, {}, {}}; }
  static Value string(std::string s) { return {Type::String, 0, std::move(s), {}}; }
  static Value symbol(std::string s) { return {Type::Symbol, 0, std::move(s), {}}; }
  static Value empty() { return {Type::Empty, 0, {}, {}}; }
  bool isNumeric() const {
    return type == Type::Int || type == Type::Real || type == Type::Bool || type == Type::Char;
  }
  bool isText() const { return type == Type::String || type == Type::Axis || type == Type::Symbol; }
};

}  // namespace ncoffset::lang
