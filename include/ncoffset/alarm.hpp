// Alarms: how ncoffset reports that the control would stop (W1, and the control's alarm list).
#pragma once

#include <stdexcept>
#include <string>

namespace ncoffset {

// Where a block came from: the program file, its 1-based line and, where known, the 1-based
// column of the word or statement concerned (0: the whole line).
struct SourceLoc {
  std::string file;
  int line = 0;
  int column = 0;
};

// One alarm, carried as data and printed at the CLI edge as `FILE:LINE: alarm N: TEXT`.
// `number` is the SINUMERIK alarm number where the control has one; numbers 99000..99999 are
// ncoffset's own (resource limits and constructs it does not model), see docs/alarms.md.
struct Alarm {
  int number = 0;
  SourceLoc where;
  std::string text;
  std::string source_line;  // the text of the line at `where` (empty where it is not known)
};

// The alarm numbers ncoffset raises: the SINUMERIK 840D sl number where the control has one
// (docs/alarms.md says which were verified against the diagnostics manual), ncoffset's own in
// 99000..99999. `Alarm::number` carries the value as an int.
enum class AlarmNumber : int {
  // --- smooth approach and retraction (W1 2.4.4) ---
  SarTooManyBlocks = 10740,     // more blocks without plane motion than MD20202 before the tangent
  SarInfeedReversal = 10741,    // the infeed reverses its direction
  SarInvalidDistance = 10742,   // DISR missing or invalid
  SarProgrammedTwice = 10743,   // SAR in one block twice, or before the previous is complete
  SarNoDirection = 10744,       // no block after an approach / no contour before a retraction
  SarPreprocessorStop = 10746,  // STOPRE between the SAR block and its tangent block
  SarRetractionDirection = 10747,  // G143 on a retraction with an implicit end point
  // --- tool radius compensation (W1 2.4) ---
  TrcCollision = 10751,             // no intersection within the MD20240 reviewed blocks
  TrcSelectionNotLinear = 10753,    // G41/G42 selected in a circle block
  TrcDeselectionNotLinear = 10754,  // G40 in a circle block
  TrcKontSelection = 10755,         // KONT selection impossible at the start point
  TrcKontDeselection = 10756,       // KONT deselection impossible at the end point
  TrcPlaneChange = 10757,           // G17/G18/G19 while G41/G42 is active
  TrcCurvatureTooSmall = 10758,     // curvature radius too small for a variable compensation value
  TrcTooManyEmptyBlocks = 10762,    // more blocks without plane motion than MD20250
  TrcBlockOmitted = 10763,          // warning: a block omitted by bottleneck detection
  TrcPreprocessorStop = 10778,      // STOPRE while compensation is active, SD42480 = 1
  // --- contour definitions with angles (PM-NC "Contour definitions") ---
  AngleLineInterpolation = 10792,  // ANG= in a circle block (a line with angles only)
  AngleLineSecondBlock = 10793,    // the second block of a two-angle definition is missing
  AngleLineSecondAngle = 10794,    // the second block has its end point but no ANG=
  AngleLineContradiction = 10795,  // end point and angle contradict each other (no intersection)
  // --- the channel ---
  FeedNotProgrammed = 10860,   // G1/G2/G3 without a feedrate
  AddressTwice = 12010,        // an address twice in one block
  SyntaxError = 12080,         // syntax error (text and column given)
  NotImplemented = 12140,      // a function the control does not have in this configuration
  TypeMismatch = 12150,        // operation not compatible with the data type
  ValueRange = 12160,          // value out of range
  AlreadyDefined = 12170,      // a name defined twice
  ParamNotVariable = 12320,    // an expression given for a call-by-reference (VAR) parameter
  ParamType = 12330,           // type (or array dimension) of a parameter incorrect
  TooManyParams = 12340,       // more arguments than the subprogram has parameters
  UnknownGCode = 12470,        // unknown G function
  NameNotDefined = 12550,      // name not defined or option not available
  ControlNesting = 12640,      // invalid nesting of control structures
  ControlDepth = 12641,        // control structures nested too deep
  DefaultParam = 14010,        // a VAR or AXIS parameter left out in a call
  ProgramNotFound = 14011,     // program not existing
  SubprogramDepth = 14012,     // maximum subprogram level exceeded
  WrongCallParams = 14020,     // wrong number or type of parameters in a call
  CircleEndPoint = 14040,      // end point not on the circle
  CircleProgramming = 14045,   // circle not defined
  CircleTurns = 14048,         // TURN= outside 0..999
  Arithmetic = 14051,          // arithmetic error (division by zero, SQRT(-1), overflow)
  JumpNotFound = 14080,        // jump destination not found
  CarrierNumber = 14150,       // toolholder number (TCARR) programmed incorrectly or MD error
  CarrierOrientation = 14152,  // toolholder: invalid orientation (TCOFR cannot reach it)
  CarrierKind = 14153,         // toolholder: unknown kinematic type ($TC_CARR23)
  IllegalDef = 14500,          // DEF after the first statement
  NoTransverseAxis = 16510,    // diameter programming without a transverse axis (MD20100)
  DcNotAllowed = 16800,        // DC for an axis that is no modulo rotary axis
  AcpNotAllowed = 16810,       // ACP for an axis that is no modulo rotary axis
  AcnNotAllowed = 16820,       // ACN for an axis that is no modulo rotary axis
  ModuloPosition = 16830,      // DC/ACP/ACN position outside 0 <= value < 360
  ArrayIndex1 = 17020,         // array index 1 out of range
  ArrayIndex2 = 17030,         // array index 2 out of range
  EdgeNotExisting = 17181,     // T no., D no. not existing
  SumOffsetIllegal = 17182,    // DL= not defined for the edge or beyond MD18110
  ToolNotExisting = 17191,     // T not existing
  // --- ncoffset's own: limits (docs/limits.md) and what it does not model ---
  LineTooLong = 99001,       // block longer than --max-line-length
  BlockLimit = 99002,        // more than --max-blocks executed blocks
  ExpressionDepth = 99003,   // expression nested deeper than --max-expression-depth
  TooManyVariables = 99004,  // more than --max-variables user variables (or tool edges)
  ArrayTooLarge = 99005,     // array larger than the limits, or out of memory
  NoMotionLimit = 99006,     // more than --max-blocks-without-motion blocks without a motion
  EndlessLoop = 99007,       // a loop that passes twice through the same state: never ends
  NotModelled = 99010,       // a construct the control knows and ncoffset does not model
  BadCharacter = 99011,      // a byte not allowed outside comments and strings
  FrameNotAffine = 99012,    // a circle a non-uniform scale would make an ellipse
  UnitsOrData = 99013,       // machine/setting data with a value ncoffset does not model
};

constexpr int toInt(AlarmNumber n) {
  return static_cast<int>(n);
}

// Thrown inside the pipeline and caught at the run boundary, where it becomes an Alarm value.
class AlarmError : public std::runtime_error {
 public:
  AlarmError(AlarmNumber number, std::string text, int line = 0, int column = 0)
      : std::runtime_error(text),
        number_(number),
        text_(std::move(text)),
        line_(line),
        column_(column) {}
  int number() const { return toInt(number_); }
  AlarmNumber alarm() const { return number_; }
  // A line other than the executing block's (e.g. a structure error found by the pre-scan).
  int line() const { return line_; }
  // The column, where the raising code knows it better than the executing statement (0).
  int column() const { return column_; }
  const std::string& text() const { return text_; }

 private:
  AlarmNumber number_;
  std::string text_;
  int line_;
  int column_;
};

[[noreturn]] inline void raise(AlarmNumber number, std::string text) {
  throw AlarmError(number, std::move(text));
}

}  // namespace ncoffset
