// Private to the C API: the barrier no C++ exception crosses, the thread-local last error, and the
// checks shared by its functions (each refusal a one-line message naming the field and its range).
#pragma once

#include <charconv>
#include <cmath>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "gkt/gkt.h"

namespace gkt::c_api {

/// Records message as this thread's last error and returns status.
gkt_status fail(gkt_status status, const std::string& message) noexcept;

/// Sets what gkt_last_warnings returns on this thread: the lines joined by newlines ("" for none).
void set_last_warnings(const std::vector<std::string>& lines);

/// A refusal of the C layer itself: the status and a message naming the field.
struct Refusal {
  gkt_status status;
  std::string message;
};

/// Returns x in the shortest decimal that reads back as the same double (for messages).
inline std::string number(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return {buffer, result.ptr};
}

/// Throws Refusal{GKT_INVALID_ARGUMENT, "<field>: must not be NULL"}. Out of line and cold (as
/// refuse), so that a check on the valid path stays a compare and a branch, no message built in
/// the caller's frame (docs/performance.md "C API").
[[noreturn, gnu::cold, gnu::noinline]] void refuse_null(const char* field);

/// Throws Refusal{GKT_INVALID_ARGUMENT, "<field>: must be <range>, got <x>"}; out of line and cold.
[[noreturn, gnu::cold, gnu::noinline]] void refuse(const char* field, const char* range, double x);

/// Throws Refusal{GKT_INVALID_ARGUMENT, "<field>: must not be NULL"} if p is null.
inline void require_pointer(const void* p, const char* field) {
  if (p == nullptr) [[unlikely]]
    refuse_null(field);
}

/// Throws a Refusal "<field>: must be a finite number > 0, got <x>" unless x is finite and positive.
inline void require_positive(double x, const char* field) {
  if (!(x > 0 && std::isfinite(x))) [[unlikely]]
    refuse(field, "a finite number > 0", x);
}

/// Throws a Refusal "<field>: must be a number in (0, 1], got <x>" unless 0 < x ≤ 1.
inline void require_restitution(double x, const char* field) {
  if (!(x > 0 && x <= 1)) [[unlikely]]
    refuse(field, "a number in (0, 1]", x);
}

/// Returns the status of the exception being handled and records its message as this thread's
/// last error: Refusal as it says, std::invalid_argument and std::domain_error
/// GKT_INVALID_ARGUMENT, anything else GKT_INTERNAL_ERROR. Call only inside a catch block. Out of
/// line and cold: the translation costs nothing on the valid path.
[[gnu::cold, gnu::noinline]] gkt_status current_exception_status() noexcept;

/// Runs body() and returns its status; turns every exception into a status and a message
/// (current_exception_status). Outputs are written by body only once it cannot fail any more.
/// The catch is a single catch (...) so that the calling function's frame holds no handler of
/// its own (the per-cell overhead of docs/performance.md).
template <class Body>
gkt_status guarded(Body&& body) noexcept {
  try {
    return body();
  } catch (...) {
    return current_exception_status();
  }
}

}  // namespace gkt::c_api
