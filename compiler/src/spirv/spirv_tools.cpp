#include "spirv/spirv_tools.h"

#include <stdexcept>

#include <fmt/format.h>
#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

#include "spirv_instructions.h"

namespace matc {
namespace {

spv_target_env environment(SpirvTarget target) {
  return target == SpirvTarget::vulkan_1_1 ? SPV_ENV_VULKAN_1_1 : SPV_ENV_UNIVERSAL_1_3;
}

// Collects SPIRV-Tools' messages for an exception.
class MessageCollector {
 public:
  spvtools::MessageConsumer consumer() {
    return [this](spv_message_level_t, const char*, const spv_position_t& position,
                  const char* message) {
      text_.append(fmt::format("  word {}: {}\n", position.index, message));
    };
  }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

}  // namespace

std::optional<std::string> spirv_validation_errors(const SpirvWords& words, SpirvTarget target) {
  spvtools::SpirvTools tools(environment(target));
  MessageCollector messages;
  tools.SetMessageConsumer(messages.consumer());
  if (tools.Validate(words)) return std::nullopt;
  return messages.text();
}

void validate_spirv(const SpirvWords& words, SpirvTarget target, std::string_view name) {
  if (const auto errors = spirv_validation_errors(words, target))
    throw std::runtime_error(fmt::format("{}: invalid SPIR-V (a bug in matc):\n{}", name, *errors));
}

SpirvWords optimize_spirv(const SpirvWords& words, SpirvTarget target, std::string_view name) {
  spvtools::Optimizer optimizer(environment(target));
  MessageCollector messages;
  optimizer.SetMessageConsumer(messages.consumer());
  optimizer.RegisterPerformancePasses();
  SpirvWords optimized;
  if (!optimizer.Run(words.data(), words.size(), &optimized)) {
    throw std::runtime_error(
        fmt::format("{}: SPIR-V optimisation failed (a bug in matc):\n{}", name, messages.text()));
  }
  validate_spirv(optimized, target, name);
  return optimized;
}

std::string disassemble_spirv(const SpirvWords& words) {
  spvtools::SpirvTools tools(SPV_ENV_UNIVERSAL_1_3);
  std::string text;
  if (!tools.Disassemble(words, &text, SPV_BINARY_TO_TEXT_OPTION_FRIENDLY_NAMES))
    throw std::runtime_error("SPIR-V disassembly failed");
  return text;
}

std::size_t count_function_instructions(const SpirvWords& words) {
  std::size_t count = 0;
  bool inside = false;
  for (const SpirvInstruction& instruction : spirv_instructions(words)) {
    if (instruction.opcode == spv::OpFunction) {
      inside = true;
    } else if (instruction.opcode == spv::OpFunctionEnd) {
      inside = false;
    } else if (inside && instruction.opcode != spv::OpFunctionParameter) {
      ++count;
    }
  }
  return count;
}

}  // namespace matc
