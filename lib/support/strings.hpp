// Private, below every layer: text helpers for error messages.
#pragma once

#include <string>

namespace gkt::detail {

/// Returns the items joined by ", ", each wrapped in `quote` (for "valid: …" error messages).
template <class Range>
std::string join(const Range& items, const std::string& quote = "") {
  std::string out;
  for (const auto& item : items) {
    if (!out.empty()) out += ", ";
    out += quote;
    out += item;
    out += quote;
  }
  return out;
}

}  // namespace gkt::detail
