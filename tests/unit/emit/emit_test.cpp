// Shader emission: literals and templates, the generated GLSL/HLSL through glslang (both front
// ends), SPIR-V validation and optimisation, library linking, error reporting, determinism.
#include <algorithm>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "base/content_hash.h"
#include "base/json_format.h"
#include "base/shared_file_stems.h"
#include "compile/compile.h"
#include "emit/build.h"
#include "emit/library_module.h"
#include "emit/manifest_writer.h"
#include "emit/material_module_template.h"
#include "emit/output_layout.h"
#include "emit/shader_literals.h"
#include "emit/template.h"
#include "emit/validation_kernel.h"
#include "example_files.h"
#include "matc/version.h"
#include "material/parse.h"
#include "spirv/linkage.h"
#include "spirv/shader_compiler.h"
#include "spirv/spirv_tools.h"

namespace matc {
namespace {

std::vector<CompiledMaterial> example_materials() {
  std::vector<CompiledMaterial> compiled;
  for (const std::string& file : test::example_material_files()) {
    ParseResult parsed = read_material_file(file);
    if (!parsed.material) throw std::runtime_error("example does not parse: " + file);
    compiled.push_back(compile_material(*parsed.material, runtime::shipped_basis()));
  }
  return compiled;
}

const std::vector<CompiledMaterial>& examples() {
  static const std::vector<CompiledMaterial> compiled = example_materials();
  return compiled;
}

const CompiledMaterial& example(std::string_view name) {
  for (const CompiledMaterial& material : examples())
    if (material.material.name == name) return material;
  throw std::runtime_error("no example named " + std::string(name));
}

BuildOptions small_options() {
  BuildOptions options;
  options.lut = {16, 64, 0};
  return options;
}

const Build& small_build() {
  static const Build build(small_options());
  return build;
}

const Build& embedded_build() {
  static const Build build([] {
    BuildOptions options = small_options();
    options.embedded_lut_size = 8;
    return options;
  }());
  return build;
}

TEST(ShaderLiterals, FloatsReadBackExactlyInEveryLanguage) {
  EXPECT_EQ(float_literal(1.0), "1.0");
  EXPECT_EQ(float_literal(0.25), "0.25");
  EXPECT_EQ(float_literal(-0.0), "0.0");
  EXPECT_EQ(float_literal(1e-5), "1e-05");
  EXPECT_EQ(float_literal(0.1), "0.1");  // the float nearest 0.1, shortest form
  EXPECT_EQ(c_float_literal(2.0), "2.0f");
  EXPECT_EQ(std::stof(float_literal(0.123456789)), 0.123456789f);
  EXPECT_THROW(float_literal(1e300), std::logic_error);
  const std::vector<double> values = {1.0, -2.5};
  EXPECT_EQ(vector_literal(ShaderLanguage::glsl, values), "vec2(1.0, -2.5)");
  EXPECT_EQ(vector_literal(ShaderLanguage::hlsl, values), "float2(1.0, -2.5)");
  EXPECT_EQ(vector_literal(ShaderLanguage::wgsl, values), "vec2f(1.0, -2.5)");
  EXPECT_EQ(template_path(ShaderLanguage::wgsl, "material"), "wgsl/material.wgsl");
}

TEST(ShaderLiterals, FileNamesInCommentsCannotCloseTheComment) {
  EXPECT_EQ(comment_safe_file_name("dir/gold.json"), "gold.json");
  EXPECT_EQ(comment_safe_file_name("a*/b\nc.json"), "b_c.json");
  EXPECT_EQ(comment_safe_file_name("x *\n evil.json"), "x____evil.json");
}

TEST(Templates, EveryPlaceholderIsFilledAndEveryValueUsed) {
  EXPECT_EQ(fill_template_text("a {{x}} b {{y}}", {{"x", "1"}, {"y", "2"}}, "t"), "a 1 b 2");
  EXPECT_THROW(fill_template_text("a {{x}}", {}, "t"), std::logic_error);
  EXPECT_THROW(fill_template_text("a {{x}}", {{"x", "1"}, {"z", "2"}}, "t"), std::logic_error);
  EXPECT_THROW(fill_template_text("a {{x", {{"x", "1"}}, "t"), std::logic_error);
  EXPECT_THROW(fill_template("glsl/no-such-template", {}), std::logic_error);
}

TEST(ContentHash, DependsOnEveryPartAndItsBoundaries) {
  EXPECT_EQ(ContentHash().add("ab").hex(), ContentHash().add("ab").hex());
  EXPECT_NE(ContentHash().add("ab").add("c").hex(), ContentHash().add("a").add("bc").hex());
  EXPECT_EQ(ContentHash().hex().size(), 16u);
  EXPECT_NE(hash_of_bytes("x"), hash_of_bytes("y"));
}

// Every example material, both front ends: the complete compute module compiles, validates
// under Vulkan rules, and survives SPIRV-Tools' performance passes (validated again).
TEST(GeneratedShaders, EveryExampleCompilesFromGlslAndHlsl) {
  for (const Build* build : {&small_build(), &embedded_build()}) {
    for (const CompiledMaterial& compiled : examples()) {
      for (const ShaderLanguage language : {ShaderLanguage::glsl, ShaderLanguage::hlsl}) {
        SpirvWords module;
        ASSERT_NO_THROW(module = material_validation_module(*build, language, compiled))
            << compiled.material.name << " " << shader_language_name(language);
        EXPECT_GT(count_function_instructions(module), 10u);
      }
    }
  }
}

TEST(GeneratedShaders, LibraryModulesExportTheirFunctions) {
  const SpirvWords module = small_build().material_library_module(example("gold"));
  validate_spirv(module, SpirvTarget::universal_1_3, "gold.spv");
  const std::string text = disassemble_spirv(module);
  EXPECT_NE(text.find("OpCapability Linkage"), std::string::npos);
  EXPECT_NE(text.find("LinkageAttributes \"matc_fresnel_gold\" Export"), std::string::npos);
  EXPECT_NE(text.find("LinkageAttributes \"matc_fresnel_preintegrated_gold\" Export"),
            std::string::npos);
  EXPECT_EQ(text.find("OpEntryPoint"), std::string::npos);
  // Validation under Vulkan rules refuses a library: it is not a module to run on its own.
  EXPECT_THROW(validate_spirv(module, SpirvTarget::vulkan_1_1, "gold.spv"), std::runtime_error);
}

// What an engine does with gold.spv: declare the functions, link, run the result.
TEST(GeneratedShaders, MaterialLibraryLinksIntoAConsumerShader) {
  const std::string consumer_source = R"(#version 450
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Data { vec4 values[]; };
// Placeholder bodies, turned into imports below.
vec3 matc_fresnel_gold(float mu) { return vec3(0.0); }
vec3 matc_fresnel_preintegrated_gold(vec4 bbar) { return vec3(0.0); }
void main() {
  uint i = gl_GlobalInvocationID.x;
  values[i] = vec4(matc_fresnel_gold(values[i].x) + matc_fresnel_preintegrated_gold(values[i]), 1.0);
}
)";
  const SpirvWords consumer =
      import_functions(compile_to_spirv({ShaderLanguage::glsl, consumer_source, "consumer.comp"}),
                       material_library_exports("gold"));
  validate_spirv(consumer, SpirvTarget::universal_1_3, "consumer.comp");
  const std::vector<SpirvWords> modules = {consumer,
                                           small_build().material_library_module(example("gold"))};
  const SpirvWords linked = link_spirv(modules, "consumer+gold");
  EXPECT_NO_THROW(validate_spirv(linked, SpirvTarget::vulkan_1_1, "consumer+gold"));
  const SpirvWords optimized = optimize_spirv(linked, SpirvTarget::vulkan_1_1, "consumer+gold");
  EXPECT_EQ(disassemble_spirv(optimized).find("Linkage"), std::string::npos);
}

TEST(GeneratedShaders, SharedLibraryLinksWithCoefficientsFromABuffer) {
  const std::string consumer_source = R"(#version 450
layout(local_size_x = 64) in;
struct MatcFresnelCoefficients { vec4 red; vec4 green; vec4 blue; };
layout(std140, binding = 0) uniform Material { MatcFresnelCoefficients coefficients; };
layout(std430, binding = 1) buffer Data { vec4 values[]; };
vec3 matc_fresnel(MatcFresnelCoefficients c, float mu) { return vec3(0.0); }
void main() {
  uint i = gl_GlobalInvocationID.x;
  values[i] = vec4(matc_fresnel(coefficients, values[i].x), 1.0);
}
)";
  const std::vector<std::string> imports = {"matc_fresnel"};
  const SpirvWords consumer = import_functions(
      compile_to_spirv({ShaderLanguage::glsl, consumer_source, "consumer.comp"}), imports);
  const std::vector<OutputFile> shared = small_build().shared_outputs();
  const auto spv = std::find_if(shared.begin(), shared.end(),
                                [](const OutputFile& f) { return f.name == "matc_fresnel.spv"; });
  ASSERT_NE(spv, shared.end());
  SpirvWords library(spv->bytes.size() / 4);
  std::memcpy(library.data(), spv->bytes.data(), spv->bytes.size());
  const std::vector<SpirvWords> modules = {consumer, library};
  EXPECT_NO_THROW(
      validate_spirv(link_spirv(modules, "consumer+lib"), SpirvTarget::vulkan_1_1, "linked"));
}

