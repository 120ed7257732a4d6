// Modal state of the channel (the G groups that matter for the path) and the words collected
// from one block before it is executed.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

#include "core/compensation.hpp"
#include "lang/block.hpp"
#include "ncoffset/geometry.hpp"
#include "ncoffset/path.hpp"
#include "ncoffset/trc.hpp"

namespace ncoffset::interp {

enum class Units { G71, G70, G710, G700 };
enum class FeedType { G93, G94, G95, G96, G97, G961, G971 };

// G group 29, diameter/radius programming of the channel (PM-NC "Channel-specific diameter
// programming", docs/turning.md).
enum class DiamMode : unsigned char { Off, On, On90, CycOff };
// The same per axis (DIAMONA[ax] ..., "Axis-specific diameter programming"): Chan follows the
// channel's group 29 (DIAMCHANA[ax], DIAMCHAN; the transverse axis of MD20100 after reset).
enum class DiamAxis : unsigned char { Chan, Off, On, On90, CycOff };

struct ModalState {
  Motion motion = Motion::G0;       // group 1 (initial G0 per common machine data)
  Plane plane = Plane::G17;         // group 6
  bool incremental = false;         // group 14: G90 / G91
  bool cut2d_frame = false;         // group 22: CUT2DF, CUT2DFD (docs/radius-compensation.md)
  bool cut_constant = false;        // group 40: CUTCONON (next to cut2d_frame: copied together)
  bool cut2d_differential = false;  // group 22: CUT2DD, CUT2DFD (R = the differences only)
  Units units = Units::G71;         // group 13
  core::TrcMode trc = core::TrcMode::Off;  // group 7: G40, G41, G42
  CornerMode corner = CornerMode::TransitionCircle;
  Approach approach = Approach::Norm;
  CollisionCheck collision = CollisionCheck::Cdof;
  core::SarSide sar_side = core::SarSide::G140;              // group 43
  core::SarInfeed sar_infeed = core::SarInfeed::G340;        // group 44
  core::TrcStrategy trc_strategy = core::TrcStrategy::G460;  // group 48
  int frame_select = 500;                                    // group 8: 500, 54..57, 505..599
  FeedType feed_type = FeedType::G94;
  FeedUnit feed_unit = FeedUnit::MmPerMin;  // of feed_type, kept with it (copied per block)
  DiamMode diam = DiamMode::Off;            // group 29
  DiamAxis diam_axis[3] = {DiamAxis::Off, DiamAxis::Off, DiamAxis::Off};
  // From diam, diam_axis and MD20100 (Interpreter::updateDiameter): the factor a programmed
  // position of axis i is multiplied by, absolute (G90, AC) and incremental (G91, IC); 0.5
  // where it is a diameter.
  double diam_abs[3] = {1, 1, 1};
  double diam_inc[3] = {1, 1, 1};
  bool diam_permitted[3] = {false, false, false};  // the MD20100 axis or MD30460 bit 2
  int exact_stop = 64;                             // group 10: G60/G64/G641..
  double feed = 0;                                 // F in mm/min (G94) as the control holds it
  Vec3 thread_lead;  // the last lead I, J, K of a G33..G332 block, mm/rev (docs/threads.md)
  double disc = 0;   // DISC=
  double offn = 0;   // OFFN=
  int tool = 0;      // T
  int edge = 0;      // D
};

// Words of one block, collected before execution (their order inside a block does not matter
// for the G codes, PM-NC "Block structure").
struct BlockWords {
  bool axis[3] = {false, false, false};
  // A circle word (I, J, K, CR=) that Interpreter::plainWord collected: finishPlainBlock's one
  // test for them (only its blocks, whose words plainWord collected alone, read it).
  bool plain_circle = false;
  double axis_value[3] = {0, 0, 0};
  lang::AxisMode axis_mode[3] = {lang::AxisMode::Default, lang::AxisMode::Default,
                                 lang::AxisMode::Default};
  bool centre[3] = {false, false, false};
  double centre_value[3] = {0, 0, 0};
  lang::AxisMode centre_mode[3] = {lang::AxisMode::Default, lang::AxisMode::Default,
                                   lang::AxisMode::Default};
  std::optional<double> cr, ar, rpl;
  std::optional<int> turn;
  bool motion_word = false;        // G0..G3 in this block
  bool dwell = false;              // G4
  bool tapping_chuck = false;      // G63 (group 2, this block only)
  int suppress_frames = 0;         // 53, 153 or 1 (SUPA)
  bool frame_select = false;       // G500/G54.. in this block
  int axial_offset = 0;            // 58 / 59
  std::string_view frame_command;  // TRANS, ATRANS, ROT, ... (views the block's text)
  std::optional<double> f;
  bool end_program = false;         // M2 / M30
  bool end_subprogram = false;      // M17 / RET
  std::optional<int> tool;          // T (number; a T="name" is resolved when collected)
  std::optional<int> edge;          // D
  std::optional<int> sum_offset;    // DL= (programmable_offsets.cpp)
  bool tool_change = false;         // M6 (MD22560) for the master spindle
  std::string_view call;            // subprogram to call at block end (block text or call_name_)
  std::optional<long long> repeat;  // P
  core::SarKind sar = core::SarKind::None;        // G147..G348 (smooth approach / retraction)
  std::optional<double> disr, discl, disrp, fad;  // SAR parameters (mm)
  bool discl_ac = false, disrp_ac = false;
  bool contour = false;     // a contour-definition word (CHF=, RND=, ANG=, AP=, CIP, G110, ...)
  bool extra_axes = false;  // words of additional axes (ChannelAxes holds them; in the padding)
  int column = 0;

