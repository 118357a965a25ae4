// Prints the tables of docs/shaders.md: the SPIR-V cost of our Fresnel against Schlick's, both
// compiled the same way, and the accuracy and cost of the embedded table (--embed-lut) against
// the texture. Run through bench/update-shader-docs.sh; tests/scripts/check_docs_block.sh keeps the
// docs in sync.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "compile/compile.h"
#include "emit/build.h"
#include "lut/analytic_lut_fit.h"
#include "lut/comparison_lobes.h"
#include "matc/runtime/lut.h"
#include "material/parse.h"
#include "spirv/spirv_tools.h"

namespace {

using matc::ShaderLanguage;

// One kernel: reads a query (mu, NdotV, roughness) from a buffer and writes `expression`.
// Everything but the expression is the same for every row, so differences are the method's.
std::string kernel(ShaderLanguage language, const std::string& prelude,
                   const std::string& expression) {
  if (language == ShaderLanguage::glsl) {
    return fmt::format(
        "#version 450\n{}\n"
        "layout(local_size_x = 64) in;\n"
        "layout(std430, binding = 0) buffer Data {{ vec4 values[]; }};\n"
        "layout(binding = 1) uniform sampler2D lut;\n"
        "vec3 karis_split_sum(vec3 f0, float NdotV, float roughness) {{\n"
        "  vec4 r = roughness * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, "
        "-0.04);\n"
        "  float a004 = min(r.x * r.x, exp2(-9.28 * NdotV)) * r.x + r.y;\n"
        "  vec2 ab = vec2(-1.04, 1.04) * a004 + r.zw;\n"
        "  return f0 * ab.x + ab.y;\n"
        "}}\n"
        "vec3 evaluate(vec4 q) {{ return {}; }}\n"
        "void main() {{\n"
        "  uint i = gl_GlobalInvocationID.x;\n"
        "  values[i] = vec4(evaluate(values[i]), 1.0);\n"
        "}}\n",
        prelude, expression);
  }
  return fmt::format(
      "{}\n"
      "[[vk::binding(0)]] RWStructuredBuffer<float4> values;\n"
      "[[vk::binding(1)]] Texture2D<float4> lut_texture;\n"
      "[[vk::binding(2)]] SamplerState lut_sampler;\n"
      "float4 lut_texture_fetch(float2 uv) {{ return lut_texture.SampleLevel(lut_sampler, uv, 0); "
      "}}\n"
      "float3 karis_split_sum(float3 f0, float NdotV, float roughness) {{\n"
      "  float4 r = roughness * float4(-1.0, -0.0275, -0.572, 0.022) + float4(1.0, 0.0425, 1.04, "
      "-0.04);\n"
      "  float a004 = min(r.x * r.x, exp2(-9.28 * NdotV)) * r.x + r.y;\n"
      "  float2 ab = float2(-1.04, 1.04) * a004 + r.zw;\n"
      "  return f0 * ab.x + ab.y;\n"
      "}}\n"
      "float3 evaluate(float4 q) {{ return {}; }}\n"
      "[numthreads(64, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {{\n"
      "  values[id.x] = float4(evaluate(values[id.x]), 1.0);\n"
      "}}\n",
      prelude, expression);
}

std::size_t instructions(ShaderLanguage language, const std::string& prelude,
                         const std::string& expression) {
  const matc::SpirvWords words =
      matc::compile_to_spirv({language, kernel(language, prelude, expression), "cost"});
  return matc::count_function_instructions(
      matc::optimize_spirv(words, matc::SpirvTarget::vulkan_1_1, "cost"));
}

struct CostRow {
  const char* label;
  std::string glsl;  // expression in GLSL
  std::string hlsl;
  bool needs_matc;
};

void print_instruction_counts(const matc::Build& build, const matc::CompiledMaterial& gold) {
  const auto prelude = [&](ShaderLanguage language) {
    return build.library_source(language) + build.material_source(language, gold);
  };
  // Schlick in the common form (Filament's F_Schlick), with gold's F0 as constants like ours.
  const std::string f0_glsl =
      fmt::format("vec3({:.4f}, {:.4f}, {:.4f})", gold.f0[0], gold.f0[1], gold.f0[2]);
  const std::string f0_hlsl =
      fmt::format("float3({:.4f}, {:.4f}, {:.4f})", gold.f0[0], gold.f0[1], gold.f0[2]);
  const std::vector<CostRow> rows = {
      {"kernel alone (reads a query, writes it back)", "q.xyz", "q.xyz", false},
      {"F, Schlick", fmt::format("{0} + (vec3(1.0) - {0}) * pow(1.0 - q.x, 5.0)", f0_glsl),
       fmt::format("{0} + (1.0 - {0}) * pow(1.0 - q.x, 5.0)", f0_hlsl), false},
      {"F, ours (`matc_fresnel_gold`)", "matc_fresnel_gold(q.x)", "matc_fresnel_gold(q.x)", true},
      {"Fbar, Schlick split sum (one fetch)",
       fmt::format("{} * texture(lut, q.yz).x + texture(lut, q.yz).y", f0_glsl),
       fmt::format("{} * lut_texture_fetch(q.yz).x + lut_texture_fetch(q.yz).y", f0_hlsl), false},
      {"Fbar, ours (one fetch)",
       "matc_fresnel_preintegrated_gold(texture(lut, matc_lut_texcoord(q.y, q.z)))",
       "matc_fresnel_preintegrated_gold(lut_texture_fetch(matc_lut_texcoord(q.y, q.z)))", true},
      {"Fbar, ours, embedded table (`--embed-lut`, no fetch)",
       "matc_fresnel_preintegrated_gold(matc_preintegrated_basis_embedded(q.y, q.z))",
       "matc_fresnel_preintegrated_gold(matc_preintegrated_basis_embedded(q.y, q.z))", true},
      {"Fbar, Schlick split sum, Karis' closed form (no fetch)",
       fmt::format("karis_split_sum({}, q.y, q.z)", f0_glsl),
       fmt::format("karis_split_sum({}, q.y, q.z)", f0_hlsl), false},
      {"Fbar, ours, closed form (`matc_preintegrated_basis_analytic`, no fetch)",
       "matc_fresnel_preintegrated_gold(matc_preintegrated_basis_analytic(q.y, q.z))",
       "matc_fresnel_preintegrated_gold(matc_preintegrated_basis_analytic(q.y, q.z))", true},
  };
  fmt::print(
      "| kernel | GLSL | HLSL | GLSL, minus the kernel alone |\n"
      "|---|---:|---:|---:|\n");
  std::size_t scaffold = 0;
  for (const CostRow& row : rows) {
    const std::size_t glsl = instructions(
        ShaderLanguage::glsl, row.needs_matc ? prelude(ShaderLanguage::glsl) : "", row.glsl);
    const std::size_t hlsl = instructions(
        ShaderLanguage::hlsl, row.needs_matc ? prelude(ShaderLanguage::hlsl) : "", row.hlsl);
    if (scaffold == 0) scaffold = glsl;
    fmt::print("| {} | {} | {} | {} |\n", row.label, glsl, hlsl, glsl - scaffold);
  }
}

// Fbar from an embedded table of each size against the 128x128 texture, over the measured metals
// and a 65x65 grid of (NdotV, roughness).
void print_embedded_accuracy(const matc::LutOptions& texture_options) {
  const matc::runtime::BasisView basis = matc::runtime::shipped_basis();
  const matc::Lut texture = matc::preintegrate_lut(basis, texture_options);
  const std::vector<matc::runtime::Coefficients> metals = matc::measured_metal_coefficients(basis);
  fmt::print(
      "| embedded table | constants in the shader | max abs(Fbar - texture) | mean |\n"
      "|---|---:|---:|---:|\n");
  constexpr std::size_t kGrid = 65;
  for (const std::size_t size : {8u, 16u, 32u, 64u}) {
    const matc::Lut embedded = matc::preintegrate_lut(basis, {size, texture_options.samples, 0});
    double worst = 0.0;
    double sum = 0.0;
    std::size_t count = 0;
    for (const auto& coefficients : metals) {
      for (std::size_t y = 0; y < kGrid; ++y) {
        for (std::size_t x = 0; x < kGrid; ++x) {
          const double ndotv = static_cast<double>(x) / (kGrid - 1);
          const double roughness = static_cast<double>(y) / (kGrid - 1);
          const auto a =
              matc::runtime::evaluate_fbar(coefficients, embedded.view(), ndotv, roughness);
          const auto b =
              matc::runtime::evaluate_fbar(coefficients, texture.view(), ndotv, roughness);
          for (std::size_t c = 0; c < 3; ++c) {
            const double difference = std::abs(a[c] - b[c]);
            worst = std::max(worst, difference);
            sum += difference;
            ++count;
          }
        }
      }
    }
    fmt::print("| {0}x{0} | {1} floats | {2:.4f} | {3:.5f} |\n", size, size * size * 4, worst,
               sum / static_cast<double>(count));
  }
}

// Karis' analytic fit of Schlick's split sum ("Physically Based Shading on Mobile", 2014), as the
// kernel above and the 720p pass compute it: F0 * A + B.
double karis_split_sum(double f0, double ndotv, double roughness) {
  const double r_x = -roughness + 1.0;
  const double r_y = -0.0275 * roughness + 0.0425;
  const double r_z = -0.572 * roughness + 1.04;
  const double r_w = 0.022 * roughness - 0.04;
  const double a004 = std::min(r_x * r_x, std::exp2(-9.28 * ndotv)) * r_x + r_y;
  return f0 * (-1.04 * a004 + r_z) + (1.04 * a004 + r_w);
}

// Fbar without a fetch against Fbar from the 128x128 texture it replaces, over the measured
// metals and a 65x65 grid of (NdotV, roughness): our closed form for each basis, the embedded
// tables, and Karis' closed form of Schlick's split sum against Schlick's split-sum texture.
void print_closed_form_accuracy() {
  fmt::print(
      "| Fbar without a fetch | constants in the shader | max abs(Fbar - texture) | mean | max, "
      "NdotV >= 0.25 |\n"
      "|---|---:|---:|---:|---:|\n");
  for (const matc::runtime::BasisKind kind : matc::runtime::kShippedBases) {
    const matc::runtime::BasisView basis = matc::runtime::shipped_basis(kind);
    const matc::Lut texture = matc::preintegrate_lut(basis, matc::LutOptions{});
    const matc::AnalyticLutError error =
        matc::analytic_lut_error(matc::runtime::shipped_analytic_lut(kind), texture, basis);
    fmt::print(
        "| ours, closed form, {} basis | {} floats | {:.4f} | {:.5f} | {:.4f} |\n",
        matc::runtime::basis_name(kind),
        matc::runtime::analytic_lut_terms(matc::runtime::kAnalyticLutAlbedoDegree) +
            3 * matc::runtime::analytic_lut_terms(matc::runtime::kAnalyticLutQuadratureDegree),
        error.max, error.mean, error.max_away_from_grazing);
  }
  // Schlick's split sum from the ComparisonLobes bake: F0 x + (1 - F0) y.
  const matc::ComparisonLobes lobes(matc::runtime::shipped_basis().samples());
  const matc::Lut schlick = matc::preintegrate_lut(lobes.view(), matc::LutOptions{});
  double worst = 0.0;
  double worst_away_from_grazing = 0.0;
  double sum = 0.0;
  std::size_t count = 0;
  constexpr std::size_t kGrid = 65;
  for (const matc::runtime::Coefficients& coefficients :
       matc::measured_metal_coefficients(matc::runtime::shipped_basis())) {
    for (std::size_t y = 0; y < kGrid; ++y) {
      for (std::size_t x = 0; x < kGrid; ++x) {
        const double ndotv = static_cast<double>(x) / (kGrid - 1);
        const double roughness = static_cast<double>(y) / (kGrid - 1);
        const auto texel = matc::runtime::sample_lut(schlick.view(), ndotv, roughness);
        for (std::size_t c = 0; c < 3; ++c) {
          const double f0 = coefficients[c][0];
          const double texture = f0 * texel[0] + (1.0 - f0) * texel[1];
          const double difference = std::abs(karis_split_sum(f0, ndotv, roughness) - texture);
          worst = std::max(worst, difference);
          if (ndotv >= 0.25)
            worst_away_from_grazing = std::max(worst_away_from_grazing, difference);
          sum += difference;
          ++count;
        }
      }
    }
  }
  fmt::print("| Schlick's split sum, Karis' closed form | 8 floats | {:.4f} | {:.5f} | {:.4f} |\n",
             worst, sum / static_cast<double>(count), worst_away_from_grazing);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  matc::BuildOptions options;
  options.emit = {};
  options.lut = {16, 64, 0};  // the table's size does not change the code
  options.embedded_lut_size = 32;
  const matc::Build build(options);
  if (mode == "--closed-form") {
    print_closed_form_accuracy();
    return 0;
  }
  if (mode == "--embedded") {
    print_embedded_accuracy(matc::LutOptions{});
    return 0;
  }
  const matc::ParseResult parsed = matc::read_material_file(MATC_EXAMPLES_DIR "/gold.json");
  if (!parsed.material) return 1;
  print_instruction_counts(
      build, matc::compile_material(*parsed.material, matc::runtime::shipped_basis()));
  return 0;
}
