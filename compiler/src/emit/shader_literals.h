// Numbers and identifiers as generated shader and header text spells them.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "spirv/shader_language.h"

namespace matc {

std::string shader_file_extension(ShaderLanguage language);  // ".glsl", ".hlsl", ".wgsl"

// The templates/ file of a language: "<language>/<stem>.<language>" (e.g. wgsl/material.wgsl).
std::string template_path(ShaderLanguage language, std::string_view stem);

// `value` rounded to float, in the shortest form that reads back to the same float, always with a
// decimal point or exponent ("1.0", "0.25", "1e-05"): a GLSL, HLSL, WGSL and C float literal.
std::string float_literal(double value);
// ... with C's `f` suffix.
std::string c_float_literal(double value);
// Comma-separated float literals.
std::string float_list(std::span<const double> values, bool c_suffix = false);

// A vector constructor such as vec3(...) / float3(...) / vec3f(...) of the given size.
std::string vector_literal(ShaderLanguage language, std::span<const double> values);

// A file name safe inside a comment of any generated language: characters outside
// [A-Za-z0-9._-] become '_'.
std::string comment_safe_file_name(std::string_view path);

}  // namespace matc