  void clear();
  // clear() for words that Interpreter::plainWord alone set (X, Y, Z, G0..G3, F, CR=, I, J,
  // K): only those fields differ from an empty instance, so resetting them is the same as
  // clear() (plainWord's axis_mode and centre_mode are the empty instance's).
  void clearPlain() {
    // Field by field (the compiler joins these into seven stores); one memset of the 64 bytes
    // cost the usual line 0.8 instructions more (docs/performance.md §53).
    axis[0] = axis[1] = axis[2] = false;
    plain_circle = false;
    axis_value[0] = axis_value[1] = axis_value[2] = 0;
    centre[0] = centre[1] = centre[2] = false;
    centre_value[0] = centre_value[1] = centre_value[2] = 0;
    // Assigned, not reset(): reset() tests the flag first (two instructions more a line).
    cr = std::optional<double>();
    motion_word = false;
    f = std::optional<double>();
  }
  // clear() for every field but plainWord's, which keep their values: the plain line collected
  // them after a block of other words (interp/plain_line.cpp). plainWord's axis_mode and
  // centre_mode are the empty instance's.
  void clearExceptPlain() {
    const bool a[3] = {axis[0], axis[1], axis[2]}, c[3] = {centre[0], centre[1], centre[2]};
    const double v[3] = {axis_value[0], axis_value[1], axis_value[2]};
    const double cv[3] = {centre_value[0], centre_value[1], centre_value[2]};
    const std::optional<double> kept_cr = cr, kept_f = f;
    const bool kept_motion = motion_word, kept_circle = plain_circle;
    clear();
    plain_circle = kept_circle;
    for (int i = 0; i < 3; ++i) {
      axis[i] = a[i];
      axis_value[i] = v[i];
      centre[i] = c[i];
      centre_value[i] = cv[i];
    }
    cr = kept_cr;
    f = kept_f;
    motion_word = kept_motion;
  }
};
// All members are plain values: a copy of one empty instance clears a block's words (cheaper
// than constructing a new one for every block).
static_assert(std::is_trivially_copyable_v<BlockWords>);
inline void BlockWords::clear() {
  static const BlockWords kEmpty;
  *this = kEmpty;
}

}  // namespace ncoffset::interp
