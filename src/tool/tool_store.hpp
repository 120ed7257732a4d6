// The tool offset memory of the channel's TO unit (W1 1, spec §1): tools T with cutting edges
// D and their parameters, as written by `$TC_...` assignments (TO_INI files or programs).
#pragma once

#include <map>
#include <string>

#include "ncoffset/tool.hpp"

namespace ncoffset::tool {

// Highest T number and D number (classic D structure, MD18102 = 0: D1..D9).
inline constexpr int kMaxTool = 32000;
inline constexpr int kMaxEdge = 9;

struct Tool {
  std::map<int, EdgeData> edges;
  std::map<int, std::string> name;                    // $TC_TP2 tool identifier (index 2)
  std::map<int, double> tp;                           // $TC_TPn numeric tool data
  std::map<int, double> tpc;                          // $TC_TPCn user tool data
  std::map<std::pair<int, int>, double> edge_user;    // $TC_DPCn[t,d]: (d, n) -> value
  std::map<std::pair<int, int>, double> edge_normal;  // $TC_DPVN3..5[t,d]: (d, n) -> value
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
