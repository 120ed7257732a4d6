// Machine data ($MN_/$MC_/$MA_) and setting data ($SN_/$SC_) held per channel, with the
// control's defaults (spec §10). Only the data ncoffset evaluates are known; writing any other
// name is alarm 12550, and writing a value whose behaviour ncoffset does not model is alarm
// 99013 (never accepted and ignored).
#pragma once

#include <array>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ncoffset::interp {

enum class DataClass : unsigned char { NckMd, ChannelMd, AxisMd, NckSd, ChannelSd };

struct DataSpec {
  int number;
  const char* name;  // without prefix, e.g. "TOOL_LENGTH_CONST"
  DataClass cls;
  double default_value;
  bool integer;
  // Values whose behaviour ncoffset models: [lo, hi]; `only_default` restricts to the default.
  double lo, hi;
  bool only_default;
  const char* meaning;
};

class MachineData {
 public:
  MachineData();
  // Finds by `$SC_NAME`-style name or `SD42940`/`MD20270` number form. Returns -1 if unknown.
  int find(std::string_view name) const;
  double get(int id) const { return values_[static_cast<size_t>(id)]; }
  // Axis machine data ($MA_NAME[X]): one value per geometry axis (0 = X, 1 = Y, 2 = Z).
  bool isAxisData(int id) const { return spec(id).cls == DataClass::AxisMd; }
  double get(int id, int axis) const {
    return axis_values_[static_cast<size_t>(id)][static_cast<size_t>(axis)];
  }
  void set(int id, int axis, double value);
  double get(std::string_view name) const;
  // Throws 12550 / 12160 / 99013.
  void set(int id, double value);
  const DataSpec& spec(int id) const;
  static std::span<const DataSpec> table();

 private:
  // The value as stored (rounded for integer data); throws 12160 / 99013 when not allowed.
  double checked(int id, double value) const;
  std::vector<double> values_;
  std::vector<std::array<double, 3>> axis_values_;
};

}  // namespace ncoffset::interp
