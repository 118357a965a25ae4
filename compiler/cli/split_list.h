// Comma-separated option values (--emit's kinds): "a,b,c" -> {"a", "b", "c"}.
#pragma once

#include <string>
#include <vector>

namespace matc::cli {

std::vector<std::string> split_list(const std::string& list);

}  // namespace matc::cli
