// Whether the tests are built with AddressSanitizer (GKT_SANITIZE=ON, the second pass of tools/run_tests.sh
// and of CI), and the guard the slow tests use there. ASan and UBSan slow the numerics some 10–30 times: a
// test of a few seconds in Release takes minutes there. Such a test is skipped under the sanitizer (it still
// runs in every Release pass); the code paths it drives are exercised under ASan by the faster tests of the
// same file, at smaller orders or sizes.
#pragma once

#include <gtest/gtest.h>

namespace gkt_test {

#if defined(__SANITIZE_ADDRESS__)  // GCC
inline constexpr bool kUnderSanitizer = true;
#elif defined(__has_feature)  // clang
#if __has_feature(address_sanitizer)
inline constexpr bool kUnderSanitizer = true;
#else
inline constexpr bool kUnderSanitizer = false;
#endif
#else
inline constexpr bool kUnderSanitizer = false;
#endif

}  // namespace gkt_test

/// Skips the current test under AddressSanitizer, saying its Release cost (`release_cost`, e.g. "5 s").
#define GKT_SKIP_UNDER_SANITIZER(release_cost)                                                            \
  do {                                                                                                    \
    if (gkt_test::kUnderSanitizer)                                                                        \
      GTEST_SKIP() << "slow under ASan/UBSan (" << (release_cost) << " in Release): run in Release only"; \
  } while (false)