TEST(GeneratedShaders, CompileErrorsShowTheOffendingLineNotTheWholeShader) {
  std::string source = "#version 450\nlayout(local_size_x = 1) in;\n";
  for (int i = 0; i < 40; ++i)
    source += "// filler line " + std::to_string(i) + "\n";
  source += "void main() { float x = undefined_name; }\n";
  try {
    compile_to_spirv({ShaderLanguage::glsl, source, "broken.comp"});
    FAIL() << "expected a compile error";
  } catch (const ShaderCompileError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("broken.comp"), std::string::npos) << message;
    EXPECT_NE(message.find(">    43 | void main() { float x = undefined_name; }"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("filler line 39"), std::string::npos) << "context above";
    EXPECT_EQ(message.find("filler line 10"), std::string::npos) << "not the whole shader";
  }
}

// The snippets refuse a shared library from another matc version, or none at all.
TEST(GeneratedShaders, VersionSkewAndMissingLibraryAreCompileErrorsThatSayWhy) {
  const CompiledMaterial& gold = example("gold");
  const std::string kernel_tail = "layout(local_size_x = 1) in;\nvoid main() {}\n";
  std::string library = small_build().library_source(ShaderLanguage::glsl);
  const std::string version_line = "#define MATC_VERSION ";
  const std::size_t at = library.find(version_line);
  ASSERT_NE(at, std::string::npos);
  library.insert(at + version_line.size(), "9");  // a different version number
  const std::string material = small_build().material_source(ShaderLanguage::glsl, gold);
  try {
    compile_to_spirv(
        {ShaderLanguage::glsl, "#version 450\n" + library + material + kernel_tail, "skew.comp"});
    FAIL() << "expected a version-skew error";
  } catch (const ShaderCompileError& error) {
    EXPECT_NE(std::string(error.what()).find("regenerate both with one matc"), std::string::npos)
        << error.what();
  }
  try {
    compile_to_spirv({ShaderLanguage::hlsl,
                      small_build().material_source(ShaderLanguage::hlsl, gold) +
                          "[numthreads(1,1,1)] void main() {}\n",
                      "alone.hlsl"});
    FAIL() << "expected a missing-library error";
  } catch (const ShaderCompileError& error) {
    // glslang reprints #error's tokens with spaces between them.
    EXPECT_NE(std::string(error.what()).find("include matc_fresnel . hlsl before gold . hlsl"),
              std::string::npos)
        << error.what();
  }
}

