// The library's batches (pipeline/) driven without the CLI: from memory into memory or a
// directory, with their events, checks and cancellation; and the CLI writing the same bytes.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <stop_token>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "emit/build.h"
#include "pipeline/bake_batch.h"
#include "pipeline/compile_batch.h"
#include "pipeline/import_batch.h"

namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

std::map<std::string, std::string> files_in(const fs::path& directory) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(directory))
    files[entry.path().filename().string()] = read_file(entry.path());
  return files;
}

constexpr const char* kGold =
    R"({"name": "gold", "artistic": {"reflectivity": [0.95, 0.64, 0.27], "edge_tint": [1.0, 0.98, 0.62]}})";
constexpr const char* kCopper =
    R"({"name": "copper", "ior": {"n": [0.27, 0.68, 1.32], "k": [3.61, 2.62, 2.29]}})";
constexpr const char* kBad = "{\n  \"name\": \"bad\",\n  \"ior\": {\"n\": -1, \"k\": 0}\n}\n";

// What a batch reported, in the order it reported it.
struct Recorded {
  std::vector<std::string> diagnostics;  // formatted, one per diagnostic
  std::vector<matc::BatchProgress> progress;
  std::vector<std::string> progress_names;
  std::vector<std::string> errors;

  matc::BatchEvents events() {
    matc::BatchEvents events;
    events.diagnostics = [this](const matc::Diagnostics& found) {
      for (const matc::Diagnostic& diagnostic : found.items())
        diagnostics.push_back(matc::format_diagnostic(diagnostic));
    };
    events.progress = [this](const matc::BatchProgress& done) {
      progress.push_back(done);
      progress_names.emplace_back(done.name);
    };
    events.error = [this](const std::string& where, const std::string& message) {
      errors.push_back(where + ": " + message);
    };
    return events;
  }
};

