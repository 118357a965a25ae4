// Every file name a build can write, decided here once: the output kinds (--emit's names), the
// file each writes per material (<name>.glsl) and once per build (matc_fresnel.glsl, the tables
// with a .json beside each, matc_manifest.json). Build names its files from it, the CLI derives
// the names a material may not take from it, and `matc layout --generate cmake|bazel` writes it
// as the lists the CMake function and the Bazel rule declare (cmake/MatcOutputLayout.cmake,
// bazel/matc_layout.bzl; a test keeps them current).
#pragma once

#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "lut/lut_files.h"

namespace matc {

enum class OutputKind { glsl, hlsl, wgsl, spirv, header, json, lut, coefficient_table, ltc };

struct OutputKindLayout {
  OutputKind kind;
  std::string_view name;                // what --emit accepts
  std::string_view material_extension;  // <name><extension> per material; empty: none
  std::string_view shared_stem;         // its file written once per build; empty: none
  // The shared file's extension; empty for a table, which takes the table format's (--lut) and
  // has a .json manifest beside it.
  std::string_view shared_extension;
};

// Every kind, in the order files are written (and listed in manifests).
std::span<const OutputKindLayout> output_layout();
const OutputKindLayout& layout_of(OutputKind kind);

// "glsl", "hlsl", "wgsl", "spirv", "header", "json", "lut", "coefficient-table", "ltc" (options
// read them through options/option_names.h).
std::string_view output_kind_name(OutputKind kind);
std::set<OutputKind> all_output_kinds();

// "matc_manifest.json": what a batch (not a per-material run) writes when json is emitted.
std::string_view manifest_file_name();

// A material's file of this kind ("gold.glsl"); the kind must have a per-material file.
std::string material_file_name(OutputKind kind, std::string_view material_name);
// Every file a material writes for these kinds, in order.
std::vector<std::string> material_file_names(const std::set<OutputKind>& emit,
                                             std::string_view material_name);
// The one shared file of a kind ("matc_fresnel.spv", "matc_ltc.ktx2"); the kind must have one.
std::string shared_file_name(OutputKind kind, LutFormat table_format);
// Every shared file for these kinds, tables' manifests included, in order (not the batch
// manifest).
std::vector<std::string> shared_file_names(const std::set<OutputKind>& emit,
                                           LutFormat table_format);

// The stem of every shared file a build can write, whatever --emit and --lut say: matc_fresnel,
// matc_lut, matc_coefficient_table, matc_ltc and matc_manifest. A material of one of these names
// (in any case) would write its files over them.
std::vector<std::string> shared_file_stems();

// The layout as CMake (variables) and Starlark (dictionaries) source.
std::string output_layout_cmake_source();
std::string output_layout_bazel_source();

}  // namespace matc
