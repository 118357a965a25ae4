// The names of the files a compile writes, known before it runs (what `matc layout` prints, for
// build systems that declare outputs up front), and the same layout as the CMake function's and
// the Bazel rule's source (docs/scaling.md).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace matc::api {

struct LayoutOptions {
  std::vector<std::string> emit;  // --emit's names; empty: every output
  std::string lut_format;         // the tables' format; empty: ktx2
  bool no_shared = false;         // each material's own files only
  bool shared_only = false;       // the shared files only
};

// The shared files (unless no_shared), each material's files, then the manifest (a batch's, with
// JSON emitted), in the order `matc layout` prints them. A name that breaks matc's name rule
// throws std::invalid_argument ("'NAME': problem; the rule"), as does an option outside its names.
std::vector<std::string> output_file_names(std::span<const std::string> material_names,
                                           const LayoutOptions& options = {});

// The layout as source for "cmake" (cmake/MatcOutputLayout.cmake) or "bazel"
// (bazel/matc_layout.bzl); another name throws std::invalid_argument.
std::string output_layout_source(std::string_view build_system);

}  // namespace matc::api
