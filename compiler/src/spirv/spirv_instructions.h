// Walking and editing a SPIR-V binary one instruction at a time (what linkage.cpp needs).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <spirv/unified1/spirv.hpp>

#include "spirv/shader_compiler.h"

namespace matc {

inline constexpr std::size_t kSpirvHeaderWords = 5;

struct SpirvInstruction {
  spv::Op opcode = spv::OpNop;
  std::span<const std::uint32_t> words;  // including the first (word count | opcode) word
};

// The instructions after the header. Throws std::runtime_error on a malformed stream.
std::vector<SpirvInstruction> spirv_instructions(const SpirvWords& module);

// A literal string operand starting at words[0].
std::string spirv_string(std::span<const std::uint32_t> words);
// `text` as a literal string operand (nul-terminated, padded to whole words).
std::vector<std::uint32_t> spirv_string_words(const std::string& text);

// One instruction from its opcode and operands.
std::vector<std::uint32_t> spirv_instruction(spv::Op opcode,
                                             std::span<const std::uint32_t> operands);

}  // namespace matc
