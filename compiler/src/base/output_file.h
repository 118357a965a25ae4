// One file a command writes: its name and its bytes, all generated before anything is written.
#pragma once

#include <string>

namespace matc {

struct OutputFile {
  std::string name;  // a plain file name inside the output directory
  std::string bytes;
};

}  // namespace matc
