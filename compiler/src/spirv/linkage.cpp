#include "spirv/linkage.h"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

#include <fmt/format.h>
#include <spirv-tools/linker.hpp>

#include "base/echoed_text.h"
#include "spirv_instructions.h"

namespace matc {
namespace {

using Instruction = std::vector<std::uint32_t>;

struct EditableModule {
  std::vector<std::uint32_t> header;
  std::vector<Instruction> instructions;

  explicit EditableModule(const SpirvWords& words) : header(words.begin(), words.begin() + 5) {
    for (const SpirvInstruction& instruction : spirv_instructions(words))
      instructions.emplace_back(instruction.words.begin(), instruction.words.end());
  }

  SpirvWords words() const {
    SpirvWords out = header;
    for (const Instruction& instruction : instructions)
      out.insert(out.end(), instruction.begin(), instruction.end());
    return out;
  }
};

spv::Op opcode_of(const Instruction& instruction) {
  return static_cast<spv::Op>(instruction[0] & spv::OpCodeMask);
}

// Function ids by source name: glslang names functions "name(mangled-parameters;".
std::map<std::string, std::uint32_t> function_ids(const EditableModule& module) {
  std::set<std::uint32_t> functions;
  for (const Instruction& instruction : module.instructions)
    if (opcode_of(instruction) == spv::OpFunction) functions.insert(instruction[2]);
  std::map<std::string, std::uint32_t> ids;
  for (const Instruction& instruction : module.instructions) {
    if (opcode_of(instruction) != spv::OpName || !functions.contains(instruction[1])) continue;
    const std::string name = spirv_string(std::span(instruction).subspan(2));
    ids.emplace(name.substr(0, name.find('(')), instruction[1]);
  }
  return ids;
}

std::vector<std::uint32_t> ids_of(const EditableModule& module,
                                  std::span<const std::string> functions) {
  const auto ids = function_ids(module);
  std::vector<std::uint32_t> out;
  for (const std::string& function : functions) {
    const auto found = ids.find(function);
    if (found == ids.end())
      throw std::logic_error(fmt::format("SPIR-V module has no function '{}'", echoed(function)));
    out.push_back(found->second);
  }
  return out;
}

void add_linkage_capability(EditableModule& module) {
  const auto last_capability =
      std::find_if(module.instructions.rbegin(), module.instructions.rend(),
                   [](const Instruction& i) { return opcode_of(i) == spv::OpCapability; });
  const std::uint32_t capability = spv::CapabilityLinkage;
  module.instructions.insert(last_capability.base(),
                             spirv_instruction(spv::OpCapability, std::span(&capability, 1)));
}

// Annotations follow the debug section (the module layout rules of SPIR-V 2.4).
void add_linkage_decorations(EditableModule& module, std::span<const std::string> names,
                             std::span<const std::uint32_t> ids, spv::LinkageType type) {
  static const std::set<spv::Op> kBeforeAnnotations = {
      spv::OpCapability, spv::OpExtension,       spv::OpExtInstImport,   spv::OpMemoryModel,
      spv::OpEntryPoint, spv::OpExecutionMode,   spv::OpExecutionModeId, spv::OpString,
      spv::OpSource,     spv::OpSourceExtension, spv::OpSourceContinued, spv::OpName,
      spv::OpMemberName, spv::OpModuleProcessed};
  const auto position =
      std::find_if(module.instructions.begin(), module.instructions.end(),
                   [](const Instruction& i) { return !kBeforeAnnotations.contains(opcode_of(i)); });
  std::vector<Instruction> decorations;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    std::vector<std::uint32_t> operands = {ids[i], spv::DecorationLinkageAttributes};
    const auto name = spirv_string_words(names[i]);
    operands.insert(operands.end(), name.begin(), name.end());
    operands.push_back(static_cast<std::uint32_t>(type));
    decorations.push_back(spirv_instruction(spv::OpDecorate, operands));
  }
  module.instructions.insert(position, decorations.begin(), decorations.end());
}

// Removes the function whose OpFunction defines `id`, from OpFunction to OpFunctionEnd.
void remove_function(EditableModule& module, std::uint32_t id) {
  auto& all = module.instructions;
  const auto first = std::find_if(all.begin(), all.end(), [&](const Instruction& i) {
    return opcode_of(i) == spv::OpFunction && i[2] == id;
  });
  const auto end = std::find_if(
      first, all.end(), [](const Instruction& i) { return opcode_of(i) == spv::OpFunctionEnd; });
  all.erase(first, end == all.end() ? end : end + 1);
}

}  // namespace

SpirvWords export_functions(const SpirvWords& words, std::span<const std::string> functions) {
  EditableModule module(words);
  const std::vector<std::uint32_t> ids = ids_of(module, functions);
  std::set<std::uint32_t> entry_points;
  for (const Instruction& instruction : module.instructions)
    if (opcode_of(instruction) == spv::OpEntryPoint) entry_points.insert(instruction[2]);
  std::erase_if(module.instructions, [&](const Instruction& i) {
    const spv::Op op = opcode_of(i);
    const bool targets_entry = i.size() > 1 && entry_points.contains(i[1]);
    return op == spv::OpEntryPoint ||
           ((op == spv::OpExecutionMode || op == spv::OpExecutionModeId || op == spv::OpName ||
             op == spv::OpDecorate) &&
            targets_entry);
  });
  for (const std::uint32_t entry : entry_points)
    remove_function(module, entry);
  add_linkage_capability(module);
  add_linkage_decorations(module, functions, ids, spv::LinkageTypeExport);
  return module.words();
}

SpirvWords import_functions(const SpirvWords& words, std::span<const std::string> functions) {
  EditableModule module(words);
  const std::vector<std::uint32_t> ids = ids_of(module, functions);
  // Declarations (no body) must precede every definition: collect them, then put them first.
  std::vector<Instruction> declarations;
  for (const std::uint32_t id : ids) {
    auto& all = module.instructions;
    const auto first = std::find_if(all.begin(), all.end(), [&](const Instruction& i) {
      return opcode_of(i) == spv::OpFunction && i[2] == id;
    });
    for (auto it = first; it != all.end(); ++it) {
      const spv::Op op = opcode_of(*it);
      if (op == spv::OpFunction || op == spv::OpFunctionParameter || op == spv::OpFunctionEnd)
        declarations.push_back(*it);
      if (op == spv::OpFunctionEnd) break;
    }
    remove_function(module, id);
  }
  const auto first_function =
      std::find_if(module.instructions.begin(), module.instructions.end(),
                   [](const Instruction& i) { return opcode_of(i) == spv::OpFunction; });
  module.instructions.insert(first_function, declarations.begin(), declarations.end());
  add_linkage_capability(module);
  add_linkage_decorations(module, functions, ids, spv::LinkageTypeImport);
  return module.words();
}

SpirvWords link_spirv(std::span<const SpirvWords> modules, std::string_view name) {
  spvtools::Context context(SPV_ENV_UNIVERSAL_1_3);
  std::string messages;
  context.SetMessageConsumer(
      [&](spv_message_level_t, const char*, const spv_position_t&, const char* message) {
        messages.append(fmt::format("  {}\n", message));
      });
  std::vector<std::vector<std::uint32_t>> binaries(modules.begin(), modules.end());
  SpirvWords linked;
  if (spvtools::Link(context, binaries, &linked) != SPV_SUCCESS)
    throw std::runtime_error(fmt::format("{}: SPIR-V linking failed:\n{}", name, messages));
  return linked;
}

}  // namespace matc
