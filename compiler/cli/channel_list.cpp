#include "channel_list.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

#include <fmt/core.h>

namespace matc::cli {

std::vector<std::string> split_list(const std::string& list) {
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    items.push_back(list.substr(start, comma - start));
    start = comma + 1;
  }
  return items;
}

ChannelList parse_channel_list(const std::string& option, const std::string& text, double max) {
  const auto fail = [&](const std::string& problem) {
    return ChannelList{std::nullopt, fmt::format("{}: {}; give one value (grey) or three (R,G,B), "
                                                 "each in [0, {}], comma-separated",
                                                 option, problem, max)};
  };
  const std::vector<std::string> items = split_list(text);
  if (items.size() != 1 && items.size() != 3)
    return fail(fmt::format("{} values given", items.size()));
  std::array<double, 3> values{};
  for (std::size_t i = 0; i < items.size(); ++i) {
    const std::string& item = items[i];
    double value = 0.0;
    const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (item.empty() || error != std::errc() || end != item.data() + item.size())
      return fail(fmt::format("'{}' is not a number", item));
    if (!std::isfinite(value) || value < 0.0 || value > max)
      return fail(fmt::format("{} is outside [0, {}]", item, max));
    values[i] = value;
  }
  if (items.size() == 1) values = {values[0], values[0], values[0]};
  return {values, {}};
}

}  // namespace matc::cli
