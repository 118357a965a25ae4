// The public face (matc/matc.h): what it reads, compiles and writes is what the modules and the
// CLI's Build make, byte for byte; bad input is a MaterialError with the CLI's lines.
#include "matc/matc.h"

#include "matc/api/batch.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "emit/build.h"
#include "matc/runtime/shader_basis.h"
#include "material/material_input.h"

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> example_materials() {
  std::vector<fs::path> paths;
  for (const auto& entry : fs::directory_iterator(MATC_EXAMPLES_DIR))
    if (entry.path().extension() == ".json") paths.push_back(entry.path());
  std::sort(paths.begin(), paths.end());
  return paths;
}

TEST(PublicApi, TextsAreTheBuildsBytesForEveryExample) {
  const matc::Build build{matc::BuildOptions{}};
  const matc::api::TextOutputs texts;
  for (const char* language : {"glsl", "hlsl", "wgsl"}) {
    const auto kind = matc::shader_language_name(matc::ShaderLanguage::glsl) == language
                          ? matc::ShaderLanguage::glsl
                      : std::string(language) == "hlsl" ? matc::ShaderLanguage::hlsl
                                                        : matc::ShaderLanguage::wgsl;
    EXPECT_EQ(texts.library_source(language), build.library_source(kind)) << language;
  }
  std::size_t compared = 0;
  for (const fs::path& path : example_materials()) {
    for (const matc::api::Material& material : matc::api::load_materials(path.string())) {
      const matc::api::CompiledMaterial compiled = matc::api::compile(material);
      const matc::MaterialOutputs outputs = build.material_outputs(compiled.value());
      for (const matc::OutputFile& file : outputs.files) {
        const std::string extension = fs::path(file.name).extension().string().substr(1);
        if (extension == "json") {
          EXPECT_EQ(texts.material_json(compiled), file.bytes) << file.name;
        } else if (extension == "glsl" || extension == "hlsl" || extension == "wgsl") {
          EXPECT_EQ(texts.material_source(extension, compiled), file.bytes) << file.name;
        } else {
          continue;
        }
        ++compared;
      }
    }
  }
  EXPECT_GE(compared, 4u * example_materials().size());
}

TEST(PublicApi, CompiledValuesAreTheLibrarys) {
  const auto materials = matc::api::load_materials(std::string(MATC_EXAMPLES_DIR) + "/gold.json");
  ASSERT_EQ(materials.size(), 1u);
  const matc::api::CompiledMaterial compiled = matc::api::compile(materials[0]);
  const matc::CompiledMaterial direct =
      matc::compile_material(matc::read_material_input(materials[0].path()).materials.at(0),
                             matc::runtime::shipped_basis(matc::runtime::kDefaultBasis));
  EXPECT_EQ(compiled.coefficients(), direct.coefficients);
  EXPECT_EQ(compiled.f0(), direct.f0);
  const std::vector<double> mu = {0.0, 0.25, 1.0};
  const std::vector<double> f = compiled.fresnel(mu);
  ASSERT_EQ(f.size(), 9u);
  for (std::size_t i = 0; i < mu.size(); ++i) {
    const auto rgb = matc::runtime::evaluate_fresnel(
        direct.coefficients, matc::runtime::shipped_shader_basis(matc::runtime::kDefaultBasis),
        mu[i]);
    for (std::size_t c = 0; c < 3; ++c)
      EXPECT_EQ(f[3 * i + c], rgb[c]);
  }
  // At normal incidence (mu = 1) the exact curve and Schlick's are F0; at grazing, 1.
  EXPECT_NEAR(compiled.exact(std::vector<double>{1.0})[0], compiled.f0()[0], 1e-12);
  EXPECT_NEAR(compiled.schlick(std::vector<double>{0.0})[1], 1.0, 1e-12);
  EXPECT_NEAR(compiled.f82_tint(std::vector<double>{1.0})[2], compiled.f0()[2], 1e-12);
  EXPECT_THROW(compiled.coated_fresnel(mu), std::logic_error);
}

