// Expression evaluation (PM-NC "Arithmetic operators and functions", priority p444). Variables,
// system variables and non-arithmetic functions come from an Environment.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "lang/block.hpp"
#include "lang/parser.hpp"
#include "lang/value.hpp"

namespace ncoffset::lang {

class Environment {
 public:
  virtual ~Environment() = default;
  // Reads a variable: `name` alone or `name[indices]`. Returns false if no such name exists.
  virtual bool read(std::string_view name, std::span<const Value> indices, bool indexed,
                    Value& out) = 0;
  virtual Value readR(double number) = 0;
  // Functions that are not pure arithmetic (CTRANS, LENTOAX, ...). Throws 12550 if unknown.
  virtual Value call(std::string_view name, std::span<const Value> args) = 0;
  // Frame chain `a:b`.
  virtual Value chain(const Value& a, const Value& b) = 0;
};

class Evaluator {
 public:
  explicit Evaluator(Environment& env) : env_(env) {}
  // Evaluates node `n` of block `b`. Names that are not variables are an alarm.
  Value eval(const Block& b, int n);
  // As eval, but a bare name that is not a variable becomes a Symbol (axis names, keywords).
  Value evalOrSymbol(const Block& b, int n);
  // Evaluates the arguments of an Index/Call node (names may be symbols).
  void evalArgs(const Block& b, const Node& node, std::vector<Value>& out);
  double number(const Block& b, int n);

 private:
  Environment& env_;
  int depth_ = 0;  // recursion of eval, bounded by kMaxExpressionDepth (lang/parser.hpp)
  // Counts one level of recursion: alarm 99003 beyond kMaxExpressionDepth (the parser bounds the
  // nesting of what it builds by ParseLimits, so only a block built otherwise gets there).
  class DepthGuard {
   public:
    explicit DepthGuard(int& depth) : depth_(depth) {
      if (++depth_ > kMaxExpressionDepth) {
        --depth_;
        tooDeep();
      }
    }
    ~DepthGuard() { --depth_; }
    DepthGuard(const DepthGuard&) = delete;
    DepthGuard& operator=(const DepthGuard&) = delete;

   private:
    int& depth_;
    [[noreturn]] static void tooDeep();
  };
  Value binaryChain(const Block& b, int n);
  Value binary(Op op, const Value& l, const Value& r);
  Value function(std::string_view name, std::span<const Value> args);
};

// Conversions with the control's rules; throw 12150 on a type mismatch.
double toNumber(const Value& v, const char* what = "operand");
bool toBool(const Value& v);
std::string toText(const Value& v);
// The INT value of a REAL (rounded, PM-F: REAL to INT conversion rounds).
double roundToInt(double v);
// REAL comparison with the control's relative tolerance 1e-12 (PM-JP 1-23).
bool realEqual(double a, double b);

}  // namespace ncoffset::lang
