// Value lists assigned to array elements in the program (PM-JP "Definition and initialization
// of array variables"): ARRAY[i]=SET(a,b,...) writes the values from element i on (the last
// index runs fastest), a value left out keeps its element; ARRAY[i]=REP(x) writes x from
// element i to the end of the array. More values than elements left: alarm 17020.
#include <fmt/format.h>

#include "interp/interpreter.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::Node;
using lang::NodeKind;
using lang::Value;

bool Interpreter::arrayListAssign(const lang::Stmt& st) {
  const Node& rhs = block_.node(st.expr);
  const Node& target = block_.node(st.target);
  UserVariable* var = target.kind == NodeKind::Index || target.kind == NodeKind::Name
                          ? vars_.find(target.text)
                          : nullptr;
  if (!var || !var->isArray())
    raise(AlarmNumber::TypeMismatch,
          fmt::format("operation not compatible with data type: {}(..) assigns to an array "
                      "element (ARRAY[i]={}(..))",
                      rhs.text, rhs.text));
  size_t at = 0;
  if (target.kind == NodeKind::Index) {
    std::vector<Value> idx;
    eval_.evalArgs(block_, target, idx);
    at = VariableStore::elementIndex(*var, idx, target.text);
  }
  const size_t count = var->data.size();
  auto value = [&](int k) {
    return convertForStore(eval_.eval(block_, block_.arg(rhs, k)), var->type, var->string_length,
                           target.text);
  };
  if (rhs.text == "REP") {
    if (rhs.b != 1) raise(AlarmNumber::WrongCallParams, "REP takes one value");
    const Value x = value(0);
    for (size_t k = at; k < count; ++k) var->data[k] = x;
    return true;
  }
  if (at + static_cast<size_t>(rhs.b) > count)
    raise(AlarmNumber::ArrayIndex1,
          fmt::format("illegal array index: {} values from element {} of {} ({} elements)", rhs.b,
                      at, target.text, count));
  for (int k = 0; k < rhs.b; ++k) {
    const Node& n = block_.node(block_.arg(rhs, k));
    if (n.kind == NodeKind::Name && n.text.empty()) continue;  // SET(1,,3): left out
    var->data[at + static_cast<size_t>(k)] = value(k);
  }
  return true;
}

}  // namespace ncoffset::interp