TEST(GeneratedShaders, IncludingEverythingTwiceIsHarmless) {
  const CompiledMaterial& gold = example("gold");
  for (const ShaderLanguage language : {ShaderLanguage::glsl, ShaderLanguage::hlsl}) {
    const std::string once =
        small_build().library_source(language) + small_build().material_source(language, gold);
    const bool glsl = language == ShaderLanguage::glsl;
    const std::string source = (glsl ? "#version 450\n" : "") + once + once +
                               (glsl ? "layout(local_size_x = 1) in;\nvoid main() {}\n"
                                     : "[numthreads(1,1,1)] void main() {}\n");
    EXPECT_NO_THROW(compile_to_spirv({language, source, "twice"}))
        << shader_language_name(language);
  }
}

TEST(GeneratedShaders, EveryGlobalNameCarriesTheMatcPrefix) {
  const std::regex declaration(
      R"(^(?:static const |const )?(?:vec[234]|float[234]?|int|struct|MatcFresnelCoefficients)\s+(\w+))");
  for (const ShaderLanguage language : {ShaderLanguage::glsl, ShaderLanguage::hlsl}) {
    const std::string source = embedded_build().library_source(language) +
                               embedded_build().material_source(language, example("gold"));
    std::size_t names = 0;
    std::size_t start = 0;
    while (start < source.size()) {
      const std::size_t end = std::min(source.find('\n', start), source.size());
      const std::string line = source.substr(start, end - start);
      std::smatch match;
      if (std::regex_search(line, match, declaration)) {
        ++names;
        const std::string name = match[1];
        EXPECT_TRUE(name.starts_with("matc_") || name.starts_with("Matc") ||
                    name.starts_with("MATC_"))
            << name;
      }
      start = end + 1;
    }
    EXPECT_GE(names, 8u);
  }
}

