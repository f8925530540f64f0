// The C API's status names, version and thread-local last error (include/gkt/gkt.h).
#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "gkt/gkt.h"
#include "guard.hpp"

namespace gkt::c_api {

namespace {
thread_local std::string last_error;     // the message of this thread's last failing call
thread_local std::string last_warnings;  // the caveats of this thread's last gkt_model_evaluate*
}  // namespace

gkt_status fail(gkt_status status, const std::string& message) noexcept {
  try {
    last_error = message;
  } catch (...) {
    last_error.clear();  // no memory for the message: the status still says what happened
  }
  return status;
}

void set_last_warnings(const std::vector<std::string>& lines) {
  std::string joined;
  for (const auto& line : lines) joined += (joined.empty() ? "" : "\n") + line;
  last_warnings = std::move(joined);
}

void refuse_null(const char* field) { throw Refusal{GKT_INVALID_ARGUMENT, std::string(field) + ": must not be NULL"}; }

void refuse(const char* field, const char* range, double x) {
  throw Refusal{GKT_INVALID_ARGUMENT, std::string(field) + ": must be " + range + ", got " + number(x)};
}

gkt_status current_exception_status() noexcept {
  try {
    throw;
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

extern "C" {

const char* gkt_last_error(void) { return gkt::c_api::last_error.c_str(); }

const char* gkt_last_warnings(void) { return gkt::c_api::last_warnings.c_str(); }

const char* gkt_status_name(gkt_status status) {
  switch (status) {
    case GKT_OK:
      return "GKT_OK";
    case GKT_INVALID_ARGUMENT:
      return "GKT_INVALID_ARGUMENT";
    case GKT_OUT_OF_RANGE:
      return "GKT_OUT_OF_RANGE";
    case GKT_INTERNAL_ERROR:
      return "GKT_INTERNAL_ERROR";
  }
  return "unknown";
}

const char* gkt_version(void) { return GKT_VERSION; }

}  // extern "C"
