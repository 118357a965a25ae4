// The text a build writes for its materials, byte for byte what `matc` writes with the same
// options: the shared shader libraries matc_fresnel.{glsl,hlsl,wgsl}, each material's snippets
// <name>.{glsl,hlsl,wgsl} and <name>.json (docs/api.md). The GLSL is GLSL 4.50 and GLSL ES 3.00
// alike (WebGL2 takes it as it is: docs/web-engines.md).
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "matc/api/compiled_material.h"

namespace matc {
class TextOutputs;
}

namespace matc::api {

class TextOutputs {
 public:
  // The options of the materials it writes for (the compile's basis and colour options).
  explicit TextOutputs(const CompileOptions& options = {});

  // "glsl", "hlsl" or "wgsl"; another name throws std::invalid_argument.
  const std::string& library_source(std::string_view language) const;
  std::string material_source(std::string_view language, const CompiledMaterial& compiled) const;
  std::string material_json(const CompiledMaterial& compiled) const;
  // The build's basis option: "auto" (a basis per material, a table of a layer per basis) or the
  // basis every material is compiled against. The tables these texts read are of that basis.
  const std::string& basis() const { return basis_; }

 private:
  std::shared_ptr<const matc::TextOutputs> texts_;
  std::string basis_;
  std::string color_key_;
};

}  // namespace matc::api
