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

// Alarm numbers used across stages. Values verified against the 840D sl diagnostics manual
// where docs/alarms.md says so.
namespace alarm_no {
inline constexpr int kFeedNotProgrammed = 10860;
inline constexpr int kSyntaxError = 12080;
inline constexpr int kNotImplemented = 12140;
inline constexpr int kValueRange = 12160;
inline constexpr int kTypeMismatch = 12150;
inline constexpr int kNameNotDefined = 12550;
inline constexpr int kAlreadyDefined = 12170;
inline constexpr int kControlNesting = 12640;
inline constexpr int kControlDepth = 12641;
inline constexpr int kProgramNotFound = 14011;
inline constexpr int kWrongCallParams = 14020;
inline constexpr int kCircleEndPoint = 14040;
inline constexpr int kCircleProgramming = 14045;
inline constexpr int kArithmetic = 14051;
inline constexpr int kCircleTurns = 14048;
inline constexpr int kJumpNotFound = 14080;
inline constexpr int kUnknownGCode = 12470;
inline constexpr int kAddressTwice = 12010;
inline constexpr int kIllegalDef = 14500;
inline constexpr int kArrayIndex1 = 17020;
inline constexpr int kArrayIndex2 = 17030;
inline constexpr int kSubprogramDepth = 14012;
inline constexpr int kEdgeNotExisting = 17181;
inline constexpr int kToolNotExisting = 17191;
// ncoffset's own numbers: limits and constructs not modelled.
inline constexpr int kLineTooLong = 99001;
inline constexpr int kBlockLimit = 99002;
inline constexpr int kExpressionDepth = 99003;
inline constexpr int kTooManyVariables = 99004;
inline constexpr int kArrayTooLarge = 99005;
inline constexpr int kNotModelled = 99010;
inline constexpr int kBadCharacter = 99011;
inline constexpr int kFrameNotAffine = 99012;
inline constexpr int kUnitsOrData = 99013;
}  // namespace alarm_no

// Thrown inside the pipeline and caught at the run boundary, where it becomes an Alarm value.
class AlarmError : public std::runtime_error {
 public:
  AlarmError(int number, std::string text, int line = 0, int column = 0)
      : std::runtime_error(text),
        number_(number),
        text_(std::move(text)),
        line_(line),
        column_(column) {}
  int number() const { return number_; }
  // A line other than the executing block's (e.g. a structure error found by the pre-scan).
  int line() const { return line_; }
  // The column, where the raising code knows it better than the executing statement (0).
  int column() const { return column_; }
  const std::string& text() const { return text_; }

 private:
  int number_;
  std::string text_;
  int line_;
  int column_;
};

[[noreturn]] inline void raise(int number, std::string text) {
  throw AlarmError(number, std::move(text));
}

}  // namespace ncoffset