TEST(Build, OutputsAreIdenticalAcrossRuns) {
  const Build again(small_options());
  const CompiledMaterial& copper = example("copper");
  const MaterialOutputs first = small_build().material_outputs(copper);
  const MaterialOutputs second = again.material_outputs(copper);
  ASSERT_EQ(first.files.size(), 6u);
  for (std::size_t i = 0; i < first.files.size(); ++i) {
    EXPECT_EQ(first.files[i].name, second.files[i].name);
    EXPECT_EQ(first.files[i].bytes, second.files[i].bytes) << first.files[i].name;
  }
  const std::vector<OutputFile> shared = small_build().shared_outputs();
  const std::vector<OutputFile> shared_again = again.shared_outputs();
  ASSERT_EQ(shared.size(), 10u);
  for (std::size_t i = 0; i < shared.size(); ++i)
    EXPECT_EQ(shared[i].bytes, shared_again[i].bytes) << shared[i].name;
}

TEST(Build, EmitSelectsOutputsAndOptionsChangeTheHash) {
  BuildOptions options = small_options();
  options.emit = {OutputKind::hlsl};
  const Build hlsl_only(options);
  const MaterialOutputs outputs = hlsl_only.material_outputs(example("iron"));
  ASSERT_EQ(outputs.files.size(), 1u);
  EXPECT_EQ(outputs.files[0].name, "iron.hlsl");
  ASSERT_EQ(hlsl_only.shared_outputs().size(), 1u);
  EXPECT_EQ(hlsl_only.shared_outputs()[0].name, "matc_fresnel.hlsl");
  options.lut.samples = 128;
  EXPECT_NE(Build(options).inputs_hash(), hlsl_only.inputs_hash());
  EXPECT_NE(Build(options).material_inputs_hash(example("iron").material),
            hlsl_only.material_inputs_hash(example("iron").material));
}

// WGSL is written as text (Dawn runs it in tests/js/check-webgpu.mjs): every placeholder filled,
// the version asserted where WGSL allows no preprocessor, and no GLSL/HLSL spelling left over.
TEST(Build, WgslOutputsAreCompleteWgsl) {
  BuildOptions options = small_options();
  options.emit = {OutputKind::wgsl};
  options.embedded_lut_size = 4;
  const Build wgsl_only(options);
  const MaterialOutputs outputs = wgsl_only.material_outputs(example("gold"));
  ASSERT_EQ(outputs.files.size(), 1u);
  EXPECT_EQ(outputs.files[0].name, "gold.wgsl");
  const std::string& snippet = outputs.files[0].bytes;
  EXPECT_NE(snippet.find(fmt::format("const_assert MATC_VERSION == {};", kVersionNumber)),
            std::string::npos);
  EXPECT_NE(snippet.find("const matc_coefficients_gold = MatcFresnelCoefficients("),
            std::string::npos);
  const std::vector<OutputFile> shared = wgsl_only.shared_outputs();
  ASSERT_EQ(shared.size(), 1u);
  const std::string& library = shared[0].bytes;
  EXPECT_EQ(shared[0].name, "matc_fresnel.wgsl");
  EXPECT_NE(library.find("const MATC_EMBEDDED_LUT = array<vec4f, 16>("), std::string::npos);
  for (const std::string* text : {&snippet, &library}) {
    for (const char* leftover : {"{{", "#define", "#if", "vec3(", "float3(", "inout"})
      EXPECT_EQ(text->find(leftover), std::string::npos) << leftover;
  }
  EXPECT_THROW(compile_to_spirv({ShaderLanguage::wgsl, library, "matc_fresnel.wgsl"}),
               std::logic_error);
}

