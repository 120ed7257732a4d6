// The tool offset memory of the channel's TO unit (W1 1, spec §1): tools T with cutting edges
// D and their parameters, as written by `$TC_...` assignments (TO_INI files or programs).
#pragma once

#include <map>
#include <string>

#include "ncoffset/tool.hpp"

namespace ncoffset::tool {

// Highest T number, and the highest D number MD18105 may allow (W1 "Free assignment of D
// numbers": D up to 32000; the default MD18105 = 9 keeps D1..D9). An edge invalidated by DZERO
// keeps its number plus kInvalidD (GETDNO then returns a value above 32000, W1).
inline constexpr int kMaxTool = 32000;
inline constexpr int kMaxEdge = 32000;
inline constexpr int kInvalidD = 32000;

struct Tool {
  std::map<int, EdgeData> edges;
  std::map<int, std::string> name;  // $TC_TP2 tool identifier (index 2)
  std::map<int, double> tp;         // $TC_TPn numeric tool data
  std::map<int, double> tpc;        // $TC_TPCn user tool data
  std::map<int, double> tpg;        // $TC_TPG1..9 grinding data (W4, src/tool/grinding.cpp)
  std::map<std::pair<int, int>, double> edge_user;    // $TC_DPCn[t,d]: (d, n) -> value
  std::map<std::pair<int, int>, double> edge_normal;  // $TC_DPVN3..5[t,d]: (d, n) -> value
  std::map<int, int> ce;                              // $TC_DPCE[t,d]: d -> cutting edge no.
};

class ToolStore {
 public:
  Tool* tool(int t) {
    auto it = tools_.find(t);
    return it == tools_.end() ? nullptr : &it->second;
  }
  const Tool* tool(int t) const {
    auto it = tools_.find(t);
    return it == tools_.end() ? nullptr : &it->second;
  }
  const EdgeData* edge(int t, int d) const {
    auto it = tools_.find(t);
    if (it == tools_.end()) return nullptr;
    auto e = it->second.edges.find(d);
    return e == it->second.edges.end() ? nullptr : &e->second;
  }
  // Creates tool and edge on first write, as a TO_INI file does.
  EdgeData& edgeForWrite(int t, int d) { return tools_[t].edges[d]; }
  Tool& toolForWrite(int t) { return tools_[t]; }
  // Renames edge `from` of tool `t` to `to` with all its data (SETDNO, DZERO); `to` is free.
  void renameEdge(int t, int from, int to) {
    Tool& tool = tools_[t];
    auto node = tool.edges.extract(from);
    node.key() = to;
    tool.edges.insert(std::move(node));
    for (auto* m : {&tool.edge_user, &tool.edge_normal}) {
      std::map<std::pair<int, int>, double> moved;
      for (auto it = m->lower_bound({from, 0}); it != m->end() && it->first.first == from;)
        moved[{to, it->first.second}] = it->second, it = m->erase(it);
      m->merge(moved);
    }
    if (auto c = tool.ce.extract(from)) {
      c.key() = to;
      tool.ce.insert(std::move(c));
    }
  }
  const std::map<int, Tool>& all() const { return tools_; }
  // The tool whose $TC_TP2 identifier is `name` (0 if none).
  int findByName(const std::string& name) const {
    for (const auto& [t, tool] : tools_) {
      auto it = tool.name.find(2);
      if (it != tool.name.end() && it->second == name) return t;
    }
    return 0;
  }
  size_t size() const { return tools_.size(); }

 private:
  std::map<int, Tool> tools_;
};

}  // namespace ncoffset::tool
