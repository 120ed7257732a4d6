// Text from a program (MSG texts, alarm texts quoting it, file names) on its way to stderr,
// which is usually a terminal: an escape sequence copied raw could recolour, retitle or clear
// it, or hide the line. Control characters are written as \xNN instead.
#pragma once

#include <string>
#include <string_view>

#include "ncoffset/alarm.hpp"

namespace ncoffset::cli {

// `text` with C0 controls, DEL, the C1 controls (U+0080..U+009F, which some terminals obey as
// ESC sequences) and bytes that are not valid UTF-8 written as \xNN (lower-case hex); printable
// ASCII and valid UTF-8 stay as they are.
std::string terminalSafe(std::string_view text);

// Writes terminalSafe(line) and a newline to stderr.
void printError(std::string_view line);

// The lines under an alarm that show where it is, as compilers do (nothing when `source` is
// empty; no caret when the column is not known):
//    12 | G1 X10 Y=1/0
//       |       ^
std::string sourceContext(const SourceLoc& where, std::string_view source);
void printSourceContext(const SourceLoc& where, std::string_view source);

}  // namespace ncoffset::cli
