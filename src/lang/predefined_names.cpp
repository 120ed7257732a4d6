// The table of predefined names (lang/predefined_names.hpp), in the order of
// std::string_view's comparison; docs/names.md lists the same rows (tests/interp/
// predefined_names_test.cpp checks that they agree).
#include "lang/predefined_names.hpp"

#include <algorithm>
#include <iterator>

namespace ncoffset::lang {
namespace {

constexpr PredefinedName kNames[] = {
    {"$AA_", NameClass::NotModelled, false, true, false,
     "main-run axis state: not modelled (except $AA_IW, $AA_IM)"},
    {"$AC_", NameClass::NotModelled, false, true, false,
     "main-run channel state: not modelled (except the ones in this table)"},
    {"$AC_TIME", NameClass::NotModelled, false, false, false,
     "main-run time since the block start: not modelled"},
    {"$A_", NameClass::NotModelled, false, true, false,
     "inputs, outputs, PLC data and the clock of the machine: values ncoffset does not have"},
    {"$TC_CARR", NameClass::NotModelled, true, true, false,
     "tool carrier data: not modelled yet; 0 is accepted (init files)"},
    {"$TC_ECP", NameClass::NotModelled, true, true, false,
     "location-dependent (setup) offsets of an edge: not modelled yet; 0 is accepted (init files)"},
    {"$TC_SCP", NameClass::NotModelled, true, true, false,
     "location-dependent (setup) offsets: not modelled yet; 0 is accepted (init files)"},
    {"$VA_", NameClass::NotModelled, false, true, false, "main-run (encoder) values: not modelled"},
    {"ACC", NameClass::NoPathEffect, false, false, false,
     "acceleration override of an axis: changes how fast the path is travelled (acceleration, "
     "jerk, feed profile), not where"},
    {"ADIS", NameClass::NoPathEffect, false, false, false,
     "rounding distance of G641/G642 in path blocks: the interpolator rounds the corner within "
     "ADIS; ncoffset outputs the programmed (compensated) corner it starts from"},
    {"ADISPOS", NameClass::NoPathEffect, false, false, false,
     "rounding distance for G0 blocks (as ADIS)"},
    {"ALF", NameClass::NoPathEffect, false, false, false,
     "lift-off direction of LIFTFAST (an interrupt, never triggered here)"},
    {"ANG", NameClass::NotModelled, false, false, false,
     "contour definition by angle: not modelled yet"},
    {"AP", NameClass::NotModelled, false, false, false,
     "polar angle (polar coordinates): not modelled yet"},
    {"ATOL", NameClass::NoPathEffect, false, false, false,
     "axis tolerance of the compressor and smoothing (as CTOL)"},
    {"BRISKA", NameClass::NoPathEffect, false, false, false,
     "acceleration profile of positioning axes: changes how fast the path is travelled "
     "(acceleration, jerk, feed profile), not where"},
    {"CALCDAT", NameClass::NotModelled, false, false, false,
     "computes a circle from points; its results steer the program: not modelled yet"},
    {"CHF", NameClass::NotModelled, true, false, false,
     "chamfer between two blocks: changes the corner; not modelled yet (CHF=0 accepted)"},
    {"CHR", NameClass::NotModelled, true, false, false,
     "chamfer between two blocks: changes the corner; not modelled yet (CHR=0 accepted)"},
    {"CLEARM", NameClass::NoPathEffect, false, false, false,
     "clears channel wait marks (channel synchronisation; one channel here)"},
    {"CLRINT", NameClass::NoPathEffect, false, false, false,
     "clears an interrupt assignment (interrupts are never triggered here)"},
    {"COMPCAD", NameClass::NoPathEffect, false, false, false,
     "compressor: the interpolator replaces G1 blocks by polynomials within the tolerance CTOL; "
     "ncoffset outputs the programmed points"},
    {"COMPCURV", NameClass::NoPathEffect, false, false, false, "compressor (as COMPCAD)"},
    {"COMPOF", NameClass::NoPathEffect, false, false, false, "compressor off"},
    {"COMPON", NameClass::NoPathEffect, false, false, false, "compressor (as COMPCAD)"},
    {"COMPSURF", NameClass::NoPathEffect, false, false, false, "compressor (as COMPCAD)"},
    {"CORROF", NameClass::NoPathEffect, false, false, false,
     "deletes DRF and overlay offsets (not modelled, so none to delete)"},
    {"CP", NameClass::NoPathEffect, false, false, false,
     "path motion (the default); PTP differs only with a transformation"},
    {"CPRECOF", NameClass::NoPathEffect, false, false, false, "programmable contour precision off"},
    {"CPRECON", NameClass::NoPathEffect, false, false, false,
     "programmable contour precision: limits the speed at curvature, not the path"},
    {"CTOL", NameClass::NoPathEffect, false, false, false,
     "contour tolerance of the compressor and smoothing: bounds how far the interpolated path may "
     "leave the programmed one"},
    {"CUT2D", NameClass::Modelled, false, false, false,
     "2½D radius compensation in the working plane G17/G18/G19: the default of group 22 and what "
     "ncoffset computes"},
    {"CUT2DF", NameClass::NotModelled, false, false, false,
     "radius compensation in the plane of the active frame: not modelled yet"},
    {"CUT3DC", NameClass::NotModelled, false, false, false,
     "3D circumferential milling compensation (5-axis): not modelled yet"},
    {"CUT3DCC", NameClass::NotModelled, false, false, false,
     "3D compensation with limit surfaces: not modelled yet"},
    {"CUT3DCCD", NameClass::NotModelled, false, false, false,
     "3D compensation with limit surfaces, differential tool: not modelled yet"},
    {"CUT3DF", NameClass::NotModelled, false, false, false,
     "3D face milling compensation: not modelled yet"},
    {"CUT3DFF", NameClass::NotModelled, false, false, false,
     "3D face milling compensation with constant orientation: not modelled yet"},
    {"CUT3DFS", NameClass::NotModelled, false, false, false,
     "3D face milling compensation: not modelled yet"},
    {"CUTCONOF", NameClass::Modelled, false, false, false,
     "contour tool off: the default of its group, what ncoffset computes"},
    {"CUTCONON", NameClass::NotModelled, false, false, false,
     "contour tool (edges as a contour): not modelled yet"},
    {"CYCLE60", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet"},
    {"CYCLE61", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (face milling)"},
    {"CYCLE62", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (contour call)"},
    {"CYCLE63", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (contour "
     "pocket)"},
    {"CYCLE64", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (contour pocket "
     "predrilling)"},
    {"CYCLE70", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (thread "
     "milling)"},
    {"CYCLE71", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (face milling)"},
    {"CYCLE72", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (path milling)"},
    {"CYCLE76", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (rectangular "
     "spigot)"},
    {"CYCLE77", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (circular "
     "spigot)"},
    {"CYCLE78", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (drill thread "
     "milling)"},
    {"CYCLE79", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (multi-edge)"},
    {"CYCLE800", NameClass::NotModelled, false, false, true,
     "swivelling the working plane: changes frames and tool orientation; not modelled yet"},
    {"CYCLE801", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (grid of "
     "holes)"},
    {"CYCLE802", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (arbitrary "
     "positions)"},
    {"CYCLE81", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (drilling, "
     "centring)"},
    {"CYCLE82", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (drilling, "
     "counterboring)"},
    {"CYCLE83", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (deep-hole "
     "drilling)"},
    {"CYCLE830", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (deep-hole "
     "drilling 2)"},
    {"CYCLE832", NameClass::NoPathEffect, false, false, true,
     "high-speed settings (tolerance, G642, COMPCAD, SOFT, FFWON): all of class (b)"},
    {"CYCLE84", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (rigid "
     "tapping)"},
    {"CYCLE840", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (tapping with "
     "compensating chuck)"},
    {"CYCLE85", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (boring 1)"},
    {"CYCLE86", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (boring 2)"},
    {"CYCLE87", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (boring 3)"},
    {"CYCLE88", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (boring 4)"},
    {"CYCLE89", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (boring 5)"},
    {"CYCLE90", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (thread "
     "milling)"},
    {"CYCLE92", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (parting)"},
    {"CYCLE93", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (groove)"},
    {"CYCLE95", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (stock "
     "removal)"},
    {"CYCLE951", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (stock "
     "removal)"},
    {"CYCLE952", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (contour "
     "turning)"},
    {"CYCLE97", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (thread "
     "cutting)"},
    {"CYCLE98", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (thread "
     "chaining)"},
    {"CYCLE99", NameClass::NotModelled, false, false, true,
     "a machining cycle: the cycle program computes its own path; not modelled yet (thread "
     "turning)"},
    {"DELDTG", NameClass::NoPathEffect, false, false, false,
     "delete distance-to-go: acts only with a measuring input (not modelled)"},
    {"DELETE", NameClass::NoPathEffect, false, false, false,
     "deletes a file in the control's memory (file handling, no motion); its error variable is set "
     "to 0"},
    {"DELTOOLENV", NameClass::NotModelled, false, false, false,
     "tool environments: not modelled yet"},
    {"DISABLE", NameClass::NoPathEffect, false, false, false,
     "disables an interrupt (interrupts are never triggered here)"},
    {"DISPLOF", NameClass::NoPathEffect, false, false, false,
     "block display off (operator display)"},
    {"DISPLON", NameClass::NoPathEffect, false, false, false,
     "block display on (operator display)"},
    {"DISPR", NameClass::NoPathEffect, false, false, false,
     "repositioning distance (REPOS after an interruption)"},
    {"DITE", NameClass::NoPathEffect, false, false, false,
     "run-out path of a thread (G33, itself not modelled)"},
    {"DITS", NameClass::NoPathEffect, false, false, false,
     "run-in path of a thread (G33, itself not modelled)"},
    {"DL", NameClass::NotModelled, true, false, false,
     "location-dependent (setup) offset: not modelled yet; DL=0 (none, the default) is accepted"},
    {"DRFOF", NameClass::NoPathEffect, false, false, false,
     "deletes the handwheel (DRF) offsets (not modelled, so none to delete)"},
    {"DRIVEA", NameClass::NoPathEffect, false, false, false,
     "acceleration profile of positioning axes: changes how fast the path is travelled "
     "(acceleration, jerk, feed profile), not where"},
    {"ENABLE", NameClass::NoPathEffect, false, false, false,
     "enables an interrupt (interrupts are never triggered here)"},
    {"EXECSTRING", NameClass::NotModelled, false, false, false,
     "runs a string as a block: not modelled yet"},
    {"EXECTAB", NameClass::NotModelled, false, false, false,
     "runs a table of contour elements: not modelled yet"},
    {"FA", NameClass::NoPathEffect, false, false, false,
     "feed of a positioning axis: changes when it arrives, not where (docs/language.md \"Axes\")"},
    {"FCUB", NameClass::NoPathEffect, false, false, false,
     "feed profile over the block: changes how fast the path is travelled (acceleration, jerk, "
     "feed profile), not where"},
    {"FGREF", NameClass::NoPathEffect, false, false, false,
     "reference radius of rotary-axis feed (rotary axes are not modelled)"},
    {"FGROUP", NameClass::NoPathEffect, false, false, false,
     "which axes the path feed refers to; the feed column keeps the programmed F"},
    {"FIFOCTRL", NameClass::NoPathEffect, false, false, false, "preprocessing buffer control"},
    {"FL", NameClass::NoPathEffect, false, false, false,
     "limit speed of synchronised axes: changes how fast the path is travelled (acceleration, "
     "jerk, feed profile), not where"},
    {"FLIN", NameClass::NoPathEffect, false, false, false,
     "feed profile over the block: changes how fast the path is travelled (acceleration, jerk, "
     "feed profile), not where"},
    {"FNORM", NameClass::NoPathEffect, false, false, false,
     "feed profile over the block (the default): changes how fast the path is travelled "
     "(acceleration, jerk, feed profile), not where"},
    {"FRC", NameClass::NoPathEffect, false, false, false,
     "feed of a chamfer or rounding (RND/CHF are not modelled)"},
    {"FRCM", NameClass::NoPathEffect, false, false, false,
     "modal feed of chamfers and roundings (RND/CHF are not modelled)"},
    {"FZ", NameClass::NoPathEffect, false, false, false,
     "feed per tooth (effective with G95, see docs/turning.md); the feed column keeps the "
     "programmed F"},
    {"GETTCOR", NameClass::NotModelled, false, false, false, "tool environments: not modelled yet"},
    {"GROUP_BEGIN", NameClass::NoPathEffect, false, false, false,
     "marks a group of blocks for the program editor"},
    {"GROUP_END", NameClass::NoPathEffect, false, false, false, "end of GROUP_BEGIN"},
    {"IPTRLOCK", NameClass::NoPathEffect, false, false, false,
     "marks where a block search may not resume (operator function)"},
    {"IPTRUNLOCK", NameClass::NoPathEffect, false, false, false, "ends IPTRLOCK"},
    {"ISFILE", NameClass::NotModelled, false, false, false,
     "whether a file exists in the control's memory: ncoffset does not know it"},
    {"JERKLIM", NameClass::NoPathEffect, false, false, false,
     "jerk limit override: changes how fast the path is travelled (acceleration, jerk, feed "
     "profile), not where"},
    {"LIFTFAST", NameClass::NoPathEffect, false, false, false,
     "fast lift-off on an interrupt (interrupts are never triggered here)"},
    {"MEAS", NameClass::NotModelled, false, false, false,
     "measuring with a probe: the block ends where the probe triggers; not modelled"},
    {"MEAW", NameClass::NotModelled, false, false, false,
     "measuring with a probe without deleting the distance to go: not modelled"},
    {"ORIAXES", NameClass::NoPathEffect, false, false, false,
     "orientation interpolation of a 5-axis transformation; without TRAORI (99010) no effect"},
    {"ORIEULER", NameClass::NoPathEffect, false, false, false,
     "orientation angles of a 5-axis transformation; without TRAORI (99010) no effect"},
    {"ORIMKS", NameClass::NoPathEffect, false, false, false,
     "orientation reference of a 5-axis transformation; without TRAORI (99010) no effect"},
    {"ORIRESET", NameClass::NotModelled, false, false, false,
     "moves the orientation axes to their initial positions: rotary axes are not modelled"},
    {"ORIRPY", NameClass::NoPathEffect, false, false, false,
     "orientation angles of a 5-axis transformation; without TRAORI (99010) no effect"},
    {"ORIVECT", NameClass::NoPathEffect, false, false, false,
     "orientation interpolation of a 5-axis transformation; without TRAORI (99010) no effect"},
    {"ORIWKS", NameClass::NoPathEffect, false, false, false,
     "orientation reference of a 5-axis transformation; without TRAORI (99010) no effect"},
    {"OVR", NameClass::NoPathEffect, false, false, false,
     "path override: changes how fast the path is travelled (acceleration, jerk, feed profile), "
     "not where"},
    {"OVRA", NameClass::NoPathEffect, false, false, false,
     "axis override: changes how fast the path is travelled (acceleration, jerk, feed profile), "
     "not where"},
    {"OVRRAP", NameClass::NoPathEffect, false, false, false,
     "rapid override: changes how fast the path is travelled (acceleration, jerk, feed profile), "
     "not where"},
    {"PAROT", NameClass::NotModelled, false, false, false,
     "aligns the workpiece coordinate system with the workpiece (frame rotation): not modelled "
     "yet"},
    {"PAROTOF", NameClass::Modelled, false, false, false,
     "deselects PAROT: the state ncoffset models"},
    {"POS", NameClass::Modelled, false, false, false,
     "positioning axis motion POS[ax]=: the end position as an axis word of the block "
     "(docs/language.md \"Axes\")"},
    {"POSA", NameClass::Modelled, false, false, false,
     "positioning axis motion over block limits POSA[ax]=: the end position as an axis word of "
     "the block (when it is reached is not modelled)"},
    {"PRESETON", NameClass::NotModelled, false, false, false,
     "sets the actual value of an axis (a new machine coordinate): not modelled"},
    {"PRIO", NameClass::NoPathEffect, false, false, false,
     "priority of an interrupt routine (SETINT; never triggered here)"},
    {"PTP", NameClass::NoPathEffect, false, false, false,
     "point-to-point motion differs from CP only with a transformation (not modelled)"},
    {"PTPG0", NameClass::NoPathEffect, false, false, false,
     "PTP for G0 only with a transformation (not modelled)"},
    {"READ", NameClass::NotModelled, false, false, false,
     "reads lines of a file in the control's memory: data ncoffset does not have"},
    {"RND", NameClass::NotModelled, true, false, false,
     "rounding between two blocks: changes the corner; not modelled yet (RND=0 accepted)"},
    {"RNDM", NameClass::NotModelled, true, false, false,
     "modal rounding: changes every corner; not modelled yet (RNDM=0 accepted)"},
    {"RP", NameClass::NotModelled, false, false, false,
     "polar radius (polar coordinates): not modelled yet"},
    {"RTLIOF", NameClass::NotModelled, false, false, false,
     "G0 without interpolation: each axis at its own speed, the path between the end points is no "
     "line; not modelled"},
    {"RTLION", NameClass::NoPathEffect, false, false, false,
     "G0 with linear interpolation (the default): the line ncoffset outputs"},
    {"SBLOF", NameClass::NoPathEffect, false, false, false,
     "single-block suppression (operator control)"},
    {"SBLON", NameClass::NoPathEffect, false, false, false,
     "single block allowed again (operator control)"},
    {"SETAL", NameClass::Modelled, false, false, false,
     "sets the cycle alarm it names (60000..69999): the program stops with that alarm, as on the "
     "control"},
    {"SETINT", NameClass::NoPathEffect, false, false, false,
     "assigns an interrupt routine to an input (never triggered here)"},
    {"SETM", NameClass::NoPathEffect, false, false, false,
     "sets channel wait marks (one channel here)"},
    {"SETPIECE", NameClass::NoPathEffect, false, false, false,
     "piece count of the tool management"},
    {"SETTCOR", NameClass::NotModelled, false, false, false, "tool environments: not modelled yet"},
    {"SF", NameClass::NoPathEffect, false, false, false,
     "start angle of a thread (G33, itself not modelled)"},
    {"SOFTA", NameClass::NoPathEffect, false, false, false,
     "acceleration profile of positioning axes: changes how fast the path is travelled "
     "(acceleration, jerk, feed profile), not where"},
    {"SPATH", NameClass::NoPathEffect, false, false, false,
     "feed reference of FGROUP axes (path length, the default)"},
    {"SPCOF", NameClass::NoPathEffect, false, false, false, "spindle back to speed control"},
    {"SPCON", NameClass::NoPathEffect, false, false, false, "spindle in position control"},
    {"STARTFIFO", NameClass::NoPathEffect, false, false, false, "preprocessing buffer control"},
    {"STAT", NameClass::NotModelled, false, false, false,
     "position of the joints for a transformation (PTP): not modelled"},
    {"STOLF", NameClass::NoPathEffect, false, false, false, "G0 tolerance factor of the smoothing"},
    {"STOPFIFO", NameClass::NoPathEffect, false, false, false, "preprocessing buffer control"},
    {"STOPREOF", NameClass::NoPathEffect, false, false, false,
     "ends a preprocessor stop that a synchronized action set (none here)"},
    {"TCARR", NameClass::NotModelled, true, false, false,
     "orientable tool holder (tool carrier): not modelled yet; TCARR=0 (none) is accepted"},
    {"TCOABS", NameClass::Modelled, false, false, false,
     "tool length from the tool data alone (the default of group 42): what ncoffset computes"},
    {"TCOFR", NameClass::NotModelled, false, false, false,
     "tool length from the orientation of the active frame (tool carrier): not modelled yet"},
    {"TCOFRX", NameClass::NotModelled, false, false, false, "as TCOFR: not modelled yet"},
    {"TCOFRY", NameClass::NotModelled, false, false, false, "as TCOFR: not modelled yet"},
    {"TCOFRZ", NameClass::NotModelled, false, false, false, "as TCOFR: not modelled yet"},
    {"TOFF", NameClass::NotModelled, true, false, false,
     "programmable tool length offset in an axis: not modelled yet; 0 is accepted"},
    {"TOFFL", NameClass::NotModelled, true, false, false,
     "programmable tool length offset: not modelled yet; 0 is accepted"},
    {"TOFFR", NameClass::NotModelled, true, false, false,
     "programmable tool radius offset: not modelled yet; 0 is accepted"},
    {"TOFRAME", NameClass::NotModelled, false, false, false,
     "frame along the tool orientation: not modelled yet"},
    {"TOFRAMEX", NameClass::NotModelled, false, false, false, "as TOFRAME: not modelled yet"},
    {"TOFRAMEY", NameClass::NotModelled, false, false, false, "as TOFRAME: not modelled yet"},
    {"TOFRAMEZ", NameClass::NotModelled, false, false, false, "as TOFRAME: not modelled yet"},
    {"TOOLENV", NameClass::NotModelled, false, false, false, "tool environments: not modelled yet"},
    {"TOROT", NameClass::NotModelled, false, false, false,
     "frame rotation along the tool orientation: not modelled yet"},
    {"TOROTOF", NameClass::Modelled, false, false, false,
     "deselects TOROT: the state ncoffset models"},
    {"TOROTX", NameClass::NotModelled, false, false, false, "as TOROT: not modelled yet"},
    {"TOROTY", NameClass::NotModelled, false, false, false, "as TOROT: not modelled yet"},
    {"TOROTZ", NameClass::NotModelled, false, false, false, "as TOROT: not modelled yet"},
    {"TU", NameClass::NotModelled, false, false, false,
     "turn of the axes for a transformation (PTP): not modelled"},
    {"UPATH", NameClass::NoPathEffect, false, false, false,
     "feed reference of FGROUP axes (curve parameter)"},
    {"VELOLIM", NameClass::NoPathEffect, false, false, false,
     "velocity limit override: changes how fast the path is travelled (acceleration, jerk, feed "
     "profile), not where"},
    {"WAITE", NameClass::NoPathEffect, false, false, false,
     "waits for the end of another channel's program (one channel here)"},
    {"WAITM", NameClass::NoPathEffect, false, false, false,
     "waits for wait marks of other channels (one channel here)"},
    {"WAITMC", NameClass::NoPathEffect, false, false, false,
     "conditional wait mark (one channel here)"},
    {"WAITS", NameClass::NoPathEffect, false, false, false, "waits for spindle positioning"},
    {"WALIMOF", NameClass::NoPathEffect, false, false, false,
     "working-area limitation off (a monitoring, not the path)"},
    {"WALIMON", NameClass::NoPathEffect, false, false, false,
     "working-area limitation on (a monitoring, not the path)"},
    {"WORKPIECE", NameClass::NoPathEffect, false, false, true,
     "blank definition for the simulation of the HMI"},
    {"WRITE", NameClass::NoPathEffect, false, false, false,
     "appends a line to a file in the control's memory (file handling, no motion); its error "
     "variable is set to 0 (done), ncoffset writes no file"},
};

constexpr bool sortedByName() {
  for (size_t i = 1; i < std::size(kNames); ++i)
    if (!(kNames[i - 1].name < kNames[i].name)) return false;
  return true;
}
static_assert(sortedByName(), "kNames must be sorted (binary search)");

}  // namespace

const PredefinedName* findPredefinedName(std::string_view name) {
  const auto* it =
      std::lower_bound(std::begin(kNames), std::end(kNames), name,
                       [](const PredefinedName& row, std::string_view n) { return row.name < n; });
  if (it != std::end(kNames) && it->name == name) return it;
  // $TC_SCP13, $AC_PATH: the rows that stand for a family of names (the longest prefix wins).
  const PredefinedName* best = nullptr;
  for (const PredefinedName& row : kNames)
    if (row.prefix && name.substr(0, row.name.size()) == row.name &&
        (!best || row.name.size() > best->name.size()))
      best = &row;
  return best;
}

const PredefinedName* predefinedNamesBegin() {
  return std::begin(kNames);
}
const PredefinedName* predefinedNamesEnd() {
  return std::end(kNames);
}

}  // namespace ncoffset::lang
