// The channel's axes beyond the three geometry axes (PM-NC "Axis types", FM K2 "Axes"): their
// names (MD20060 $MC_AXCONF_GEOAX_NAME_TAB renames the geometry axes, MD20080
// $MC_AXCONF_CHANAX_NAME_TAB names the channel axes, MD10000 $MN_AXCONF_MACHAX_NAME_TAB the
// machine axes), whether each is rotary and modulo 360 (MD30300 $MA_IS_ROT_AX, MD30310
// $MA_ROT_IS_MODULO), their programmed and machine positions, and their part of the frames
// (translations and mirroring; rotations and scaling act on geometry axes only).
// docs/language.md "Axes" has the decisions.
#pragma once

#include <array>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "lang/block.hpp"

namespace ncoffset::interp {

struct ExtraAxis {
  std::string name;     // channel axis name (A, B, C, U, V, W, or as MD20080 sets it)
  std::string machine;  // machine axis name (MD10000; default A1, B1, ...)
  bool rotary = false;  // MD30300
  bool modulo = false;  // MD30310 (rotary axes only)
  double machine_pos = 0;
  bool output = false;  // has an output column in this run
};

// The frame parts of the additional axes of one frame: translation (coarse and fine) and
// mirroring, per axis.
struct AxisFrame {
  std::vector<double> coarse, fine;
  std::vector<bool> mirror;
  void resize(size_t n) {
    coarse.resize(n, 0);
    fine.resize(n, 0);
    mirror.resize(n, false);
  }
  bool empty() const;
};

// One axis word of a block: `A=DC(90)`.
struct AxisWord {
  int axis = 0;
  double value = 0;
  lang::AxisMode mode = lang::AxisMode::Default;
};

class ChannelAxes {
 public:
  static constexpr size_t kMaxAxes = 17;  // 20 channel axes minus the 3 geometry axes

  ChannelAxes();
  const std::vector<ExtraAxis>& axes() const { return axes_; }
  // The additional axis of that channel axis name, or with `machine_names` also of that machine
  // axis name ($MA_ data, $AA_IM) (-1: none).
  int find(std::string_view name, bool machine_names) const;
  void setOutput(int axis, bool output) { axes_[static_cast<size_t>(axis)].output = output; }
  // Geometry axis by name (renamed ones too), 99010 for an additional axis, 12550 else.
  int geometryAxisOf(std::string_view name, std::string_view what) const;
  // The geometry axis of that name (0..2; -1: none).
  int geometry(std::string_view name) const;
  const std::array<std::string, 3>& geometryNames() const { return geo_; }
  // Whether the geometry axes carry other names than X, Y, Z.
  bool geometryRenamed() const { return geo_renamed_; }
  // Whether the channel axes were configured by MD20080 (all of them get columns).
  bool configured() const { return configured_; }

  // MD20060 / MD20080 / MD10000 entry `index` (0-based). Throws 12160 / 17020.
  void setName(std::string_view table, int index, const std::string& name);
  std::string name(std::string_view table, int index) const;
  void setRotary(int axis, bool rotary);
  void setModulo(int axis, bool modulo);

  // --- the words of the block being executed ---
  void collect(const AxisWord& w);
  bool pending() const { return !words_.empty(); }
  const std::vector<AxisWord>& words() const { return words_; }
  void clearWords() { words_.clear(); }

  // Moves the axes of the collected words (G90/G91 `incremental`, G70 `inch`), under the
  // settable frame `settable` (0: G500) and the programmable frame; `suppressed`: G53/G153/SUPA.
  void move(bool incremental, bool inch, size_t settable, bool suppressed);
  // The position of axis `k` in the WCS (the programmed value) / the MCS.
  double wcs(int k, size_t settable) const;
  double mcs(int k) const { return axes_[static_cast<size_t>(k)].machine_pos; }

  // --- frames ---
  AxisFrame& settableFrame(size_t n);
  AxisFrame& programmable() { return programmable_; }
  // TRANS / ATRANS / MIRROR / AMIRROR / ROT / SCALE / AROT / ASCALE with the block's words.
  void frameCommand(std::string_view cmd, bool inch);
  // G58 (coarse) / G59 (fine) for the words of the block.
  void axialOffset(int g, bool inch);

 private:
  double offset(int k, size_t settable) const;
  bool mirrored(int k, size_t settable) const;
  void grow();
  std::array<std::string, 3> geo_{"X", "Y", "Z"};
  bool geo_renamed_ = false;
  bool configured_ = false;
  std::vector<ExtraAxis> axes_;
  std::vector<AxisWord> words_;
  std::map<size_t, AxisFrame> settable_;
  AxisFrame programmable_;
};

// Modulo 360: the value in [0, 360).
double modulo360(double v);

}  // namespace ncoffset::interp
