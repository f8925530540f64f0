// The per-thread caches of the exact arithmetic (FLINT, GMP), for programs that run gkt in threads.
#pragma once

namespace gkt {

/// Frees the exact-arithmetic caches (FLINT's fmpz and MPFR caches) of the calling thread; call it as
/// the last thing in a worker thread that used gkt, after its Rationals and models are destroyed (the
/// main thread's are freed at exit). Returns nothing.
void release_thread_arithmetic_caches();

}  // namespace gkt
