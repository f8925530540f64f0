#include "gkt/algebra/thread_caches.hpp"

#include <flint/flint.h>

namespace gkt {

void release_thread_arithmetic_caches() { flint_cleanup(); }

}  // namespace gkt