class Pipeline : public testing::Test {
 protected:
  static void SetUpTestSuite() { build_ = new matc::Build(matc::BuildOptions{}); }
  static void TearDownTestSuite() { delete build_; }
  void SetUp() override {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("matc_pipeline_") + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::vector<matc::MaterialSource> two_metals() {
    return {matc::MaterialSource::in_memory("gold.json", kGold),
            matc::MaterialSource::in_memory("copper.json", kCopper)};
  }

  static matc::Build* build_;
  fs::path dir_;
};

matc::Build* Pipeline::build_ = nullptr;

TEST_F(Pipeline, CompilesMaterialsFromMemoryIntoMemory) {
  matc::MemoryOutput output;
  Recorded recorded;
  const matc::CompileBatchResult result =
      matc::compile_batch(*build_, two_metals(), output, {}, recorded.events());
  EXPECT_EQ(result.counts.done, 2u);
  EXPECT_EQ(result.counts.failed, 0u);
  EXPECT_FALSE(result.cancelled);
  EXPECT_EQ(result.counts.written, output.files().size());
  for (const char* name :
       {"gold.glsl", "gold.hlsl", "gold.wgsl", "gold.spv", "gold.h", "gold.json", "copper.json",
        "matc_fresnel.glsl", "matc_lut.ktx2", "matc_manifest.json"})
    EXPECT_TRUE(output.files().contains(name)) << name;
  const auto manifest = nlohmann::json::parse(output.files().at("matc_manifest.json"));
  ASSERT_EQ(manifest["materials"].size(), 2u);
  EXPECT_EQ(manifest["materials"][0]["name"], "gold");  // input order, whatever the threads
  EXPECT_EQ(manifest["materials"][1]["name"], "copper");
  const auto gold = nlohmann::json::parse(output.files().at("gold.json"));
  EXPECT_EQ(gold["coefficients"].size(), 3u);
  EXPECT_TRUE(recorded.diagnostics.empty());
  ASSERT_EQ(recorded.progress.size(), 2u);
  EXPECT_EQ(recorded.progress.back().done, 2u);
  EXPECT_EQ(recorded.progress.back().total, 2u);
  EXPECT_TRUE(recorded.errors.empty());
}

TEST_F(Pipeline, DirectoryAndMemoryOutputsHoldTheSameBytes) {
  matc::MemoryOutput memory;
  matc::compile_batch(*build_, two_metals(), memory);
  matc::DirectoryOutput directory(dir_ / "out");
  const matc::CompileBatchResult first = matc::compile_batch(*build_, two_metals(), directory);
  EXPECT_EQ(files_in(dir_ / "out"), memory.files());
  EXPECT_EQ(first.counts.unchanged, 0u);
  // Again: every file is left as it was, so build systems see no change.
  const matc::CompileBatchResult again = matc::compile_batch(*build_, two_metals(), directory);
  EXPECT_EQ(again.counts.written, 0u);
  EXPECT_EQ(again.counts.unchanged, first.counts.written);
}

// The library's batch is the CLI's: the same sources give the same bytes, manifest included.
TEST_F(Pipeline, WritesWhatTheCliWrites) {
  write_file(dir_ / "m" / "gold.json", kGold);
  write_file(dir_ / "m" / "copper.json", kCopper);
  const std::string command =
      "cd '" + dir_.string() + "' && '" MATC_BINARY "' -q -o cli m/gold.json m/copper.json";
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  const std::vector<matc::MaterialSource> sources = {
      matc::MaterialSource::in_memory("m/gold.json", kGold),
      matc::MaterialSource::in_memory("m/copper.json", kCopper)};
  matc::MemoryOutput memory;
  matc::compile_batch(*build_, sources, memory);
  EXPECT_EQ(files_in(dir_ / "cli"), memory.files());
}

TEST_F(Pipeline, AnInvalidInputStopsTheBatchWithItsLocatedError) {
  std::vector<matc::MaterialSource> sources = two_metals();
  sources.insert(sources.begin() + 1, matc::MaterialSource::in_memory("bad.json", kBad));
  matc::MemoryOutput output;
  Recorded recorded;
  const matc::CompileBatchResult result =
      matc::compile_batch(*build_, sources, output, {}, recorded.events());
  EXPECT_EQ(result.counts.failed, 1u);
  EXPECT_EQ(result.counts.done, 0u);
  EXPECT_EQ(result.counts.not_attempted, 2u);
  EXPECT_TRUE(output.files().empty());
  ASSERT_EQ(recorded.diagnostics.size(), 1u);
  EXPECT_EQ(recorded.diagnostics[0].rfind("bad.json:3:16: error: ior.n: -1 is out of range", 0), 0u)
      << recorded.diagnostics[0];

  matc::CompileBatchOptions keep_going;
  keep_going.keep_going = true;
  matc::MemoryOutput rest;
  const matc::CompileBatchResult kept = matc::compile_batch(*build_, sources, rest, keep_going);
  EXPECT_EQ(kept.counts.done, 2u);
  EXPECT_EQ(kept.counts.failed, 1u);
  EXPECT_TRUE(rest.files().contains("copper.spv"));
  EXPECT_FALSE(rest.files().contains("bad.json"));
}

TEST_F(Pipeline, NamesMustDifferByMoreThanCase) {
  const std::vector<matc::MaterialSource> sources = {
      matc::MaterialSource::in_memory("a.json", kGold),
      matc::MaterialSource::in_memory("b.json", R"({"name": "GOLD", "ior": {"n": 1.5, "k": 0}})")};
  matc::MemoryOutput output;
  Recorded recorded;
  const auto result = matc::compile_batch(*build_, sources, output, {}, recorded.events());
  EXPECT_EQ(result.counts.failed, 1u);
  bool clash = false;
  for (const std::string& line : recorded.diagnostics)
    clash |= line.find("b.json:1:10: error: name: 'GOLD' is already used by a.json (1:10)") == 0;
  EXPECT_TRUE(clash);
}

TEST_F(Pipeline, ARefusedCheckWritesNothingForThatMaterial) {
  matc::CompileBatchOptions options;
  options.keep_going = true;
  std::vector<std::string> checked;
  options.check_material = [&checked](const matc::CompiledMaterial& compiled) {
    checked.push_back(compiled.material.name);
    return compiled.material.name != "copper";
  };
  matc::MemoryOutput output;
  const auto result = matc::compile_batch(*build_, two_metals(), output, options);
  EXPECT_EQ(checked.size(), 2u);
  EXPECT_EQ(result.failed_checks, 1u);
  EXPECT_EQ(result.counts.failed, 1u);
  EXPECT_TRUE(output.files().contains("gold.spv"));
  EXPECT_FALSE(output.files().contains("copper.spv"));
}

TEST_F(Pipeline, ACancelledBatchStopsAndWritesNoSharedFile) {
  std::vector<matc::MaterialSource> sources;
  for (char digit = '0'; digit < '6'; ++digit) {
    std::string path = "m0.json", text = R"({"name": "m0", "ior": {"n": 1.5, "k": 0}})";
    path[1] = digit;
    text[11] = digit;
    sources.push_back(matc::MaterialSource::in_memory(path, text));
  }
  std::stop_source stop;
  matc::CompileBatchOptions options;
  options.jobs = 1;
  options.cancel = stop.get_token();
  matc::BatchEvents events;
  events.progress = [&stop](const matc::BatchProgress&) { stop.request_stop(); };
  matc::MemoryOutput output;
  const auto result = matc::compile_batch(*build_, sources, output, options, events);
  EXPECT_TRUE(result.cancelled);
  EXPECT_EQ(result.counts.done, 1u);
  EXPECT_EQ(result.counts.not_attempted, 5u);
  EXPECT_TRUE(output.files().contains("m0.spv"));
  EXPECT_FALSE(output.files().contains("m1.spv"));
  EXPECT_FALSE(output.files().contains("matc_fresnel.glsl"));
  EXPECT_FALSE(output.files().contains("matc_manifest.json"));
}

TEST_F(Pipeline, ContradictoryOptionsAreRefused) {
  matc::MemoryOutput output;
  matc::CompileBatchOptions shared_only;
  shared_only.shared_only = true;
  EXPECT_THROW(matc::compile_batch(*build_, two_metals(), output, shared_only),
               std::invalid_argument);
  matc::CompileBatchOptions depfile;
  depfile.depfile = dir_ / "matc.d";
  EXPECT_THROW(matc::compile_batch(*build_, two_metals(), output, depfile), std::invalid_argument);
}

TEST_F(Pipeline, DepfileListsEveryOutputAndInput) {
  write_file(dir_ / "gold.json", kGold);
  matc::CompileBatchOptions options;
  options.depfile = dir_ / "out" / "matc.d";
  options.extra_dependencies = {dir_ / "tool"};
  matc::DirectoryOutput output(dir_ / "out");
  const std::vector<matc::MaterialSource> sources = {
      matc::MaterialSource::file((dir_ / "gold.json").string())};
  ASSERT_EQ(matc::compile_batch(*build_, sources, output, options).counts.failed, 0u);
  const std::string depfile = read_file(dir_ / "out" / "matc.d");
  for (const fs::path& path : {dir_ / "out" / "gold.spv", dir_ / "out" / "matc_manifest.json",
                               dir_ / "gold.json", dir_ / "tool"})
    EXPECT_NE(depfile.find(path.string()), std::string::npos) << path << "\n" << depfile;
}

TEST_F(Pipeline, AnOutputMayNotOverwriteAnInput) {
  write_file(dir_ / "gold.json", kGold);
  matc::DirectoryOutput output(dir_);
  Recorded recorded;
  const std::vector<matc::MaterialSource> sources = {
      matc::MaterialSource::file((dir_ / "gold.json").string())};
  const auto result = matc::compile_batch(*build_, sources, output, {}, recorded.events());
  EXPECT_EQ(result.counts.failed, 1u);
  ASSERT_FALSE(recorded.diagnostics.empty());
  EXPECT_NE(recorded.diagnostics[0].find("would overwrite the input"), std::string::npos);
  EXPECT_EQ(read_file(dir_ / "gold.json"), kGold);
}

TEST_F(Pipeline, ImportsADocumentFromMemory) {
  const std::string document = read_file(MATC_SOURCE_DIR "/examples/materialx/metals.mtlx");
  matc::MemoryOutput output;
  const std::vector<matc::MaterialSource> documents = {
      matc::MaterialSource::in_memory("metals.mtlx", document)};
  const matc::BatchCounts counts = matc::import_batch(documents, output);
  EXPECT_GT(counts.done, 0u);
  EXPECT_EQ(counts.done, output.files().size());
  for (const auto& [name, text] : output.files()) {
    EXPECT_EQ(fs::path(name).extension(), ".json");
    EXPECT_EQ(nlohmann::json::parse(text)["name"].get<std::string>() + ".json", name);
  }
  Recorded recorded;
  const std::vector<matc::MaterialSource> wrong = {
      matc::MaterialSource::in_memory("gold.json", kGold)};
  EXPECT_EQ(matc::import_batch(wrong, output, {}, recorded.events()).failed, 1u);
  ASSERT_EQ(recorded.diagnostics.size(), 1u);
  EXPECT_EQ(recorded.diagnostics[0],
            "gold.json: error: is not a MaterialX document or a glTF asset; a .mtlx, .gltf or .glb "
            "file");
}

TEST_F(Pipeline, BakesAnAssetDescribedInMemory) {
  matc::BakeAsset asset;
  asset.name = "plate";
  asset.model = matc::BakeModel::artistic;
  asset.first.quantity = matc::MapQuantity::reflectivity;
  asset.first.constant = matc::runtime::Rgb{0.9, 0.6, 0.3};
  asset.second.quantity = matc::MapQuantity::edge_tint;
  asset.second.constant = matc::runtime::Rgb{1.0, 0.9, 0.5};
  asset.name_location = {"cooker", 0, 0};
  const std::vector<matc::BakeSource> sources = {
      matc::BakeSource::in_memory({asset, {}}, "the cooker")};
  matc::MemoryOutput output;
  Recorded recorded;
  const matc::BakeBatchResult result = matc::bake_batch(sources, output, {}, recorded.events());
  EXPECT_EQ(result.counts.done, 1u)
      << (recorded.diagnostics.empty() ? "" : recorded.diagnostics[0]);
  EXPECT_EQ(result.counts.written, output.files().size());
  EXPECT_TRUE(output.files().contains("plate_c2.ktx2"));
  EXPECT_TRUE(output.files().contains("plate_bake.json"));
  ASSERT_EQ(recorded.progress_names, std::vector<std::string>{"plate"});
}

}  // namespace
