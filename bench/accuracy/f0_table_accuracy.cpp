// A glTF metal's base colour texture under an edge colour or a clear coat, followed per pixel
// through its F0 table (compile/f0_table.h; docs/gltf.md): over all 256 levels of an 8-bit sRGB
// texture, the largest |F from the table - F compiled at the pixel's own F0|, beside the largest
// error of those compiles against the exact curve. Prints the table docs/gltf.md holds
// (ctest f0_table_docs_current).
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "bake/image_map.h"  // srgb_to_linear: how the bake decodes an 8-bit sRGB map
#include "compile/f0_table.h"
#include "matc/runtime/shipped_bases.h"

namespace {

struct Case {
  std::string what;
  matc::Rgb tint;
  std::optional<matc::CoatInput> coat;
};

}  // namespace

int main() {
  std::vector<double> levels;
  for (int level = 0; level < 256; ++level)
    levels.push_back(matc::srgb_to_linear(level / 255.0));
  const std::vector<Case> cases = {
      {"edge colour (0.6, 0.8, 1.0), bare", {0.6, 0.8, 1.0}, std::nullopt},
      {"edge colour (0.9, 0.95, 1.0), bare", {0.9, 0.95, 1.0}, std::nullopt},
      {"Schlick under a coat of 1.3", {1, 1, 1}, matc::CoatInput{1.0, 1.3, 0.0, {1, 1, 1}}},
      {"Schlick under a coat of 1.5 (glTF's default)",
       {1, 1, 1},
       matc::CoatInput{1.0, 1.5, 0.0, {1, 1, 1}}},
      {"Schlick under a coat of 1.6", {1, 1, 1}, matc::CoatInput{1.0, 1.6, 0.0, {1, 1, 1}}},
      {"edge colour (0.7, 0.9, 1.0) under a coat of 1.5",
       {0.7, 0.9, 1.0},
       matc::CoatInput{1.0, 1.5, 0.0, {1, 1, 1}}},
      {"Schlick under half a coat of 1.5", {1, 1, 1}, matc::CoatInput{0.5, 1.5, 0.0, {1, 1, 1}}},
  };
  const matc::runtime::BasisView& basis =
      matc::runtime::shipped_basis(matc::runtime::kDefaultBasis);
  fmt::print(
      "| textured metal ({} basis) | max \\|F table - F compiled\\| | max \\|F compiled - exact\\| "
      "|\n",
      matc::runtime::basis_name(basis.kind));
  fmt::print("|---|---:|---:|\n");
  for (const Case& entry : cases) {
    matc::Material material;
    material.name = "textured";
    material.model = matc::F82TintInput{{0.5, 0.5, 0.5}, entry.tint};
    material.coat = entry.coat;
    const matc::F0TableError error = matc::measure_f0_table(material, basis, {}, levels);
    fmt::print("| {} | {:.1e} | {:.4f} |\n", entry.what, error.table, error.fit);
  }
  return 0;
}
