// `--start X,Y,Z`: where the machine stands when the program starts (RunOptions::start), the tool
// carrier reference point in machine coordinates (docs/output-formats.md "Start position").
#pragma once

#include <optional>
#include <string>

#include "ncoffset/geometry.hpp"

namespace ncoffset::cli {

// Three decimal numbers separated by commas ("0,0,500", "-300.5,20,1e2"), each finite and within
// the machine's number range (|v| <= 1e9 mm). Nothing else: no hexadecimal, inf or nan, no spaces.
// nullopt for anything else, with the reason in `why`.
std::optional<Vec3> parseStart(const std::string& text, std::string& why);

}  // namespace ncoffset::cli
