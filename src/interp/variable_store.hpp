// The variable store of the channel (PM-JP "Variables"): R parameters (MD28050), the user
// variables of each program level (DEF), and the limits on how many there may be
// (docs/limits.md). Program levels open and close scopes; what a variable holds and how values
// are converted is in variables.hpp.
#pragma once

#include <deque>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "interp/variables.hpp"
#include "lang/block.hpp"
#include "ncoffset/channel.hpp"

namespace ncoffset::interp {

class VariableStore {
 public:
  VariableStore(const Limits& limits, size_t r_count);

  // --- R parameters R0..R(n-1) ---
  size_t rCount() const { return r_.size(); }
  // MD28050 changed by an init file: the store grows or shrinks, values kept.
  void resizeR(size_t n);
  // R<number>, range-checked (alarm 17020 outside R0..R(n-1) or for a fraction).
  double r(double number) const;
  void setR(double number, double value);
  bool rWritten(size_t i) const { return r_written_[i]; }
  double rValue(size_t i) const { return r_[i]; }

  // --- scopes: one per program level ---
  // A new run: the main program's level (the variables of an earlier main program go).
  void beginRun();
  // A subprogram level begins / ends (its variables are released).
  void pushScope();
  void popScope();
  // The same level runs again (a pass count P): it starts without variables.
  void clearScope();
  // The run ended: the main program's variables stay readable (--vars), `keep` = false for an
  // init file, whose variables go with it.
  void endRun(bool keep);

  // The variable `name` of the current level (or a global one), nullptr if there is none.
  UserVariable* find(std::string_view name) {
    if (current().empty() && globals_.empty()) return nullptr;  // the common case: no call
    return findIn(name);
  }
  const UserVariable* find(std::string_view name) const {
    return const_cast<VariableStore*>(this)->find(name);
  }
  // DEF, in two steps so that the initial values are evaluated before the variable exists:
  // the checks (alarms 12170 defined twice, 99004/99005 beyond the limits) and the variable
  // with its type's initial value, then adding it to the current level.
  UserVariable prepare(const lang::Decl& d) const;
  void add(std::string_view name, UserVariable v);
  // A global user variable (DEF NCK/CHAN in an init or GUD definition file): seen by every
  // program level of every later run (docs/language.md "Global user data").
  void addGlobal(std::string_view name, UserVariable v);
  // Alarm 12160 when `v` lies outside the LLI/ULI limits of `var`.
  static void checkLimits(const UserVariable& var, const lang::Value& v, std::string_view name);
  // The flat element index of `var[idx]` (alarms 17020/17030).
  static size_t elementIndex(const UserVariable& var, std::span<const lang::Value> idx,
                             std::string_view name);
  // The main program's variables and the global ones, for --vars.
  const VariableMap& mainVariables() const;
  const VariableMap& globals() const { return globals_; }

 private:
  VariableMap& current() { return scopes_.empty() ? main_vars_ : scopes_.back(); }
  const VariableMap& current() const { return scopes_.empty() ? main_vars_ : scopes_.back(); }
  void release(const VariableMap& scope);
  UserVariable* findIn(std::string_view name);

  Limits limits_;
  std::vector<double> r_;
  std::vector<bool> r_written_;
  // One per active program level, main program first; a deque keeps the caller's variables in
  // place while a call level is added (a VAR parameter points at them).
  std::deque<VariableMap> scopes_;
  VariableMap globals_;
  VariableMap main_vars_;  // the main program's variables after it ended (for --vars)
  size_t variable_count_ = 0;
  size_t element_count_ = 0;  // array elements of all live variables
};

}  // namespace ncoffset::interp
