#include "limit_option.hpp"

#include <fmt/format.h>

#include <string>

namespace ncoffset::cli {

CLI::Validator limitValue(unsigned long long max, unsigned long long min) {
  auto parse = [max, min](std::string& text) -> std::string {
    auto bad = [&] {
      return fmt::format("'{}' is not a whole number {}..{} (decimal digits only)", text, min, max);
    };
    if (text.empty() || text.size() > 20) return bad();
    unsigned long long value = 0;
    for (char c : text) {
      if (c < '0' || c > '9') return bad();
      value = value * 10 + static_cast<unsigned>(c - '0');
      if (value > max) return bad();  // max < 2^64 / 10, so the product never wraps
    }
    if (value < min) return bad();
    text = std::to_string(value);
    return {};
  };
  return CLI::Validator(parse, fmt::format("{}..{}", min, max), "LIMIT");
}

}  // namespace ncoffset::cli
