#include "matc/emit/c_header.h"

#include <fmt/format.h>

#include "matc/emit/material_snippet.h"

namespace matc {

std::string material_c_header(const CompiledMaterial& compiled, std::string_view inputs_hash,
                              const LutReference& lut, const SpirvWords& library_module) {
  TemplateValues values = material_template_values(compiled, inputs_hash);
  values.erase("red");
  values.erase("green");
  values.erase("blue");
  values.erase("version_number");
  std::string words;
  for (std::size_t i = 0; i < library_module.size(); ++i) {
    words.append(i % 8 == 0 ? "    " : " ");
    words.append(fmt::format("0x{:08x}u,", library_module[i]));
    if (i % 8 == 7 && i + 1 < library_module.size()) words.append("\n");
  }
  values.insert({{"lut_file", lut.file},
                 {"lut_size", std::to_string(lut.size)},
                 {"lut_hash", lut.hash},
                 {"basis", lut.basis},
                 {"spirv_word_count", std::to_string(library_module.size())},
                 {"spirv_words", words}});
  return fill_template("c/material.h", values);
}

}  // namespace matc
