#include "matc/api/spirv.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "base/echoed_text.h"
#include "spirv/linkage.h"
#include "spirv/shader_compiler.h"
#include "spirv/spirv_tools.h"

namespace matc::api {
namespace {

ShaderLanguage compiled_language(std::string_view name) {
  if (name == "glsl") return ShaderLanguage::glsl;
  if (name == "hlsl") return ShaderLanguage::hlsl;
  throw std::invalid_argument(
      fmt::format("language: '{}' is not one of glsl, hlsl (WGSL is not compiled to SPIR-V here)",
                  echoed(name)));
}

ShaderStage shader_stage(std::string_view name) {
  if (name == "compute") return ShaderStage::compute;
  if (name == "vertex") return ShaderStage::vertex;
  if (name == "fragment") return ShaderStage::fragment;
  throw std::invalid_argument(
      fmt::format("stage: '{}' is not one of compute, vertex, fragment", echoed(name)));
}

// Each line of a tool's message made printable: the lines quote the caller's shader text and the
// names in its modules.
std::string printable_lines(std::string_view text) {
  std::string out;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    if (start != 0) out += '\n';
    out += printable(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

// A module from the caller is validated before matc's own code edits or links it: words that are
// not SPIR-V are refused with the validator's messages rather than read.
void validate_input(const SpirvWords& module, std::string_view name) {
  if (const auto errors = spirv_validation_errors(module, SpirvTarget::universal_1_3))
    throw std::invalid_argument(
        fmt::format("{}: not valid SPIR-V:\n{}", name, printable_lines(*errors)));
}

template <typename Call>
auto with_printable_errors(const Call& call) {
  try {
    return call();
  } catch (const std::invalid_argument&) {
    throw;
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(printable_lines(error.what()));
  }
}

}  // namespace

SpirvWords compile_shader(std::string_view language, std::string_view source, std::string_view name,
                          std::string_view stage) {
  ShaderSource shader;
  shader.language = compiled_language(language);
  shader.stage = shader_stage(stage);
  shader.text = std::string(source);
  shader.name = std::string(name);
  return with_printable_errors([&] { return compile_to_spirv(shader); });
}

SpirvWords import_functions(const SpirvWords& module, std::span<const std::string> functions) {
  validate_input(module, "module");
  try {
    return matc::import_functions(module, functions);
  } catch (const std::logic_error& error) {
    throw std::invalid_argument(error.what());
  }
}

SpirvWords link_spirv(std::span<const SpirvWords> modules, std::string_view name) {
  for (std::size_t i = 0; i < modules.size(); ++i)
    validate_input(modules[i], fmt::format("{}: module {}", echoed(name), i));
  SpirvWords linked = with_printable_errors([&] { return matc::link_spirv(modules, name); });
  if (const auto errors = spirv_validation_errors(linked, SpirvTarget::vulkan_1_1))
    throw std::runtime_error(fmt::format("{}: the linked module is not valid for Vulkan 1.1:\n{}",
                                         echoed(name), printable_lines(*errors)));
  return linked;
}

}  // namespace matc::api
