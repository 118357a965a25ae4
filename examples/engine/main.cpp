// What an engine's asset pipeline does with matc: materials compiled by the build
// (matc_add_materials), their C headers included, the SPIR-V library module linked into the
// engine's own shader, a material compiled from memory with libmatc, and a textured metal's
// coefficients from the coefficient table at run time, and a textured metal's maps baked by the
// build (matc_add_baked_textures) into coefficient textures. Exits non-zero if any check fails.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <span>
#include <string>
#include <vector>

#include "figure2_edge_tint.h"  // generated at build time by matc_add_materials
#include "gold.h"

#include "matc/api/spirv.h"
#include "matc/matc.h"
#include "matc/runtime/coefficient_table.h"
#include "matc/runtime/fresnel.h"
#include "matc/runtime/ltc.h"
#include "matc/runtime/lut.h"

namespace {

int failures = 0;

void expect(bool condition, const std::string& what) {
  std::printf("%s %s\n", condition ? "ok  " : "FAIL", what.c_str());
  if (!condition) ++failures;
}

matc::runtime::Coefficients from_header(const MatcFresnelCoefficients& c) {
  matc::runtime::Coefficients out{};
  const float* rows[3] = {c.red, c.green, c.blue};
  for (int channel = 0; channel < 3; ++channel)
    for (int i = 0; i < 4; ++i)
      out[channel][i] = rows[channel][i];
  return out;
}

// BEGIN api-example
// Compiling a material held in memory with the public API (matc/matc.h): nothing is read from or
// written to disk.
std::optional<matc::api::CompiledMaterial> compile_in_memory(const std::string& json) {
  try {
    // The path only names the material in diagnostics (and resolves relative spectral files).
    const std::vector<matc::api::Material> materials =
        matc::api::parse_materials(json, "memory/brushed_brass.json");
    return matc::api::compile(materials.at(0));
  } catch (const matc::api::MaterialError& error) {
    std::fprintf(stderr, "%s\n", error.what());  // the lines `matc` prints, one per problem
    return std::nullopt;
  }
}

void emit_in_memory(const matc::api::CompiledMaterial& material) {
  const matc::api::TextOutputs texts;  // what `matc` writes by default, byte for byte
  for (const char* language : {"glsl", "hlsl", "wgsl"}) {
    std::printf("     %s.%s: %zu bytes\n", material.name().c_str(), language,
                texts.material_source(language, material).size());
  }
  std::printf("     %s.json: %zu bytes\n", material.name().c_str(),
              texts.material_json(material).size());
}
// END api-example

// A KTX2 file with one RGBA16F 2D texture (what matc bake writes by default): level `level`.
std::string file_bytes(const char* path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
std::uint32_t ktx2_level_count(const char* path) {
  const std::string bytes = file_bytes(path);
  std::uint32_t levels = 0;
  if (bytes.size() >= 44) std::memcpy(&levels, bytes.data() + 40, 4);
  return levels;
}
float half_to_float(std::uint16_t h) {
  const int exponent = (h >> 10) & 0x1F, mantissa = h & 0x3FF;
  const float magnitude = exponent == 0
                              ? std::ldexp(static_cast<float>(mantissa), -24)
                              : std::ldexp(static_cast<float>(mantissa | 0x400), exponent - 25);
  return (h & 0x8000) ? -magnitude : magnitude;
}
// Level `level` of a KTX2 file's RGBA texture, half (matc bake's default) or 32-bit float (the
// tables matc writes): the level index holds each level's offset and length.
std::vector<float> ktx2_level(const char* path, std::uint32_t level, bool half = true) {
  const std::string bytes = file_bytes(path);
  std::uint64_t offset = 0, length = 0;
  const std::size_t index = 80 + 24 * static_cast<std::size_t>(level);
  if (bytes.size() < index + 16) return {};
  std::memcpy(&offset, bytes.data() + index, 8);
  std::memcpy(&length, bytes.data() + index + 8, 8);
  if (offset + length > bytes.size()) return {};
  std::vector<float> texels(length / (half ? 2 : 4));
  for (std::size_t i = 0; i < texels.size(); ++i) {
    if (!half) {
      std::memcpy(&texels[i], bytes.data() + offset + 4 * i, 4);
      continue;
    }
    std::uint16_t h = 0;
    std::memcpy(&h, bytes.data() + offset + 2 * i, 2);
    texels[i] = half_to_float(h);
  }
  return texels;
}

}  // namespace

int main() {
  // 1. The headers hold the coefficients the shaders use; F through the runtime matches the
  //    header's F0 comment's claim that F(1) = F0.
  const auto gold = from_header(matc_coefficients_gold);
  const auto f_normal =
      matc::runtime::evaluate_fresnel(gold, matc::runtime::shipped_shader_basis(), 1.0);
  expect(f_normal[0] > 0.9 && f_normal[2] < 0.5, "gold.h: F(0 degrees) is gold's (reddish-yellow)");
  const auto tint = from_header(matc_coefficients_figure2_edge_tint);
  const auto f_grazing =
      matc::runtime::evaluate_fresnel(tint, matc::runtime::shipped_shader_basis(), 0.05);
  expect(f_grazing[1] > f_grazing[0], "figure2_edge_tint.h: green edge tint near grazing");
  expect(std::string(MATC_gold_LUT_FILE) == "matc_lut.ktx2", "gold.h names the table it needs");

  // 2. The engine's shader calls matc_fresnel_gold; the material's SPIR-V library (from the
  //    header) supplies it at link time.
  const std::string shader = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { vec4 values[]; };
vec3 matc_fresnel_gold(float mu) { return vec3(0.0); }  // placeholder, becomes an import
void main() {
  uint i = gl_GlobalInvocationID.x;
  values[i] = vec4(matc_fresnel_gold(values[i].x), 1.0);
}
)";
  const std::vector<std::string> imports = {"matc_fresnel_gold"};
  const matc::api::SpirvWords engine = matc::api::import_functions(
      matc::api::compile_shader("glsl", shader, "engine.comp"), imports);
  const matc::api::SpirvWords library(std::begin(matc_spirv_gold), std::end(matc_spirv_gold));
  const std::vector<matc::api::SpirvWords> modules = {engine, library};
  bool linked = false;
  try {
    matc::api::link_spirv(modules, "engine+gold");  // validated as a Vulkan 1.1 module
    linked = true;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s\n", error.what());
  }
  expect(linked, "engine shader + gold.spv link into a valid Vulkan module");

