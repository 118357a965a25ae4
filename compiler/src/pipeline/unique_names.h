// Material names name output files, and file systems may ignore case: within one run, names must
// differ by more than case. Shared by the batch compile and `matc report`.
#pragma once

#include <map>
#include <string>
#include <string_view>

#include "base/diagnostics.h"
#include "material/material.h"

namespace matc {

class UniqueNames {
 public:
  // Records `material`'s name, or, when an earlier material has it (ignoring case), adds an error
  // at the name pointing to the first one and returns false. `scope` says what the names must be
  // unique within ("a build", "a report").
  bool claim(const Material& material, std::string_view scope, Diagnostics& diagnostics);
  // The same for any named thing (a bake asset) given in `path` at `location`.
  bool claim(const std::string& name, const std::string& path, const SourceLocation& location,
             std::string_view scope, Diagnostics& diagnostics);

 private:
  struct FirstUse {    // kept small: a batch of 100,000 materials holds one per material
    std::string name;  // as given: generated identifiers keep its case
    std::string path;
    std::size_t line = 0;
    std::size_t column = 0;
  };
  std::map<std::string, FirstUse> first_use_;  // lowercase name -> its first use
};

}  // namespace matc