TEST(PublicApi, BadInputIsAMaterialErrorWithTheCliLines) {
  try {
    matc::api::parse_materials(R"({"name": "x", "artistic": {"reflectivity": [2, 0, 0]}})",
                               "bad.json");
    FAIL() << "no error";
  } catch (const matc::api::MaterialError& error) {
    ASSERT_FALSE(error.diagnostics().empty());
    EXPECT_EQ(error.diagnostics()[0].severity, "error");
    EXPECT_EQ(error.diagnostics()[0].path, "bad.json");
    EXPECT_NE(std::string(error.what()).find("bad.json:1:"), std::string::npos) << error.what();
  }
}

TEST(PublicApi, ArgumentsOutOfRangeAreNamed) {
  const auto materials = matc::api::load_materials(std::string(MATC_EXAMPLES_DIR) + "/gold.json");
  const matc::api::CompiledMaterial compiled = matc::api::compile(materials[0]);
  EXPECT_THROW(compiled.fresnel(std::vector<double>{0.5, 1.5}), std::invalid_argument);
  EXPECT_THROW(compiled.fbar(std::vector<double>{0.5}, std::vector<double>{}),
               std::invalid_argument);
  EXPECT_THROW(matc::api::compile(materials[0], {"no-such-basis", "", ""}), std::invalid_argument);
  const matc::api::TextOutputs paper({"paper", "", ""});
  EXPECT_THROW(paper.material_source("glsl", compiled), std::invalid_argument);
  EXPECT_THROW(matc::api::TextOutputs().material_source("msl", compiled), std::invalid_argument);
}

}  // namespace

namespace {

// Files an input names, given in memory: read instead of the disk (the same material as from
// the disk), the only files read, their names checked.
TEST(PublicApi, FilesAnInputNamesComeFromMemoryWhenGiven) {
  const std::string dir = MATC_EXAMPLES_DIR;
  const auto read = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string text = read(dir + "/gold_measured_file.json");
  const matc::api::InputFiles files{
      {"spectra/gold_pbrt_v4.csv", read(dir + "/spectra/gold_pbrt_v4.csv")}};
  // A folder that does not exist: nothing can come from the disk.
  const auto from_memory =
      matc::api::parse_materials(text, "/nowhere/gold_measured_file.json", files);
  const auto from_disk = matc::api::load_materials(dir + "/gold_measured_file.json");
  ASSERT_EQ(from_memory.size(), 1u);
  EXPECT_EQ(matc::api::compile(from_memory[0]).coefficients(),
            matc::api::compile(from_disk[0]).coefficients());
  // Given files are the only ones read: one missing cannot be read even where the disk has it.
  try {
    matc::api::parse_materials(text, dir + "/gold_measured_file.json", matc::api::InputFiles{});
    FAIL() << "a file not given was read";
  } catch (const matc::api::MaterialError& error) {
    EXPECT_NE(std::string(error.what()).find("not among the files given"), std::string::npos)
        << error.what();
  }
  for (const char* name : {"../gold.csv", "/etc/passwd", "", "a\\b.csv", "c:x.csv", "spectra/.."}) {
    EXPECT_THROW(matc::api::parse_materials(text, "gold.json", matc::api::InputFiles{{name, "x"}}),
                 std::invalid_argument)
        << name;
  }
  // A .gltf's buffer: the asset written back as from the disk.
  const std::string gltf =
      R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 4, "uri": "b.bin"}],
          "materials": [{"name": "steel", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]}}]})";
  EXPECT_THROW(matc::api::compile_gltf(gltf, "a/car.gltf", {}, matc::api::InputFiles{}),
               matc::api::MaterialError);
  const matc::api::GltfAsset asset =
      matc::api::compile_gltf(gltf, "a/car.gltf", {}, matc::api::InputFiles{{"b.bin", "abcd"}});
  EXPECT_EQ(asset.materials.size(), 1u);
  EXPECT_EQ(asset.external_uris, std::vector<std::string>{"b.bin"});
}

namespace {
std::string file_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
void put_file(const fs::path& path, const std::string& bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << bytes;
}
}  // namespace

