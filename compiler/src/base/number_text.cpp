#include "base/number_text.h"

#include <charconv>
#include <cmath>
#if !defined(__cpp_lib_to_chars)
// The WebAssembly build's libc++ (LLVM 14) has no floating-point std::from_chars.
#include <fast_float/fast_float.h>
#endif

namespace matc {

std::optional<double> parse_number(std::string_view text) {
  if (text.empty()) return std::nullopt;
  if (text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
#if defined(__cpp_lib_to_chars)
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
#else
  // Correctly rounded as std::from_chars; it gives infinity for a number past the largest double
  // where std::from_chars fails, and the check below refuses both alike.
  const auto [end, error] = fast_float::from_chars(text.data(), text.data() + text.size(), value);
#endif
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

}  // namespace matc
