// Whether this test binary is built with AddressSanitizer (scripts/test-sanitized.sh), where code
// runs some 40 times slower. Tests whose size serves numerical coverage rather than memory safety
// check a sample there; the plain run checks everything.
#pragma once

namespace matc::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitizedBuild = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif
#else
inline constexpr bool kSanitizedBuild = false;
#endif

}  // namespace matc::test
