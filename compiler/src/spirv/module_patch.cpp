#include "spirv/module_patch.h"

#include <bit>
#include <cstdint>
#include <set>
#include <stdexcept>

#include <fmt/format.h>

#include "spirv_instructions.h"

namespace matc {
namespace {

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at)) {
    text.replace(at, from.size(), to);
    at += to.size();
  }
  return text;
}

}  // namespace

SpirvWords patch_module(const SpirvWords& module, const ModulePatch& patch) {
  std::set<std::uint32_t> float_types;
  for (const SpirvInstruction& instruction : spirv_instructions(module)) {
    if (instruction.opcode == spv::OpTypeFloat && instruction.words[2] == 32)
      float_types.insert(instruction.words[1]);
  }
  std::vector<int> replacements(patch.constants.size(), 0);
  SpirvWords out(module.begin(), module.begin() + kSpirvHeaderWords);
  for (const SpirvInstruction& instruction : spirv_instructions(module)) {
    std::vector<std::uint32_t> words(instruction.words.begin(), instruction.words.end());
    const bool named = instruction.opcode == spv::OpName;
    const bool linkage = instruction.opcode == spv::OpDecorate &&
                         words[2] == static_cast<std::uint32_t>(spv::DecorationLinkageAttributes);
    if (named || linkage) {
      // OpName id "name"; OpDecorate id LinkageAttributes "name" Export|Import.
      const std::size_t first = named ? 2 : 3;
      const std::string text = spirv_string(std::span(words).subspan(first));
      const std::vector<std::uint32_t> string_words =
          spirv_string_words(replaced(text, patch.from_name, patch.to_name));
      std::vector<std::uint32_t> operands(words.begin() + 1, words.begin() + first);
      operands.insert(operands.end(), string_words.begin(), string_words.end());
      if (linkage) operands.push_back(words.back());  // the linkage type follows the string
      words = spirv_instruction(instruction.opcode, operands);
    } else if (instruction.opcode == spv::OpConstant && float_types.contains(words[1])) {
      for (std::size_t i = 0; i < patch.constants.size(); ++i) {
        if (words[3] != std::bit_cast<std::uint32_t>(patch.constants[i].first)) continue;
        words[3] = std::bit_cast<std::uint32_t>(patch.constants[i].second);
        ++replacements[i];
        break;
      }
    }
    out.insert(out.end(), words.begin(), words.end());
  }
  for (std::size_t i = 0; i < replacements.size(); ++i) {
    if (replacements[i] != 1) {
      throw std::logic_error(fmt::format("placeholder constant {} occurs {} times in the module",
                                         patch.constants[i].first, replacements[i]));
    }
  }
  return out;
}

}  // namespace matc
