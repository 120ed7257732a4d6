#include "interp/variable_store.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "lang/evaluator.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

using lang::Value;

VariableStore::VariableStore(const Limits& limits, size_t r_count)
    : limits_(limits), r_(r_count, 0.0), r_written_(r_count, false) {}

void VariableStore::resizeR(size_t n) {
  r_.resize(n, 0.0);
  r_written_.resize(n, false);
}

double VariableStore::r(double number) const {
  if (number < 0 || number >= static_cast<double>(r_.size()) || number != std::floor(number))
    raise(
        AlarmNumber::ArrayIndex1,
        r_.empty()
            ? fmt::format("illegal array index: R{} (no R parameters: MD28050 = 0)", number)
            : fmt::format("illegal array index: R{} (R0..R{} per MD28050)", number, r_.size() - 1));
  return r_[static_cast<size_t>(number)];
}

void VariableStore::setR(double number, double value) {
  r(number);  // range check
  r_[static_cast<size_t>(number)] = value;
  r_written_[static_cast<size_t>(number)] = true;
}

void VariableStore::beginRun() {
  scopes_.clear();
  scopes_.emplace_back();
}

void VariableStore::pushScope() {
  scopes_.emplace_back();
}

void VariableStore::release(const VariableMap& scope) {
  variable_count_ -= std::min(variable_count_, scope.size());
  for (const auto& [name, var] : scope) element_count_ -= std::min(element_count_, var.data.size());
}

void VariableStore::popScope() {
  release(scopes_.back());
  scopes_.pop_back();
}

void VariableStore::clearScope() {
  release(scopes_.back());
  scopes_.back().clear();
}

void VariableStore::endRun(bool keep) {
  if (keep && !scopes_.empty()) main_vars_ = std::move(scopes_.front());
  scopes_.clear();
}

UserVariable* VariableStore::findIn(std::string_view name) {
  auto& loc = current();
  if (auto it = loc.find(name); it != loc.end())
    return it->second.ref ? it->second.ref : &it->second;
  if (auto it = globals_.find(name); it != globals_.end()) return &it->second;
  return nullptr;
}

const VariableMap& VariableStore::mainVariables() const {
  return scopes_.empty() ? main_vars_ : scopes_.front();
}

UserVariable VariableStore::prepare(const lang::Decl& d) const {
  const VariableMap& scope = current();
  std::string_view name = d.name;
  if (scope.find(name) != scope.end() || globals_.find(name) != globals_.end())
    raise(AlarmNumber::AlreadyDefined, fmt::format("name {} defined several times", name));
  if (name[0] == '$' ||
      (name.size() >= 2 && name[0] == 'R' &&
       std::all_of(name.begin() + 1, name.end(), [](char c) { return c >= '0' && c <= '9'; })))
    raise(AlarmNumber::SyntaxError, fmt::format("{} is a reserved name", name));
  if (variable_count_ >= limits_.max_variables)
    raise(AlarmNumber::TooManyVariables,
          fmt::format("more than {} user variables (--max-variables)", limits_.max_variables));
  UserVariable v;
  v.type = d.type;
  v.dims[0] = d.dims[0];
  v.dims[1] = d.dims[1];
  v.string_length = d.string_length;
  v.attributes = d.attributes;
  size_t count = 1;
  if (d.dims[0] > 0) {
    count = static_cast<size_t>(d.dims[0]) * static_cast<size_t>(d.dims[1] > 0 ? d.dims[1] : 1);
    // Each limit named by itself: which one the array breaks.
    if (count > limits_.max_array_elements)
      raise(AlarmNumber::ArrayTooLarge,
            fmt::format("array {} has {} elements: more than {} in one array "
                        "(--max-array-elements)",
                        name, count, limits_.max_array_elements));
    if (element_count_ + count > limits_.max_total_elements)
      raise(AlarmNumber::ArrayTooLarge,
            fmt::format("array {} has {} elements: with the {} of the live arrays more than {} in "
                        "all (--max-total-elements)",
                        name, count, element_count_, limits_.max_total_elements));
  }
  v.data.assign(count, initialValue(d.type));
  return v;
}

void VariableStore::add(std::string_view name, UserVariable v) {
  element_count_ += v.data.size();
  ++variable_count_;
  current().emplace(std::string(name), std::move(v));
}

void VariableStore::addGlobal(std::string_view name, UserVariable v) {
  element_count_ += v.data.size();
  ++variable_count_;
  globals_.emplace(std::string(name), std::move(v));
}

void VariableStore::checkLimits(const UserVariable& var, const Value& v, std::string_view name) {
  const lang::DefAttributes& a = var.attributes;
  if (!v.isNumeric() || (!a.has_lower && !a.has_upper)) return;
  if ((a.has_lower && v.num < a.lower && !lang::realEqual(v.num, a.lower)) ||
      (a.has_upper && v.num > a.upper && !lang::realEqual(v.num, a.upper)))
    raise(AlarmNumber::ValueRange,
          fmt::format("value range exceeded: {} = {} outside its limits{}{}", name, v.num,
                      a.has_lower ? fmt::format(" LLI {}", a.lower) : std::string(),
                      a.has_upper ? fmt::format(" ULI {}", a.upper) : std::string()));
}

size_t VariableStore::elementIndex(const UserVariable& var, std::span<const Value> idx,
                                   std::string_view name) {
  int dims = var.dims[1] > 0 ? 2 : 1;
  if (static_cast<int>(idx.size()) != dims)
    raise(AlarmNumber::ArrayIndex1,
          fmt::format("illegal array index: {} has {} dimension(s), {} index(es) given", name, dims,
                      idx.size()));
  size_t flat = 0;
  for (int k = 0; k < dims; ++k) {
    double x = lang::toNumber(idx[static_cast<size_t>(k)], "array index");
    if (x != std::floor(x) || x < 0 || x >= var.dims[k])
      raise(k == 0 ? AlarmNumber::ArrayIndex1 : AlarmNumber::ArrayIndex2,
            fmt::format("illegal array index {}: {}[{}] with {} outside 0..{}", k + 1, name,
                        k == 0 ? "i" : "..,j", x, var.dims[k] - 1));
    flat = flat * static_cast<size_t>(k == 0 ? 1 : var.dims[1]) + static_cast<size_t>(x);
  }
  return flat;
}

}  // namespace ncoffset::interp
