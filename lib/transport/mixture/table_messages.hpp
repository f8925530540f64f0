// Private: the refusals shared by the binary and ternary per-cell tables (one line naming the field).
#pragma once

#include <string>

namespace gkt::detail {

/// Returns x with `digits` significant digits (3: measured errors, positions, echoed arguments;
/// 6: the ends of an interval a few 1e-4 wide).
std::string short_number(double x, int digits = 3);

/// Throws "<name>: must be <range>, got <value>" (evaluate's arguments), or with an empty range the
/// over- or underflow of the set at (n, T) = (value, temperature). Out of line and cold: the
/// per-state path stays a few compares (docs/performance.md).
[[noreturn, gnu::cold, gnu::noinline]] void refuse_state(const char* name, const char* range, double value,
                                                         double temperature);

}  // namespace gkt::detail