// write_gltf: a .gltf written into another folder takes the files it names along (decoded URIs,
// subfolders, each once); over an input, or over another file of a copy's name, it writes nothing.
TEST(PublicApi, WriteGltfCopiesTheFilesItNamesBesideTheOutput) {
  const fs::path folder = fs::temp_directory_path() / "matc_api_write_gltf_test";
  fs::remove_all(folder);
  put_file(folder / "in" / "car.gltf",
           R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 4, "uri": "data/b%20x.bin"},
               {"byteLength": 4, "uri": "data/b x.bin"}], "images": [{"uri": "t.png"}, {"uri": "data/t.png"}],
               "materials": [{"name": "steel"}]})");
  put_file(folder / "in" / "data" / "b x.bin", "abcd");
  put_file(folder / "in" / "t.png", "png!");
  put_file(folder / "in" / "data" / "t.png", "png2");
  const std::string input = (folder / "in" / "car.gltf").string();
  const matc::api::GltfAsset asset = matc::api::compile_gltf_file(input);
  const matc::api::GltfFilesCopied copied =
      matc::api::write_gltf(asset, input, (folder / "out" / "car.gltf").string());
  EXPECT_EQ(copied.written, (std::vector<std::string>{"data/b x.bin", "t.png", "data/t.png"}));
  EXPECT_EQ(file_text(folder / "out" / "data" / "b x.bin"), "abcd");
  EXPECT_EQ(file_text(folder / "out" / "t.png"), "png!");
  EXPECT_EQ(file_text(folder / "out" / "car.gltf"), asset.bytes);
  const auto again = matc::api::write_gltf(asset, input, (folder / "out" / "car.gltf").string());
  EXPECT_TRUE(again.written.empty());
  EXPECT_EQ(again.unchanged.size(), 3u);
  // In its own folder nothing is copied.
  EXPECT_TRUE(matc::api::write_gltf(asset, input, (folder / "in" / "car_matc.gltf").string())
                  .written.empty());
  // Refused, nothing written: over the input; a copy over a file the asset names (t.png over
  // data/t.png from the subfolder); over another file with other bytes.
  EXPECT_THROW(matc::api::write_gltf(asset, input, input), std::invalid_argument);
  EXPECT_THROW(matc::api::write_gltf(asset, input, (folder / "in" / "data" / "x.gltf").string()),
               std::invalid_argument);  // t.png would be copied over data/t.png
  put_file(folder / "other" / "t.png", "someone else's");
  EXPECT_THROW(matc::api::write_gltf(asset, input, (folder / "other" / "car.gltf").string()),
               std::invalid_argument);
  EXPECT_EQ(file_text(folder / "other" / "t.png"), "someone else's");
  EXPECT_FALSE(fs::exists(folder / "other" / "car.gltf"));
  EXPECT_FALSE(fs::exists(folder / "other" / "data"));
  EXPECT_FALSE(fs::exists(folder / "in" / "data" / "x.gltf"));
  fs::remove_all(folder);
}

TEST(PublicApi, BatchRefusesBadOptionsBeforeWriting) {
  const std::vector<matc::api::BatchSource> sources = {
      matc::api::BatchSource::file(std::string(MATC_EXAMPLES_DIR) + "/gold.json")};
  matc::api::BatchOptions options;
  EXPECT_THROW(matc::api::compile_batch(sources, options), std::invalid_argument);  // no folder
  const fs::path folder = fs::temp_directory_path() / "matc_api_batch_test";
  fs::remove_all(folder);
  options.output_directory = folder.string();
  options.emit = {"glsl", "msl"};
  EXPECT_THROW(matc::api::compile_batch(sources, options), std::invalid_argument);
  EXPECT_FALSE(fs::exists(folder));
  options.emit = {"glsl", "json"};
  std::size_t diagnostics = 0;
  matc::api::BatchEvents events;
  events.diagnostics = [&](const std::vector<matc::api::Diagnostic>& items) {
    diagnostics += items.size();
  };
  const matc::api::BatchResult result = matc::api::compile_batch(sources, options, events);
  EXPECT_EQ(result.compiled, 1u);
  EXPECT_EQ(result.failed, 0u);
  EXPECT_GT(diagnostics, 0u);  // gold's note: its curve leaves [0, 1] in Rec.709
  EXPECT_TRUE(fs::exists(folder / "gold.glsl"));
  EXPECT_TRUE(fs::exists(folder / "gold.json"));
  EXPECT_FALSE(fs::exists(folder / "gold.spv"));
  fs::remove_all(folder);
}

}  // namespace
