#include "spirv/shader_compiler.h"

#include <algorithm>
#include <charconv>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

namespace matc {
namespace {

// glslang keeps its built-in symbol tables in process-wide state: set up once (a function-local
// static, so the first caller initialises and the others wait), never torn down. After that,
// compiles on different threads are independent (each TShader has its own pool allocator), which
// is what `matc -j` relies on; see docs/scaling.md.
void initialize_glslang_once() {
  static const bool initialized = glslang::InitializeProcess();
  if (!initialized) throw std::runtime_error("glslang failed to initialise");
}

std::vector<std::string_view> split_lines(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) {
      if (start < text.size()) lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

// The line number in "ERROR: 0:12: 'x' : ..." (or "WARNING: ..."), 0 when there is none.
std::size_t line_of_log_entry(std::string_view entry) {
  std::size_t colon = entry.find(": ");
  if (colon == std::string_view::npos) return 0;
  std::string_view rest = entry.substr(colon + 2);
  colon = rest.find(':');
  if (colon == std::string_view::npos) return 0;
  rest = rest.substr(colon + 1);
  std::size_t line = 0;
  const auto [end, error] = std::from_chars(rest.data(), rest.data() + rest.size(), line);
  return error == std::errc{} && end != rest.data() ? line : 0;
}

}  // namespace

std::string describe_compile_errors(std::string_view log, std::string_view source,
                                    std::string_view name) {
  const std::vector<std::string_view> lines = split_lines(source);
  std::string out = fmt::format("generated shader {} does not compile (a bug in matc):\n", name);
  for (const std::string_view entry : split_lines(log)) {
    if (!entry.starts_with("ERROR:")) continue;
    out.append(fmt::format("  {}\n", entry));
    const std::size_t line = line_of_log_entry(entry);
    if (line == 0 || line > lines.size()) continue;
    const std::size_t first = line > 2 ? line - 2 : 1;
    const std::size_t last = std::min(lines.size(), line + 2);
    for (std::size_t n = first; n <= last; ++n)
      out.append(fmt::format("  {} {:5} | {}\n", n == line ? '>' : ' ', n, lines[n - 1]));
  }
  return out;
}

namespace {

EShLanguage glslang_stage(ShaderStage stage) {
  switch (stage) {
    case ShaderStage::vertex:
      return EShLangVertex;
    case ShaderStage::fragment:
      return EShLangFragment;
    case ShaderStage::compute:
      break;
  }
  return EShLangCompute;
}

}  // namespace

SpirvWords compile_to_spirv(const ShaderSource& source) {
  if (source.language == ShaderLanguage::wgsl)
    throw std::logic_error("glslang compiles GLSL and HLSL, not WGSL");
  initialize_glslang_once();

  const bool hlsl = source.language == ShaderLanguage::hlsl;
  const EShLanguage stage = glslang_stage(source.stage);
  glslang::TShader shader(stage);
  const char* text = source.text.c_str();
  const int length = static_cast<int>(source.text.size());
  const char* name = source.name.c_str();
  shader.setStringsWithLengthsAndNames(&text, &length, &name, 1);
  shader.setEntryPoint(source.entry_point.c_str());
  shader.setSourceEntryPoint(source.entry_point.c_str());
  shader.setEnvInput(hlsl ? glslang::EShSourceHlsl : glslang::EShSourceGlsl, stage,
                     glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
  // SPIR-V 1.3 for both front ends: glslang 12's HLSL output uses BufferBlock, invalid in 1.4+.
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
  if (hlsl) shader.setHlslIoMapping(true);

  int flags = EShMsgSpvRules | EShMsgVulkanRules;
  if (hlsl) flags |= EShMsgReadHlsl;
  if (source.keep_uncalled_functions) flags |= EShMsgKeepUncalled;
  const auto messages = static_cast<EShMessages>(flags);
  if (!shader.parse(GetDefaultResources(), 100, false, messages)) {
    throw ShaderCompileError(describe_compile_errors(
        std::string(shader.getInfoLog()) + shader.getInfoDebugLog(), source.text, source.name));
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    throw ShaderCompileError(describe_compile_errors(
        std::string(program.getInfoLog()) + program.getInfoDebugLog(), source.text, source.name));
  }
  SpirvWords words;
  spv::SpvBuildLogger logger;
  glslang::SpvOptions options;
  // glslang's own legalisation: HLSL needs it (resources in function scope); later passes are ours.
  options.disableOptimizer = !hlsl;
  glslang::GlslangToSpv(*program.getIntermediate(stage), words, &logger, &options);
  if (const std::string messages_text = logger.getAllMessages();
      messages_text.find("error") != std::string::npos) {
    throw ShaderCompileError(fmt::format("generated shader {}: SPIR-V generation failed: {}",
                                         source.name, messages_text));
  }
  return words;
}

}  // namespace matc