// Per-material SPIR-V is patched from a checked-in template (no glslang run per material): the
// templates are what today's compile gives (rerun `matc basis material-modules -o
// compiler/src/generated/material_module_templates.cpp`), and every example's patched module is the
// full compile's, byte for byte, or, where the optimiser merges a coefficient with an equal
// constant, a module that validates and exports the same two functions.
TEST(MaterialModuleTemplates, CheckedInTemplatesAreCurrent) {
  for (const MaterialModuleTemplate& entry : compile_material_module_templates()) {
    const std::span<const std::uint32_t> checked_in = checked_in_material_module_template(
        entry.basis, entry.fresnel_nonnegative, entry.per_material_build, entry.filmed);
    EXPECT_TRUE(
        std::equal(entry.words.begin(), entry.words.end(), checked_in.begin(), checked_in.end()))
        << runtime::basis_name(entry.basis) << (entry.fresnel_nonnegative ? ", no clamp" : "")
        << (entry.filmed ? ", filmed" : "");
  }
}

TEST(MaterialModuleTemplates, PatchedModulesMatchAFullCompile) {
  const Build build(BuildOptions{});
  std::size_t identical = 0;
  for (const CompiledMaterial& material : examples()) {
    const SpirvWords patched = build.material_library_module(material);
    const SpirvWords compiled = build.compile_material_library_module(material);
    if (patched == compiled) {
      ++identical;
      continue;
    }
    EXPECT_NO_THROW(validate_spirv(patched, SpirvTarget::universal_1_3, material.material.name));
    const std::string bytes(reinterpret_cast<const char*>(patched.data()),
                            patched.size() * sizeof(std::uint32_t));
    for (const std::string prefix : {"matc_fresnel_", "matc_fresnel_preintegrated_"}) {
      EXPECT_NE(bytes.find(prefix + material.material.name + std::string(1, '\0')),
                std::string::npos)
          << material.material.name;
    }
  }
  EXPECT_GE(identical, examples().size() / 2);
  // Placeholders must be found, once each.
  CompiledMaterial gold = example("gold");
  const std::span<const std::uint32_t> words =
      checked_in_material_module_template(runtime::kDefaultBasis, gold.fresnel_nonnegative, false);
  SpirvWords broken(words.begin(), words.end());
  EXPECT_THROW(patch_material_module(SpirvWords(broken.begin(), broken.begin() + 5), gold),
               std::logic_error);
}

// Whether a material's twelve coefficients are distinct floats: the compiler merges equal
// constants (an F82-tint curve's c_3 = 0 in f82, a grey metal's rows), which the patched template
// keeps apart, so only then are the bytes the same.
bool distinct_coefficients(const CompiledMaterial& material) {
  std::set<float> values;
  for (const auto& row : material.coefficients)
    for (const double value : row)
      values.insert(static_cast<float>(value));
  return values.size() == 12;
}

