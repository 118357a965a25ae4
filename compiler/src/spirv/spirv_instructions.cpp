#include "spirv_instructions.h"

#include <stdexcept>

namespace matc {

std::vector<SpirvInstruction> spirv_instructions(const SpirvWords& module) {
  if (module.size() < kSpirvHeaderWords || module[0] != spv::MagicNumber)
    throw std::runtime_error("not a SPIR-V module");
  std::vector<SpirvInstruction> instructions;
  std::size_t offset = kSpirvHeaderWords;
  while (offset < module.size()) {
    const std::uint32_t count = module[offset] >> spv::WordCountShift;
    if (count == 0 || offset + count > module.size())
      throw std::runtime_error("truncated SPIR-V instruction");
    instructions.push_back({static_cast<spv::Op>(module[offset] & spv::OpCodeMask),
                            std::span<const std::uint32_t>(module).subspan(offset, count)});
    offset += count;
  }
  return instructions;
}

std::string spirv_string(std::span<const std::uint32_t> words) {
  std::string text;
  for (const std::uint32_t word : words) {
    for (int byte = 0; byte < 4; ++byte) {
      const auto c = static_cast<char>((word >> (8 * byte)) & 0xffu);
      if (c == '\0') return text;
      text.push_back(c);
    }
  }
  return text;
}

std::vector<std::uint32_t> spirv_string_words(const std::string& text) {
  std::vector<std::uint32_t> words(text.size() / 4 + 1, 0u);
  for (std::size_t i = 0; i < text.size(); ++i)
    words[i / 4] |= static_cast<std::uint32_t>(static_cast<unsigned char>(text[i]))
                    << (8 * (i % 4));
  return words;
}

std::vector<std::uint32_t> spirv_instruction(spv::Op opcode,
                                             std::span<const std::uint32_t> operands) {
  std::vector<std::uint32_t> words;
  words.push_back(static_cast<std::uint32_t>(operands.size() + 1) << spv::WordCountShift |
                  static_cast<std::uint32_t>(opcode));
  words.insert(words.end(), operands.begin(), operands.end());
  return words;
}

}  // namespace matc
