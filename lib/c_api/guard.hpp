// Private to the C API: the barrier no C++ exception crosses, the thread-local last error, and the
// checks shared by its functions (each refusal a one-line message naming the field and its range).
#pragma once

#include <charconv>
#include <cmath>
#include <new>
#include <stdexcept>
#include <string>

#include "gkt/gkt.h"

namespace gkt::c_api {

/// Records message as this thread's last error and returns status.
gkt_status fail(gkt_status status, const std::string& message) noexcept;

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

/// Throws Refusal{GKT_INVALID_ARGUMENT, "<field>: must not be NULL"} if p is null.
inline void require_pointer(const void* p, const char* field) {
  if (p == nullptr) throw Refusal{GKT_INVALID_ARGUMENT, std::string(field) + ": must not be NULL"};
}

/// Throws a Refusal "<field>: must be a number > 0, got <x>" unless x is finite and positive.
inline void require_positive(double x, const char* field) {
  if (!(x > 0 && std::isfinite(x)))
    throw Refusal{GKT_INVALID_ARGUMENT, std::string(field) + ": must be a finite number > 0, got " + number(x)};
}

/// Throws a Refusal "alpha: must be a number in (0, 1], got <x>" unless 0 < x ≤ 1.
inline void require_restitution(double x, const char* field) {
  if (!(x > 0 && x <= 1))
    throw Refusal{GKT_INVALID_ARGUMENT, std::string(field) + ": must be a number in (0, 1], got " + number(x)};
}

/// Runs body() and returns its status; turns every exception into a status and a message:
/// Refusal as it says, std::invalid_argument and std::domain_error GKT_INVALID_ARGUMENT, anything
/// else GKT_INTERNAL_ERROR. Outputs are written by body only once it cannot fail any more.
template <class Body>
gkt_status guarded(Body&& body) noexcept {
  try {
    return body();
  } catch (const Refusal& r) {
    return fail(r.status, r.message);
  } catch (const std::invalid_argument& e) {
    return fail(GKT_INVALID_ARGUMENT, e.what());
  } catch (const std::domain_error& e) {
    return fail(GKT_INVALID_ARGUMENT, e.what());
  } catch (const std::bad_alloc&) {
    return fail(GKT_INTERNAL_ERROR, "out of memory");
  } catch (const std::exception& e) {
    return fail(GKT_INTERNAL_ERROR, std::string("internal error: ") + e.what());
  } catch (...) {
    return fail(GKT_INTERNAL_ERROR, "internal error: unknown exception");
  }
}

}  // namespace gkt::c_api
