// User variables (DEF, PM-F "Variables") and R parameters.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "lang/block.hpp"
#include "lang/program_index.hpp"
#include "lang/value.hpp"

namespace ncoffset::interp {

struct UserVariable {
  lang::VarType type = lang::VarType::Real;
  int dims[2] = {0, 0};  // 0: scalar
  int string_length = 0;
  std::vector<lang::Value> data;   // one element for scalars, row-major for arrays
  lang::DefAttributes attributes;  // LLI/ULI limits of the DEF
  // A call-by-reference parameter bound to a whole variable of the caller (PROC .. VAR):
  // VariableStore::find gives the caller's variable itself.
  UserVariable* ref = nullptr;
  bool isArray() const { return dims[0] > 0; }
};

using VariableMap =
    std::unordered_map<std::string, UserVariable, lang::StringHash, std::equal_to<>>;

// The initial value of a variable of type `t` (0, FALSE, "", X, empty frame).
lang::Value initialValue(lang::VarType t);
// Converts `v` for storage in a variable of type `t` (REAL -> INT rounds). Throws 12150.
lang::Value convertForStore(const lang::Value& v, lang::VarType t, int string_length,
                            std::string_view name);
const char* varTypeName(lang::VarType t);

}  // namespace ncoffset::interp
