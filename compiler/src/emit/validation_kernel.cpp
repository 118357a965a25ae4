#include "emit/validation_kernel.h"

#include <fmt/format.h>

#include "emit/material_snippet.h"
#include "emit/template.h"
#include "matc/version.h"
#include "spirv/spirv_tools.h"

namespace matc {
namespace {

SpirvWords vulkan_compute_module(ShaderLanguage language, std::string source,
                                 const std::string& source_name) {
  const SpirvWords words = compile_to_spirv({language, std::move(source), source_name});
  validate_spirv(words, SpirvTarget::vulkan_1_1, source_name);
  return optimize_spirv(words, SpirvTarget::vulkan_1_1, source_name);
}

}  // namespace

MaterialKernel material_kernel_of(const CompiledMaterial& compiled) {
  if (compiled.coat)
    return compiled.film_table ? MaterialKernel::film_coated : MaterialKernel::coated;
  if (compiled.film_stack) return MaterialKernel::film_stack;
  return compiled.film_table ? MaterialKernel::filmed : MaterialKernel::bare;
}

std::string validation_kernel_source(ShaderLanguage language, std::string_view library,
                                     std::string_view material, std::string_view material_name,
                                     MaterialKernel kind, std::string_view basis_suffix) {
  const bool glsl = language == ShaderLanguage::glsl;
  TemplateValues values = {{"version", kVersion},
                           {"name", std::string(material_name)},
                           {"library", std::string(library)},
                           {"material", std::string(material)}};
  if (kind == MaterialKernel::bare) {
    values["suffix"] = std::string(basis_suffix);
    return fill_template(glsl ? "glsl/validate.comp" : "hlsl/validate.hlsl", values);
  }
  std::string quad;
  for (const runtime::Vec3& corner : kLayeredValidationQuad)
    quad += (quad.empty() ? "" : ", ") + vector_literal(language, corner);
  values["quad"] = quad;
  // A filmed metal's kernel samples its own table, not the preintegrated one; with a thickness
  // per pixel, at the query's thickness coordinate (w).
  if (kind == MaterialKernel::filmed || kind == MaterialKernel::film_stack) {
    const std::string slices = fmt::format("matc_film_slices_{}", material_name);
    const bool stack = kind == MaterialKernel::film_stack;
    if (glsl) {
      const std::string table = "sampler2D(matc_film, matc_lut_sampler)";
      values["film_direct"] =
          stack ? fmt::format("MATC_FILM_STACK_FRESNEL({}, query.x, query.w, {})", table, slices)
                : fmt::format("MATC_FILM_FRESNEL({}, query.x)", table);
      values["film_image"] =
          stack ? fmt::format(
                      "MATC_FILM_STACK_PREINTEGRATED({}, "
                      "matc_film_stack_preintegrated_texcoords(query.y, query.z, query.w, "
                      "{}))",
                      table, slices)
                : fmt::format("MATC_FILM_PREINTEGRATED({}, query.y, query.z)", table);
    } else {
      values["film_direct"] =
          stack ? fmt::format(
                      "matc_film_stack_fresnel(matc_film, matc_lut_sampler, query.x, "
                      "query.w, {})",
                      slices)
                : "matc_film_fresnel(matc_film, matc_lut_sampler, query.x)";
      values["film_image"] =
          stack ? fmt::format(
                      "matc_film_stack_preintegrated(matc_film, matc_lut_sampler, "
                      "query.y, query.z, query.w, {})",
                      slices)
                : "matc_film_preintegrated(matc_film, matc_lut_sampler, query.y, query.z)";
    }
    return fill_template(glsl ? "glsl/validate_film.comp" : "hlsl/validate_film.hlsl", values);
  }
  if (kind == MaterialKernel::film_coated) {
    return fill_template(glsl ? "glsl/validate_film_coated.comp" : "hlsl/validate_film_coated.hlsl",
                         values);
  }
  return fill_template(glsl ? "glsl/validate_coated.comp" : "hlsl/validate_coated.hlsl", values);
}

std::string table_validation_kernel_source(ShaderLanguage language, std::string_view library) {
  return fill_template(
      language == ShaderLanguage::glsl ? "glsl/validate_table.comp" : "hlsl/validate_table.hlsl",
      {{"version", kVersion}, {"library", std::string(library)}});
}

std::string area_light_validation_kernel_source(ShaderLanguage language, std::string_view library) {
  return fill_template(language == ShaderLanguage::glsl ? "glsl/validate_area_lights.comp"
                                                        : "hlsl/validate_area_lights.hlsl",
                       {{"version", kVersion}, {"library", std::string(library)}});
}

SpirvWords material_validation_module(const Build& build, ShaderLanguage language,
                                      const CompiledMaterial& compiled) {
  const std::string& name = compiled.material.name;
  return vulkan_compute_module(
      language,
      validation_kernel_source(language, build.library_source(language),
                               build.material_source(language, compiled), name,
                               material_kernel_of(compiled),
                               basis_function_suffix(compiled, build.options().per_material_basis)),
      fmt::format("{}.validate{}", name, shader_file_extension(language)));
}

SpirvWords table_validation_module(const Build& build, ShaderLanguage language) {
  return vulkan_compute_module(
      language, table_validation_kernel_source(language, build.library_source(language)),
      fmt::format("matc_coefficient_table.validate{}", shader_file_extension(language)));
}

SpirvWords area_light_validation_module(const Build& build, ShaderLanguage language) {
  return vulkan_compute_module(
      language, area_light_validation_kernel_source(language, build.library_source(language)),
      fmt::format("matc_area_lights.validate{}", shader_file_extension(language)));
}

}  // namespace matc
