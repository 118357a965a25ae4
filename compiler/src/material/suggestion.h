// "Did you mean ...?" for misspelt field names and presets.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace matc {

// The candidate closest to `word` by case-insensitive edit distance, if it is close enough to be
// a plausible typo (at most 2 edits, and fewer than the word's length).
std::optional<std::string_view> closest_match(std::string_view word,
                                              std::span<const std::string_view> candidates);

// "a, b, c"
std::string join(std::span<const std::string_view> words);

}  // namespace matc