// A default build (a basis per material) patches each material's module from its basis' template
// of such a build: the same bytes as compiling its snippet, an f82 material among them (a measured
// metal pinned to f82: an F82-tint curve's c_3 is 0 there), the same functions otherwise.
TEST(MaterialModuleTemplates, PerMaterialBuildsPatchTheirBasisTemplate) {
  BuildOptions options;
  options.per_material_basis = true;
  const Build build(options);
  std::size_t f82 = 0;
  std::size_t bare = 0;
  std::size_t identical = 0;
  std::vector<Material> materials;
  for (const std::string& file : test::example_material_files()) {
    const ParseResult parsed = read_material_file(file);
    ASSERT_TRUE(parsed.material.has_value());
    materials.push_back(*parsed.material);
  }
  const ParseResult pinned = parse_material(
      R"({"name": "pinned_gold", "spectral": {"preset": "Au"}, "basis": "f82"})", "pinned.json");
  ASSERT_TRUE(pinned.material.has_value());
  materials.push_back(*pinned.material);
  for (const Material& parsed : materials) {
    const CompiledMaterial material = compile_material(parsed, build.basis_for(parsed));
    if (material.coat) continue;
    ++bare;
    const SpirvWords patched = build.material_library_module(material);
    const SpirvWords compiled = build.compile_material_library_module(material);
    if (material.basis == runtime::BasisKind::f82 && distinct_coefficients(material)) {
      ++f82;
      EXPECT_EQ(patched, compiled) << material.material.name;
    }
    if (patched == compiled) {
      ++identical;
      continue;
    }
    EXPECT_NO_THROW(validate_spirv(patched, SpirvTarget::universal_1_3, material.material.name));
  }
  EXPECT_GE(f82, 1u);
  EXPECT_GE(identical, bare / 2);
}

TEST(Build, EmbeddedTableIsOptionalAndBounded) {
  EXPECT_EQ(small_build().library_source(ShaderLanguage::glsl).find("MATC_EMBEDDED_LUT"),
            std::string::npos);
  EXPECT_NE(embedded_build().library_source(ShaderLanguage::glsl).find("MATC_EMBEDDED_LUT[64]"),
            std::string::npos);
  BuildOptions options = small_options();
  options.embedded_lut_size = kMaxEmbeddedLutSize + 1;
  EXPECT_THROW(Build{options}, std::invalid_argument);
}

TEST(Build, ManifestListsEveryFileWithItsHash) {
  const std::vector<OutputFile> shared = small_build().shared_outputs();
  const std::vector<MaterialOutputs> materials = {small_build().material_outputs(example("gold"))};
  const nlohmann::ordered_json manifest = manifest_json(small_build(), shared, materials);
  EXPECT_EQ(manifest["materials"][0]["name"], "gold");
  EXPECT_EQ(manifest["materials"][0]["files"].size(), 6u);
  EXPECT_EQ(manifest["materials"][0]["files"][0]["hash"],
            hash_of_bytes(materials[0].files[0].bytes));
  EXPECT_EQ(manifest["shared_files"].size(), shared.size());
  EXPECT_EQ(manifest["lut"]["size"], 16);
  // The text a batch streams from per-material formatted entries (in memory or spooled in a
  // directory) is format_json of the whole.
  const std::vector<MaterialOutputs> twice = {materials[0], materials[0]};
  const std::filesystem::path spool =
      std::filesystem::temp_directory_path() / "matc_manifest_writer_test";
  for (const std::filesystem::path& directory : {std::filesystem::path(), spool}) {
    ManifestWriter writer(directory);
    EXPECT_EQ(writer.text(small_build(), shared),
              format_json(manifest_json(small_build(), shared, {})));
    for (const MaterialOutputs& material : twice)
      writer.append(ManifestWriter::format_entry(material));
    EXPECT_EQ(writer.entry_count(), 2u);
    EXPECT_EQ(writer.text(small_build(), shared),
              format_json(manifest_json(small_build(), shared, twice)));
  }
  // The spooled entries leave nothing behind.
  EXPECT_TRUE(std::filesystem::is_empty(spool));
  std::filesystem::remove_all(spool);
}

}  // namespace
}  // namespace matc

// The files a build writes once, as the output layout names them, are the base list the glTF
// importer keeps material names off (base/shared_file_stems.h): one more shared file, one more
// stem there.
TEST(OutputLayout, SharedStemsAreTheBaseList) {
  std::vector<std::string> from_layout = matc::shared_file_stems();
  std::vector<std::string> base(matc::kSharedFileStems.begin(), matc::kSharedFileStems.end());
  std::sort(from_layout.begin(), from_layout.end());
  std::sort(base.begin(), base.end());
  EXPECT_EQ(from_layout, base);
}
