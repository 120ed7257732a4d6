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
    {"$TC_ECP", NameClass::Modelled, false, true, false,
     "setup offsets $TC_ECPxy[t,d] of DL x (with MD18112 bit 4; docs/tool-offsets.md section 10)"},
    {"$TC_SCP", NameClass::Modelled, false, true, false,
     "sum offsets $TC_SCPxy[t,d] of DL x (docs/tool-offsets.md section 10)"},
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
    {"ANG", NameClass::Modelled, false, false, false,
     "straight line by its angle to the abscissa; contour definitions with two angles "
     "(docs/contour-definitions.md)"},
    {"AP", NameClass::Modelled, false, false, false,
     "polar angle about the pole of G110/G111/G112 (docs/contour-definitions.md)"},
    {"ATOL", NameClass::NoPathEffect, false, false, false,
     "axis tolerance of the compressor and smoothing (as CTOL)"},
    {"BRISKA", NameClass::NoPathEffect, false, false, false,
     "acceleration profile of positioning axes: changes how fast the path is travelled "
     "(acceleration, jerk, feed profile), not where"},
    {"CALCDAT", NameClass::NotModelled, false, false, false,
     "computes a circle from points; its results steer the program: not modelled yet"},
    {"CHF", NameClass::Modelled, false, false, false,
     "chamfer of the given length at the end of the block (docs/contour-definitions.md)"},
    {"CHR", NameClass::Modelled, false, false, false,
     "chamfer with the given leg length at the end of the block (docs/contour-definitions.md)"},
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
     "2½D radius compensation in the working plane G17/G18/G19 of the machine (the default of "
     "group 22; g_codes.cpp)"},
    {"CUT2DD", NameClass::Modelled, false, false, false,
     "as CUT2D with a differential tool: compensated by the radius minus $TC_DP6"},
    {"CUT2DF", NameClass::Modelled, false, false, false,
     "2½D radius compensation in the plane of the active frame"},
    {"CUT2DFD", NameClass::Modelled, false, false, false,
     "as CUT2DF with a differential tool: compensated by the radius minus $TC_DP6"},
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
     "keep tool radius compensation constant off: the default of G group 40; the block that "
     "ends CUTCONON is compensated normally again"},
    {"CUTCONON", NameClass::Modelled, false, false, false,
     "keep tool radius compensation constant (W1): the blocks are traversed uncompensated, "
     "shifted by the offset vector at the end of the last compensated block"},
    {"CYCLE60", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle: its program computes the path, ncoffset does not model it; a "
     "CYCLE60.SPF on the search path runs instead"},
    {"CYCLE61", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (face milling): its program computes the path, ncoffset does not "
     "model it; a CYCLE61.SPF on the search path runs instead"},
    {"CYCLE62", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (contour call): its program computes the path, ncoffset does not "
     "model it; a CYCLE62.SPF on the search path runs instead"},
    {"CYCLE63", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (contour pocket): its program computes the path, ncoffset does not "
     "model it; a CYCLE63.SPF on the search path runs instead"},
    {"CYCLE64", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (contour pocket predrilling): its program computes the path, "
     "ncoffset does not model it; a CYCLE64.SPF on the search path runs instead"},
    {"CYCLE70", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (thread milling): its program computes the path, ncoffset does not "
     "model it; a CYCLE70.SPF on the search path runs instead"},
    {"CYCLE71", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (face milling): its program computes the path, ncoffset does not "
     "model it; a CYCLE71.SPF on the search path runs instead"},
    {"CYCLE72", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (path milling): its program computes the path, ncoffset does not "
     "model it; a CYCLE72.SPF on the search path runs instead"},
    {"CYCLE76", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (rectangular spigot): its program computes the path, ncoffset does "
     "not model it; a CYCLE76.SPF on the search path runs instead"},
    {"CYCLE77", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (circular spigot): its program computes the path, ncoffset does not "
     "model it; a CYCLE77.SPF on the search path runs instead"},
    {"CYCLE78", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (drill thread milling): its program computes the path, ncoffset "
     "does not model it; a CYCLE78.SPF on the search path runs instead"},
    {"CYCLE79", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (multi-edge): its program computes the path, ncoffset does not "
     "model it; a CYCLE79.SPF on the search path runs instead"},
    {"CYCLE800", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (swivelling the working plane: frames and tool orientation): "
     "ncoffset does not model it; a CYCLE800.SPF on the search path runs instead"},
    {"CYCLE801", NameClass::Modelled, false, false, true,
     "a standard drilling cycle modelled by ncoffset (grid of holes, docs/cycles.md)"},
    {"CYCLE802", NameClass::Modelled, false, false, true,
     "a standard drilling cycle modelled by ncoffset (arbitrary positions, docs/cycles.md)"},
    {"CYCLE81", NameClass::Modelled, false, false, true,
     "a standard drilling cycle modelled by ncoffset (drilling, centring, docs/cycles.md)"},
    {"CYCLE82", NameClass::Modelled, false, false, true,
     "a standard drilling cycle modelled by ncoffset (drilling, counterboring (dwell at depth), "
     "docs/cycles.md)"},
    {"CYCLE83", NameClass::Modelled, false, false, true,
     "a standard drilling cycle modelled by ncoffset (deep-hole drilling (chip breaking, chip "
     "removal), docs/cycles.md)"},
    {"CYCLE830", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (deep-hole drilling 2): its program computes the path, ncoffset "
     "does not model it; a CYCLE830.SPF on the search path runs instead"},
    {"CYCLE832", NameClass::NoPathEffect, false, false, true,
     "high-speed settings (tolerance, G642, COMPCAD, SOFT, FFWON): all of class (b)"},
    {"CYCLE84", NameClass::Modelled, false, false, true,
     "a standard drilling cycle modelled by ncoffset (rigid tapping (G331/G332), docs/cycles.md)"},
    {"CYCLE840", NameClass::Modelled, false, false, true,
     "a standard drilling cycle modelled by ncoffset (tapping with compensating chuck (G33 or "
     "G63), docs/cycles.md)"},
    {"CYCLE85", NameClass::Modelled, false, false, true,
     "a standard drilling cycle modelled by ncoffset (boring 1 (feed out), docs/cycles.md)"},
    {"CYCLE86", NameClass::Modelled, false, false, true,
     "a standard drilling cycle modelled by ncoffset (boring 2 (oriented stop, lift-off), "
     "docs/cycles.md)"},
    {"CYCLE87", NameClass::Modelled, false, false, true,
     "a standard drilling cycle modelled by ncoffset (boring 3 (stop M5 M0), docs/cycles.md)"},
    {"CYCLE88", NameClass::Modelled, false, false, true,
     "a standard drilling cycle modelled by ncoffset (boring 4 (dwell, stop M5 M0), "
     "docs/cycles.md)"},
    {"CYCLE89", NameClass::Modelled, false, false, true,
     "a standard drilling cycle modelled by ncoffset (boring 5 (dwell, feed out), docs/cycles.md)"},
    {"CYCLE90", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (thread milling): its program computes the path, ncoffset does not "
     "model it; a CYCLE90.SPF on the search path runs instead"},
    {"CYCLE92", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (parting): its program computes the path, ncoffset does not model "
     "it; a CYCLE92.SPF on the search path runs instead"},
    {"CYCLE93", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (groove): its program computes the path, ncoffset does not model "
     "it; a CYCLE93.SPF on the search path runs instead"},
    {"CYCLE930", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (groove): its program computes the path, ncoffset does not model "
     "it; a CYCLE930.SPF on the search path runs instead"},
    {"CYCLE940", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (undercut): its program computes the path, ncoffset does not model "
     "it; a CYCLE940.SPF on the search path runs instead"},
    {"CYCLE95", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (stock removal): its program computes the path, ncoffset does not "
     "model it; a CYCLE95.SPF on the search path runs instead"},
    {"CYCLE950", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (stock removal, extended): its program computes the path, ncoffset "
     "does not model it; a CYCLE950.SPF on the search path runs instead"},
    {"CYCLE951", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (stock removal): its program computes the path, ncoffset does not "
     "model it; a CYCLE951.SPF on the search path runs instead"},
    {"CYCLE952", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (contour turning): its program computes the path, ncoffset does not "
     "model it; a CYCLE952.SPF on the search path runs instead"},
    {"CYCLE96", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (thread undercut): its program computes the path, ncoffset does not "
     "model it; a CYCLE96.SPF on the search path runs instead"},
    {"CYCLE97", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (thread cutting): its program computes the path, ncoffset does not "
     "model it; a CYCLE97.SPF on the search path runs instead"},
    {"CYCLE98", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (thread chaining): its program computes the path, ncoffset does not "
     "model it; a CYCLE98.SPF on the search path runs instead"},
    {"CYCLE99", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (thread turning): its program computes the path, ncoffset does not "
     "model it; a CYCLE99.SPF on the search path runs instead"},
    {"DELDTG", NameClass::NoPathEffect, false, false, false,
     "delete distance-to-go: acts only with a measuring input (not modelled)"},
    {"DELETE", NameClass::NoPathEffect, false, false, false,
     "deletes a file in the control's memory (file handling, no motion); its error variable is set "
     "to 0"},
    {"DISABLE", NameClass::NoPathEffect, false, false, false,
     "disables an interrupt (interrupts are never triggered here)"},
    {"DISPLOF", NameClass::NoPathEffect, false, false, false,
     "block display off (operator display)"},
    {"DISPLON", NameClass::NoPathEffect, false, false, false,
     "block display on (operator display)"},
    {"DISPR", NameClass::NoPathEffect, false, false, false,
     "repositioning distance (REPOS after an interruption)"},
    {"DITE", NameClass::NoPathEffect, false, false, false,
     "run-out path of a thread: the acceleration at the thread's end, not its path"},
    {"DITS", NameClass::NoPathEffect, false, false, false,
     "run-in path of a thread: the acceleration at the thread's start, not its path"},
    {"DL", NameClass::Modelled, false, false, false,
     "selects the sum/setup offset of the active edge (docs/tool-offsets.md section 10)"},
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
    {"FRC", NameClass::Modelled, false, false, false,
     "feed of the block's chamfer or rounding (docs/contour-definitions.md)"},
    {"FRCM", NameClass::Modelled, false, false, false,
     "modal feed of chamfers and roundings, FRCM=0 off (docs/contour-definitions.md)"},
    {"FZ", NameClass::NoPathEffect, false, false, false,
     "feed per tooth (effective with G95, see docs/turning.md); the feed column keeps the "
     "programmed F"},
    {"GROUP_BEGIN", NameClass::NoPathEffect, false, false, false,
     "marks a group of blocks for the program editor"},
    {"GROUP_END", NameClass::NoPathEffect, false, false, false, "end of GROUP_BEGIN"},
    {"HOLES1", NameClass::Modelled, false, false, true,
     "a standard drilling cycle modelled by ncoffset (row of holes, docs/cycles.md)"},
    {"HOLES2", NameClass::Modelled, false, false, true,
     "a standard drilling cycle modelled by ncoffset (circle of holes, docs/cycles.md)"},
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
    {"LONGHOLE", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (elongated holes): its program computes the path, ncoffset does not "
     "model it; a LONGHOLE.SPF on the search path runs instead"},
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
    {"POCKET1", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle: its program computes the path, ncoffset does not model it; a "
     "POCKET1.SPF on the search path runs instead"},
    {"POCKET2", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle: its program computes the path, ncoffset does not model it; a "
     "POCKET2.SPF on the search path runs instead"},
    {"POCKET3", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (rectangular pocket): its program computes the path, ncoffset does "
     "not model it; a POCKET3.SPF on the search path runs instead"},
    {"POCKET4", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (circular pocket): its program computes the path, ncoffset does not "
     "model it; a POCKET4.SPF on the search path runs instead"},
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
    {"RND", NameClass::Modelled, false, false, false,
     "rounding of the given radius at the end of the block (docs/contour-definitions.md)"},
    {"RNDM", NameClass::Modelled, false, false, false,
     "modal rounding of every corner, RNDM=0 off (docs/contour-definitions.md)"},
    {"RP", NameClass::Modelled, false, false, false,
     "polar radius about the pole of G110/G111/G112 (docs/contour-definitions.md)"},
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
    {"SF", NameClass::NoPathEffect, false, false, false,
     "start angle of a thread (the spindle angle where the cut starts; multi-start threads: one "
     "pass per start, docs/threads.md): not the path"},
    {"SLOT1", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (slots on a circle): its program computes the path, ncoffset does "
     "not model it; a SLOT1.SPF on the search path runs instead"},
    {"SLOT2", NameClass::NotModelled, false, false, true,
     "a Siemens standard cycle (circumferential slots): its program computes the path, ncoffset "
     "does not model it; a SLOT2.SPF on the search path runs instead"},
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
    {"TOFF", NameClass::Modelled, false, false, false,
     "programmable tool length offset along an axis (docs/tool-offsets.md section 11)"},
    {"TOFFCR", NameClass::NotModelled, true, false, false,
     "programmable corner radius offset (3D tool radius compensation): not modelled; 0 is "
     "accepted"},
    {"TOFFL", NameClass::Modelled, false, false, false,
     "programmable tool length offset of L1..L3 (docs/tool-offsets.md section 11)"},
    {"TOFFLR", NameClass::NotModelled, true, false, false,
     "programmable length and radius offset for 3D tool radius compensation: not modelled; 0 "
     "is accepted"},
    {"TOFFOF", NameClass::NotModelled, false, false, false,
     "online tool length offset off (needs an orientation transformation): not modelled"},
    {"TOFFON", NameClass::NotModelled, false, false, false,
     "online tool length offset (only with an orientation transformation or toolholder, "
     "PM-JP \"Transformations\"): not modelled"},
    {"TOFFR", NameClass::Modelled, false, false, false,
     "programmable tool radius offset (docs/tool-offsets.md section 11)"},
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
