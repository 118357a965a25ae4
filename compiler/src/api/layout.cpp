#include "matc/api/layout.h"

#include <set>
#include <stdexcept>

#include <fmt/format.h>

#include "checked_options.h"
#include "emit/output_layout.h"
#include "material/parse.h"

namespace matc::api {

std::vector<std::string> output_file_names(std::span<const std::string> material_names,
                                           const LayoutOptions& options) {
  for (const std::string& name : material_names) {
    if (const auto problem = material_name_problem(name)) {
      throw std::invalid_argument(
          fmt::format("'{}': {}; {}", echoed(name), *problem, kMaterialNameRule));
    }
  }
  std::set<OutputKind> emit;
  for (const std::string& name : options.emit)
    emit.insert(checked_option_value<OutputKind>("emit", name));
  if (emit.empty()) emit = all_output_kinds();
  const LutFormat format = option_from_name("lut_format", options.lut_format, LutFormat::ktx2);
  std::vector<std::string> files;
  if (!options.no_shared) files = shared_file_names(emit, format);
  for (const std::string& name : material_names)
    for (std::string& file : material_file_names(emit, name))
      files.push_back(std::move(file));
  // As the compile: only a batch writes the manifest.
  if (!options.no_shared && !options.shared_only && emit.contains(OutputKind::json))
    files.emplace_back(manifest_file_name());
  return files;
}

std::string output_layout_source(std::string_view build_system) {
  if (build_system == "cmake") return output_layout_cmake_source();
  if (build_system == "bazel") return output_layout_bazel_source();
  throw std::invalid_argument(
      fmt::format("build_system: '{}' is not one of cmake, bazel", echoed(build_system)));
}

}  // namespace matc::api
