// Thread cutting and tapping (PM-NC "Thread cutting with constant lead G33", "Thread cutting
// with variable lead G34, G35", "Tapping without compensating chuck G331, G332", "Tapping with
// compensating chuck G63"; docs/threads.md): straight lines whose motion keeps its own name
// through every stage and output. The lead is what the spindle turns per millimetre of path, so
// the segment's feed is the lead in mm/rev.
#include <fmt/format.h>

#include <cmath>

#include "interp/interpreter.hpp"
#include "interp/motion_builder.hpp"
#include "ncoffset/alarm.hpp"

namespace ncoffset::interp {

bool Interpreter::threadMotionWord(int g) {
  switch (g) {
    case 33:
      modal_.motion = Motion::G33;
      break;
    case 34:
      modal_.motion = Motion::G34;
      break;
    case 35:
      modal_.motion = Motion::G35;
      break;
    case 331:
      modal_.motion = Motion::G331;
      break;
    case 332:
      modal_.motion = Motion::G332;
      break;
    default:
      return false;
  }
  words_.motion_word = true;
  return true;
}

// I, J, K without G2/G3: in a thread block (G33..G332) they are the lead of the thread along
// X, Y, Z; kept as the modal lead (a chained thread may leave it out in its next blocks).
void Interpreter::threadLeadWords() {
  const bool thread = isThreadMotion(modal_.motion);
  if (!thread || words_.cr || words_.ar || words_.turn)
    raise(AlarmNumber::CircleProgramming,
          thread ? "circle programming error: CR=, AR= or TURN= in a thread block (G33..G332)"
                 : "circle programming error: I, J, K, CR=, AR= or TURN= without G2/G3");
  Vec3 lead;
  for (int i = 0; i < 3; ++i) {
    if (!words_.centre[i]) continue;
    lead[i] = std::fabs(interp::toMm(modal_, words_.centre_value[i]));
    if (!std::isfinite(lead[i]) || lead[i] > 1e6)
      raise(AlarmNumber::ValueRange,
            fmt::format("value range exceeded: thread lead {} = {}", "IJK"[i], lead[i]));
  }
  modal_.thread_lead = lead;
}

// The feed of a thread line: the lead (mm/rev) of the axis with the longest path among those
// programmed (PM-NC "G33": a taper thread's lead is given for its longer axis); G34/G35 carry F
// as the lead change (mm/rev per revolution). G63 (group 2, this block only) names a G1 line,
// which keeps F.
void MotionBuilder::threadFeed(const BlockWords& w, const ModalState& modal, const Vec3& from,
                               const Vec3& to) {
  core::MotionBlock& m = m_;
  if (!isThreadMotion(m.motion)) {  // G63 in a G0..G3 block
    if (m.motion != Motion::G1)
      raise(AlarmNumber::NotModelled,
            "G63 (tapping with compensating chuck) with G0, G2 or G3 is not modelled by ncoffset: "
            "program the tapping line with G1");
    m.motion = Motion::G63;
    return;
  }
  if (w.tapping_chuck) raise(AlarmNumber::SyntaxError, "G63 together with G33..G332 in one block");
  const Vec3& lead = modal.thread_lead;
  int ax = -1;
  for (int i = 0; i < 3; ++i)
    if (lead[i] > 0 && (ax < 0 || std::fabs(to[i] - from[i]) > std::fabs(to[ax] - from[ax])))
      ax = i;
  if (ax < 0)
    raise(AlarmNumber::FeedNotProgrammed,
          fmt::format("no thread lead programmed: {} needs the lead with I, J or K",
                      motionName(m.motion)));
  m.feed = lead[ax];
  m.feed_unit = FeedUnit::MmPerRev;
  m.has_feed = true;
  if (m.motion == Motion::G34 || m.motion == Motion::G35) {
    if (modal.feed <= 0)
      raise(AlarmNumber::FeedNotProgrammed,
            fmt::format("no lead change programmed: {} needs F (mm/rev per revolution)",
                        motionName(m.motion)));
    m.lead_change = modal.feed;
  }
}

}  // namespace ncoffset::interp
