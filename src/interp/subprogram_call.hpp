// Subprograms with parameters (PM-JP "Subprogram technique"): the formal parameters of a PROC
// header, the actual arguments of a call, what a call level must undo at its return (SAVE,
// call-by-reference write-backs) and the modal call MCALL. The interpreter's part is
// interp/subprogram_call.cpp; docs/language.md "Subprograms with parameters" says what is
// modelled and why.
#pragma once

#include <string>
#include <vector>

#include "interp/modal_state.hpp"
#include "interp/variables.hpp"
#include "lang/block.hpp"
#include "lang/value.hpp"
#include "ncoffset/frame.hpp"

namespace ncoffset::interp {

// One formal parameter of `PROC NAME(...)` or one type of `EXTERN NAME(...)`.
struct FormalParameter {
  std::string name;  // empty in an EXTERN declaration
  lang::VarType type = lang::VarType::Real;
  int string_length = 0;
  int dims[2] = {0, 0};  // 0: scalar; dims[0] = -1: open first dimension
  bool by_ref = false;   // VAR
};

// The interface of a subprogram as its first block (PROC) declares it.
struct ProcSignature {
  bool has_proc = false;  // the first block is a PROC statement
  std::vector<FormalParameter> params;
  int attributes = 0;  // lang::ProcAttribute bits
};

// One actual argument, taken in the caller's scope when the call is executed.
struct CallArg {
  enum class Kind { Omitted, Value, Variable, Element, RParam };
  Kind kind = Kind::Omitted;
  lang::Value value;            // Value: the evaluated expression
  UserVariable* var = nullptr;  // Variable, Element: the caller's variable
  size_t offset = 0;            // Element: the flat index
  double r = 0;                 // RParam: the R number
  bool modal = false;           // an argument of MCALL (evaluated when MCALL was programmed)
};

// A parameter bound by reference to an array element or an R parameter: written back to the
// caller at the return (a whole variable is shared, see VariableStore::find).
struct WriteBack {
  std::string param;
  UserVariable* var = nullptr;  // nullptr: R parameter `r`
  size_t offset = 0;
  double r = 0;
};

// What one subprogram level keeps from its call until its return.
struct CallFrame {
  const ProcSignature* signature = nullptr;
  std::vector<CallArg> args;
  std::vector<WriteBack> write_backs;
  bool modal = false;  // called by MCALL
  // CALL .. BLOCK .. TO ..: the start of the section's last line (the level returns after it)
  // and whether the level has variables of its own (not for a section of the calling program).
  size_t section_end = static_cast<size_t>(-1);
  bool own_scope = true;
  bool save = false;  // PROC ... SAVE: the state below is restored at the return
  ModalState saved_modal;
  Frame saved_settable;      // $P_IFRAME at the call
  Frame saved_programmable;  // $P_PFRAME at the call
};

// The active modal call (MCALL NAME(args) until MCALL alone or the program end).
struct ModalCall {
  bool active = false;
  std::string name;
  std::vector<CallArg> args;
};

}  // namespace ncoffset::interp