  // 3. libmatc from memory.
  const auto brass = compile_in_memory(
      R"({"name": "brushed_brass", "artistic": {"reflectivity": [0.91, 0.78, 0.42],
          "edge_tint": [0.95, 0.93, 0.88]}, "roughness": 0.35})");
  expect(brass.has_value(), "a material compiles from an in-memory JSON string");
  if (brass) emit_in_memory(*brass);
  const auto broken = compile_in_memory(R"({"name": "x", "artistic": {"reflectivity": 2}})");
  expect(!broken.has_value(), "a bad in-memory material gives diagnostics, not a crash");

  // 4. A textured metal: a texel's coefficients from its base colour (reflectivity) and edge tint
  //    through the coefficient table, as MATC_COEFFICIENTS_FROM_TABLE computes them in a shader,
  //    give the F that compiling that texel's material gives.
  if (brass) {
    const matc::runtime::Coefficients texel = matc::runtime::coefficients_from_table(
        matc::runtime::shipped_coefficient_table(), {0.91, 0.78, 0.42}, {0.95, 0.93, 0.88});
    double worst = 0.0;
    for (int i = 0; i <= 100; ++i) {
      const auto& basis = matc::runtime::shipped_shader_basis();
      const auto table_f = matc::runtime::evaluate_fresnel(texel, basis, i / 100.0);
      const auto compiled_f =
          matc::runtime::evaluate_fresnel(brass->coefficients(), basis, i / 100.0);
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(table_f[c] - compiled_f[c]));
    }
    expect(worst < 0.002, "a textured texel's F from the coefficient table matches its compile");
  }

  // 5. Baked coefficient textures: the 1 x 1 top of the C2 mip chain is the mean of level 0, as
  //    an engine's trilinear sampler at full minification would see it (docs/baking.md).
  {
    const std::vector<float> level0 = ktx2_level(MATC_BAKED_C2, 0);
    const std::vector<float> top = ktx2_level(MATC_BAKED_C2, ktx2_level_count(MATC_BAKED_C2) - 1);
    double mean = 0.0;
    for (std::size_t t = 0; t < level0.size() / 4; ++t)
      mean += level0[4 * t] / static_cast<double>(level0.size() / 4);
    expect(level0.size() == 512 * 512 * 4 && top.size() == 4,
           "the baked C2 texture has a full mip chain (512 x 512 down to 1 x 1)");
    // Each f16 level is rounded on its own: the mean of rounded texels and the rounded mean
    // differ by about half an f16 step.
    expect(!top.empty() && std::abs(top[0] - mean) < 1e-3,
           "its 1 x 1 mip holds the mean coefficient of level 0 (the average curve)");
  }

  // 6. An area light: the preintegrated table and the LTC table as the build wrote them (RGBA32F
  //    KTX2), and gold's radiance under a quad light as matc_ltc_quad_light computes it in a
  //    shader (docs/ltc.md). Vertices in the shading frame: normal +z, the view in the xz-plane.
  {
    const std::vector<float> lut_texels = ktx2_level(MATC_LUT_KTX2, 0, /*half=*/false);
    const std::vector<float> ltc_texels = ktx2_level(MATC_LTC_KTX2, 0, /*half=*/false);
    const auto lut_size = static_cast<std::size_t>(std::lround(std::sqrt(lut_texels.size() / 4)));
    const auto ltc_size = static_cast<std::size_t>(std::lround(std::sqrt(ltc_texels.size() / 4)));
    const matc::runtime::LutView lut{lut_size, lut_texels};
    const matc::runtime::LtcTableView ltc{ltc_size, ltc_texels};
    expect(ltc_size == matc::runtime::shipped_ltc_table().size &&
               std::equal(ltc_texels.begin(), ltc_texels.end(),
                          matc::runtime::shipped_ltc_table().texels.begin()),
           "matc_ltc.ktx2 holds the runtime's LTC table");
    const std::array<matc::runtime::Vec3, 4> quad = {
        {{-1.0, -1.0, 2.0}, {1.0, -1.0, 2.0}, {1.0, 1.0, 2.0}, {-1.0, 1.0, 2.0}}};
    const matc::runtime::Rgb radiance =
        matc::runtime::polygon_light_ltc(gold, lut, ltc, 0.8, 0.3, quad);
    expect(radiance[0] > radiance[2] && radiance[2] > 0.0 && radiance[0] < 1.0,
           "gold under a quad light: reddish-yellow, between 0 and the light's radiance");
  }

  std::printf("%s\n",
              failures == 0 ? "engine example: all checks passed" : "engine example: FAILED");
  return failures == 0 ? 0 : 1;
}
