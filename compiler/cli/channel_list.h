// Parsing a per-channel option such as `--reflectivity 0.9,0.6,0.3`: one value (grey) or three
// (R, G, B), each a number in [0, 1].
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace matc::cli {

// "a,b,c" -> {"a", "b", "c"}: every comma-separated option (--emit, --reflectivity, ...).
std::vector<std::string> split_list(const std::string& list);

struct ChannelList {
  std::optional<std::array<double, 3>> values;
  std::string error;  // when values is empty: "OPTION: problem; what to give"
};

// The three values (one given is a grey triple), or what is wrong with the text.
// Each value must lie in [0, max].
ChannelList parse_channel_list(const std::string& option, const std::string& text,
                               double max = 1.0);

}  // namespace matc::cli
