// End-to-end tests of the matc binary: outputs, exit codes, determinism, and safety.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "example_files.h"
#include "matc/emit/output_layout.h"
#include "matc/lut/lut_files.h"
#include "matc/options/option_names.h"
#include "test_images.h"

namespace {

namespace fs = std::filesystem;

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

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

// Single-quotes a word for the shell. Built with append(): GCC 12 warns falsely (-Wrestrict,
// PR 105329) on chains of std::string operator+.
std::string quote(const std::string& word) {
  std::string out = "'";
  for (const char c : word) {
    if (c == '\'') {
      out.append("'\\''");
    } else {
      out.push_back(c);
    }
  }
  out.push_back('\'');
  return out;
}

class MatcCli : public testing::Test {
 protected:
  void SetUp() override {
    const auto* info = testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / (std::string("matc_cli_") + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // `environment`: NAME=value words placed before the command.
  CommandResult run(const std::vector<std::string>& args,
                    const std::vector<std::string>& environment = {}) const {
    std::string command = "cd ";
    command.append(quote(dir_.string())).append(" && ");
    for (const auto& assignment : environment)
      command.append(assignment).append(" ");
    command.append(quote(MATC_BINARY));
    for (const auto& arg : args)
      command.append(" ").append(quote(arg));
    command.append(" >").append(quote((dir_ / ".stdout").string()));
    command.append(" 2>").append(quote((dir_ / ".stderr").string()));
    const int status = std::system(command.c_str());
    CommandResult result;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    result.out = read_file(dir_ / ".stdout");
    result.err = read_file(dir_ / ".stderr");
    return result;
  }

  fs::path dir_;
};

constexpr const char* kGood = R"({"name": "good", "ior": {"n": 1.5, "k": 0}})";
constexpr const char* kBad = "{\n  \"name\": \"bad\",\n  \"ior\": {\"n\": -1, \"k\": 0}\n}\n";

TEST_F(MatcCli, CompilesEveryExample) {
  std::vector<std::string> args = {"-o", "out"};
  const auto files = matc::test::example_material_files();
  ASSERT_GE(files.size(), 11u);
  args.insert(args.end(), files.begin(), files.end());
  const CommandResult result = run(args);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.err.find(std::to_string(files.size()) + " compiled"), std::string::npos)
      << result.err;
  for (const auto& file : files) {
    const auto input = nlohmann::json::parse(read_file(file));
    const fs::path output = dir_ / "out" / (input["name"].get<std::string>() + ".json");
    ASSERT_TRUE(fs::exists(output)) << output;
    const auto compiled = nlohmann::json::parse(read_file(output));
    EXPECT_EQ(compiled["name"], input["name"]);
    ASSERT_EQ(compiled["coefficients"].size(), 3u);
    for (const auto& row : compiled["coefficients"]) {
      ASSERT_EQ(row.size(), 4u);
      EXPECT_NEAR(row[0].get<double>() + row[1].get<double>(), 1.0, 1e-12);
    }
    for (const char* model : {"decomposition", "schlick", "f82_tint"}) {
      EXPECT_EQ(compiled["accuracy"][model]["max"].size(), 3u);
    }
  }
}

// The manifest is streamed from a temporary list of entries: a change to one material that
// keeps the manifest's length (its hashes change, not their size) still rewrites it, in order.
TEST_F(MatcCli, ManifestFollowsAChangedMaterialInInputOrder) {
  write_file(dir_ / "m" / "a.json", R"({"name": "a", "ior": {"n": 1.5, "k": 0}})");
  write_file(dir_ / "m" / "b.json", R"({"name": "b", "ior": {"n": 1.6, "k": 0}})");
  write_file(dir_ / "m" / "c.json", R"({"name": "c", "ior": {"n": 1.7, "k": 0}})");
  const std::vector<std::string> args = {"-o",       "out",      "-j",      "2",
                                         "m/c.json", "m/a.json", "m/b.json"};
  ASSERT_EQ(run(args).exit_code, 0);
  const std::string before = read_file(dir_ / "out" / "matc_manifest.json");
  write_file(dir_ / "m" / "a.json", R"({"name": "a", "ior": {"n": 1.4, "k": 0}})");
  ASSERT_EQ(run(args).exit_code, 0);
  const std::string after = read_file(dir_ / "out" / "matc_manifest.json");
  EXPECT_EQ(after.size(), before.size());
  EXPECT_NE(after, before);
  const auto manifest = nlohmann::json::parse(after);
  ASSERT_EQ(manifest["materials"].size(), 3u);
  EXPECT_EQ(manifest["materials"][0]["name"], "c");
  EXPECT_EQ(manifest["materials"][1]["name"], "a");
  EXPECT_EQ(manifest["materials"][2]["name"], "b");
}

TEST_F(MatcCli, SameInputsGiveSameBytesAndUnchangedFilesAreNotRewritten) {
  write_file(dir_ / "m" / "good.json", kGood);
  ASSERT_EQ(run({"-o", "a", "m/good.json"}).exit_code, 0);
  const auto first_time = fs::last_write_time(dir_ / "a" / "good.json");
  const CommandResult again = run({"-o", "a", "m/good.json"});
  ASSERT_EQ(again.exit_code, 0);
  // good.{json,glsl,hlsl,wgsl,spv,h}, matc_fresnel.{glsl,hlsl,wgsl,spv}, matc_lut,
  // matc_coefficient_table and matc_ltc .ktx2 and .json, the manifest.
  EXPECT_NE(again.err.find("0 files written, 17 unchanged"), std::string::npos) << again.err;
  EXPECT_EQ(fs::last_write_time(dir_ / "a" / "good.json"), first_time);
  ASSERT_EQ(run({"-o", "b", "m/good.json"}).exit_code, 0);
  for (const auto& entry : fs::directory_iterator(dir_ / "a")) {
    const fs::path name = entry.path().filename();
    EXPECT_EQ(read_file(entry.path()), read_file(dir_ / "b" / name)) << name;
  }
  // No temporary files are left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "a"), fs::directory_iterator()), 17);
}

// A batch killed mid-write (SIGKILL) leaves its hidden temporaries behind; the next run into the
// directory removes those of writers that no longer exist, and nothing else.
TEST_F(MatcCli, RemovesTemporariesOfKilledWriters) {
  write_file(dir_ / "m" / "good.json", kGood);
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ASSERT_EQ(::waitpid(child, nullptr, 0), child);  // its process id now names no process
  const fs::path killed = dir_ / "out" / (".good.glsl.tmp" + std::to_string(child));
  const fs::path alive = dir_ / "out" / (".good.hlsl.tmp" + std::to_string(::getpid()));
  const fs::path unrelated = dir_ / "out" / ".notes.tmp";
  write_file(killed, "half a shader");
  write_file(alive, "still being written");
  write_file(unrelated, "not matc's");
  ASSERT_EQ(run({"-q", "-o", "out", "m/good.json"}).exit_code, 0);
  EXPECT_FALSE(fs::exists(killed));
  EXPECT_TRUE(fs::exists(alive));
  EXPECT_TRUE(fs::exists(unrelated));
}

// One action per material (--no-shared) plus one shared action (--shared-only) write the batch's
// files byte for byte, less the manifest, which lists a whole batch.
TEST_F(MatcCli, PerMaterialActionsWriteTheBatchsBytes) {
  std::vector<std::string> batch = {"-o", "batch"};
  const std::vector<std::string> files = matc::test::example_material_files();
  batch.insert(batch.end(), files.begin(), files.end());
  ASSERT_EQ(run(batch).exit_code, 0);
  const CommandResult shared = run({"-o", "split", "--shared-only"});
  ASSERT_EQ(shared.exit_code, 0) << shared.err;
  for (const std::string& file : files) {
    const CommandResult one = run({"-o", "split", "--no-shared", file});
    ASSERT_EQ(one.exit_code, 0) << one.err;
  }
  std::size_t compared = 0;
  for (const auto& entry : fs::directory_iterator(dir_ / "batch")) {
    const fs::path name = entry.path().filename();
    if (name == "matc_manifest.json") {
      EXPECT_FALSE(fs::exists(dir_ / "split" / name));
      continue;
    }
    EXPECT_EQ(read_file(entry.path()), read_file(dir_ / "split" / name)) << name;
    ++compared;
  }
  EXPECT_EQ(compared, files.size() * 6 + 10);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "split"), fs::directory_iterator()),
            static_cast<std::ptrdiff_t>(compared));
  // A material's own run writes no shared file; the shared run takes no material.
  const CommandResult alone = run({"-o", "alone", "--no-shared", files.front()});
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  EXPECT_FALSE(fs::exists(dir_ / "alone" / "matc_fresnel.glsl"));
  EXPECT_FALSE(fs::exists(dir_ / "alone" / "matc_lut.ktx2"));
  const CommandResult both = run({"-o", "x", "--shared-only", files.front()});
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("--shared-only writes no material's files"), std::string::npos)
      << both.err;
  EXPECT_EQ(run({"-o", "x", "--shared-only", "--no-shared"}).exit_code, 2);
  EXPECT_FALSE(fs::exists(dir_ / "x"));
}

// --files-from reads the paths of a list too long for a command line; blank lines are skipped.
TEST_F(MatcCli, FilesFromReadsAListOfMaterials) {
  write_file(dir_ / "good.json", kGood);
  write_file(dir_ / "gold.json", R"({"name": "Gold", "spectral": {"preset": "Au"}})");
  write_file(dir_ / "list.txt", "good.json\n\ngold.json\r\n");
  const CommandResult listed = run({"-o", "out", "--emit", "json", "--files-from", "list.txt"});
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "good.json"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "Gold.json"));
  const CommandResult missing = run({"-o", "x", "--files-from", "no-such-list.txt"});
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("no-such-list.txt: error: --files-from: cannot read the list"),
            std::string::npos)
      << missing.err;
  EXPECT_FALSE(fs::exists(dir_ / "x"));
}

// -j only changes how fast: every example built one at a time and four at a time gives the
// same files, byte for byte, diagnostics in input order.
TEST_F(MatcCli, ParallelBuildsWriteTheSameBytes) {
  std::vector<std::string> files = matc::test::example_material_files();
  std::vector<std::string> serial = {"-j", "1", "-o", "serial"};
  std::vector<std::string> parallel = {"-j", "4", "-o", "parallel"};
  serial.insert(serial.end(), files.begin(), files.end());
  parallel.insert(parallel.end(), files.begin(), files.end());
  ASSERT_EQ(run(serial).exit_code, 0);
  const CommandResult result = run(parallel);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::size_t compared = 0;
  for (const auto& entry : fs::directory_iterator(dir_ / "serial")) {
    const fs::path name = entry.path().filename();
    EXPECT_EQ(read_file(entry.path()), read_file(dir_ / "parallel" / name)) << name;
    ++compared;
  }
  EXPECT_EQ(compared, files.size() * 6 + 11);
  // Not a terminal: no progress line, only the summary.
  EXPECT_EQ(result.err.find('\r'), std::string::npos);
}

TEST_F(MatcCli, InvalidInputsReportedInOrderWhateverTheJobs) {
  write_file(dir_ / "a.json", kBad);
  write_file(dir_ / "b.json", kGood);
  write_file(dir_ / "c.json", R"({"name": "c", "ior": {"n": 1.5}})");
  const CommandResult result = run({"-j", "3", "-k", "-o", "out", "a.json", "b.json", "c.json"});
  EXPECT_EQ(result.exit_code, 1);
  const std::size_t a = result.err.find("a.json:");
  const std::size_t c = result.err.find("c.json:");
  ASSERT_NE(a, std::string::npos) << result.err;
  ASSERT_NE(c, std::string::npos) << result.err;
  EXPECT_LT(a, c);
  EXPECT_NE(result.err.find("1 compiled"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("2 failed"), std::string::npos) << result.err;
}

// The depfile lists every output as a target and every input as a dependency, absolute, with
// spaces escaped for Ninja; -MD puts it in the output directory.
TEST_F(MatcCli, DepfileListsOutputsAndEveryInput) {
  write_file(dir_ / "in put" / "good.json", kGood);
  const CommandResult result = run({"-MD", "--emit", "glsl,json", "-o", "out", "in put/good.json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::string depfile = read_file(dir_ / "out" / "matc.d");
  const std::string out = (dir_ / "out").string();
  EXPECT_EQ(depfile.find(out + "/matc_fresnel.glsl \\\n"), 0u) << depfile;
  EXPECT_NE(depfile.find(out + "/good.glsl"), std::string::npos) << depfile;
  EXPECT_NE(depfile.find(out + "/matc_manifest.json"), std::string::npos) << depfile;
  EXPECT_NE(depfile.find((dir_ / "in\\ put" / "good.json").string()), std::string::npos) << depfile;
  EXPECT_NE(depfile.find("/matc\n"), std::string::npos) << depfile;  // the binary, last

  write_file(dir_ / "bad.json", kBad);
  EXPECT_EQ(run({"--depfile", "bad.d", "-o", "out2", "bad.json"}).exit_code, 1);
  EXPECT_FALSE(fs::exists(dir_ / "bad.d"));
}

// --diagnostics-format=json: every line on standard error is one JSON object, diagnostics with
// their position and parts, then the summary.
TEST_F(MatcCli, DiagnosticsAsJsonLines) {
  write_file(dir_ / "bad.json", kBad);
  write_file(dir_ / "good.json", kGood);
  const CommandResult result =
      run({"--diagnostics-format=json", "-k", "-o", "out", "bad.json", "good.json"});
  EXPECT_EQ(result.exit_code, 1);
  std::istringstream lines(result.err);
  std::vector<nlohmann::json> objects;
  for (std::string line; std::getline(lines, line);)
    objects.push_back(nlohmann::json::parse(line));  // throws, failing the test, if not JSON
  ASSERT_EQ(objects.size(), 2u) << result.err;
  EXPECT_EQ(objects[0]["file"], "bad.json");
  EXPECT_EQ(objects[0]["line"], 3);
  EXPECT_EQ(objects[0]["column"], 16);
  EXPECT_EQ(objects[0]["severity"], "error");
  EXPECT_EQ(objects[0]["field"], "ior.n");
  EXPECT_EQ(objects[0]["message"], "-1 is out of range");
  EXPECT_EQ(objects[0]["allowed"], "a number in [0, 1000]");
  EXPECT_EQ(objects[1]["summary"]["compiled"], 1);
  EXPECT_EQ(objects[1]["summary"]["failed"], 1);
}

// A symlink planted in the output directory is replaced by the new file, never written through:
// nothing outside the output directory changes.
TEST_F(MatcCli, SymlinksInTheOutputDirectoryAreReplacedNotFollowed) {
  write_file(dir_ / "good.json", kGood);
  write_file(dir_ / "victim.txt", "precious");
  fs::create_directories(dir_ / "out");
  fs::create_symlink(dir_ / "victim.txt", dir_ / "out" / "good.glsl");
  fs::create_symlink(dir_ / "victim.txt", dir_ / "out" / "matc_fresnel.hlsl");
  const CommandResult result = run({"-o", "out", "good.json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(read_file(dir_ / "victim.txt"), "precious");
  EXPECT_FALSE(fs::is_symlink(dir_ / "out" / "good.glsl"));
  EXPECT_FALSE(fs::is_symlink(dir_ / "out" / "matc_fresnel.hlsl"));
  EXPECT_NE(read_file(dir_ / "out" / "good.glsl").find("matc_fresnel_good"), std::string::npos);
}

TEST_F(MatcCli, NamesOfTheSharedOutputsAreReserved) {
  write_file(dir_ / "lut.json", R"({"name": "Matc_Lut", "ior": {"n": 1.5, "k": 0}})");
  const CommandResult result = run({"-o", "out", "lut.json"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("lut.json:1:10: error: name: 'Matc_Lut' names a file every build "
                            "writes"),
            std::string::npos)
      << result.err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "Matc_Lut.glsl"));
}

// Every shared file's stem (the output layout's list, issue #29: matc_ltc and
// matc_coefficient_table were missing and a material so named overwrote their headers with --lut
// header), in every table format and in either case: refused, and nothing written.
TEST_F(MatcCli, EverySharedFileStemIsReservedInEveryFormat) {
  const std::vector<std::string> stems = matc::shared_file_stems();
  ASSERT_EQ(stems.size(), 5u);
  for (const std::string& stem : stems) {
    std::string upper = stem;
    std::transform(upper.begin(), upper.end(), upper.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    for (const std::string& name : {stem, upper}) {
      for (const std::string& format : matc::option_name_list<matc::LutFormat>()) {
        write_file(dir_ / "reserved.json",
                   R"({"name": ")" + name + R"(", "ior": {"n": 1.5, "k": 0}})");
        const CommandResult result = run({"-o", "out", "--lut", format, "reserved.json"});
        EXPECT_EQ(result.exit_code, 1) << name << " with --lut " << format;
        EXPECT_NE(result.err.find("'" + name + "' names a file every build writes"),
                  std::string::npos)
            << result.err;
        EXPECT_TRUE(!fs::exists(dir_ / "out") || fs::is_empty(dir_ / "out"))
            << name << " with --lut " << format << ": a refused build wrote a file";
      }
    }
  }
}

TEST_F(MatcCli, OutputsThatWouldOverwriteAnInputAreRefused) {
  // out/good.h is a material file (named "other") that compiling "good" into out/ would replace.
  write_file(dir_ / "m" / "x.json", kGood);
  const std::string other = R"({"name": "other", "ior": {"n": 1.5, "k": 0}})";
  write_file(dir_ / "out" / "good.h", other);
  const CommandResult result = run({"-o", "out", "m/x.json", "out/good.h"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("would overwrite the input out/good.h"), std::string::npos)
      << result.err;
  EXPECT_EQ(read_file(dir_ / "out" / "good.h"), other);
}

TEST_F(MatcCli, EmitSelectsTheOutputKinds) {
  write_file(dir_ / "good.json", kGood);
  const CommandResult result = run({"-o", "out", "--emit", "glsl,spirv", "good.json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir_ / "out"))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"good.glsl", "good.spv", "matc_fresnel.glsl",
                                             "matc_fresnel.spv"}));
  const CommandResult unknown = run({"-o", "out2", "--emit", "glsl,msl", "good.json"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("msl"), std::string::npos) << unknown.err;
  EXPECT_FALSE(fs::exists(dir_ / "out2"));
}

// `matc layout` (what build systems declare) names exactly the files a compile writes, for each
// output kind alone, every table format, and the split layout's two halves.
TEST_F(MatcCli, LayoutNamesExactlyTheFilesACompileWrites) {
  write_file(dir_ / "good.json", kGood);
  const auto written_files = [&](const fs::path& directory) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory))
      names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  };
  const auto listed_files = [](const std::string& out) {
    std::vector<std::string> names;
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);)
      names.push_back(line);
    std::sort(names.begin(), names.end());
    return names;
  };
  std::vector<std::vector<std::string>> cases;
  for (const std::string& kind : matc::option_name_list<matc::OutputKind>())
    cases.push_back({"--emit", kind});
  for (const std::string& format : matc::option_name_list<matc::LutFormat>())
    cases.push_back({"--lut", format});
  cases.push_back({"--no-shared"});
  cases.push_back({"--shared-only"});
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string out = "out" + std::to_string(i);
    const bool shared_only = cases[i].front() == "--shared-only";
    std::vector<std::string> compile = {"-q", "-o", out};
    std::vector<std::string> layout = {"layout"};
    compile.insert(compile.end(), cases[i].begin(), cases[i].end());
    layout.insert(layout.end(), cases[i].begin(), cases[i].end());
    if (!shared_only) {
      compile.push_back("good.json");
      layout.push_back("good");
    }
    const CommandResult compiled = run(compile);
    ASSERT_EQ(compiled.exit_code, 0) << compiled.err;
    const CommandResult listed = run(layout);
    ASSERT_EQ(listed.exit_code, 0) << listed.err;
    EXPECT_EQ(listed_files(listed.out), written_files(dir_ / out)) << cases[i].front();
  }
}

// The CMake function's and the Bazel rule's file names are generated from the layout.
TEST_F(MatcCli, BuildSystemLayoutSourcesAreCurrent) {
  for (const auto& [system, file] : {std::pair{"cmake", "cmake/MatcOutputLayout.cmake"},
                                     std::pair{"bazel", "bazel/matc_layout.bzl"}}) {
    const CommandResult generated = run({"layout", "--generate", system});
    ASSERT_EQ(generated.exit_code, 0) << generated.err;
    EXPECT_EQ(generated.out, read_file(fs::path(MATC_SOURCE_DIR) / file))
        << file << " is stale: rerun `matc layout --generate " << system << " -o " << file << "`";
  }
}

TEST_F(MatcCli, EmbedLutPutsTheTableInTheSharedLibrary) {
  write_file(dir_ / "good.json", kGood);
  ASSERT_EQ(
      run({"-o", "out", "--emit", "hlsl", "--embed-lut", "--embed-lut-size", "4", "good.json"})
          .exit_code,
      0);
  const std::string library = read_file(dir_ / "out" / "matc_fresnel.hlsl");
  EXPECT_NE(library.find("#define MATC_EMBEDDED_LUT_SIZE 4"), std::string::npos);
  EXPECT_NE(library.find("MATC_EMBEDDED_LUT[16]"), std::string::npos);
  EXPECT_EQ(run({"-o", "out", "--embed-lut", "--embed-lut-size", "65", "good.json"}).exit_code, 2);
}

TEST_F(MatcCli, ManifestListsTheBuildAndGeneratedFilesNameTheirInputs) {
  write_file(dir_ / "good.json", kGood);
  ASSERT_EQ(run({"-o", "out", "--lut-size", "8", "--lut-samples", "16", "good.json"}).exit_code, 0);
  const auto manifest = nlohmann::json::parse(read_file(dir_ / "out" / "matc_manifest.json"));
  EXPECT_EQ(manifest["matc_version"], MATC_VERSION);
  ASSERT_EQ(manifest["materials"].size(), 1u);
  const std::string hash = manifest["materials"][0]["inputs_hash"];
  EXPECT_EQ(manifest["materials"][0]["files"].size(), 6u);
  for (const char* file : {"good.glsl", "good.hlsl", "good.wgsl", "good.h"})
    EXPECT_NE(read_file(dir_ / "out" / file).find(hash), std::string::npos) << file;
  EXPECT_EQ(nlohmann::json::parse(read_file(dir_ / "out" / "good.json"))["inputs_hash"], hash);
  // Changing the material changes the hash.
  write_file(dir_ / "good.json", R"({"name": "good", "ior": {"n": 1.6, "k": 0}})");
  ASSERT_EQ(run({"-o", "out", "--lut-size", "8", "--lut-samples", "16", "good.json"}).exit_code, 0);
  const auto changed = nlohmann::json::parse(read_file(dir_ / "out" / "matc_manifest.json"));
  EXPECT_NE(changed["materials"][0]["inputs_hash"], hash);
}

TEST_F(MatcCli, BadMaterialExitsOneWithLocatedErrorAndWritesNothing) {
  write_file(dir_ / "bad.json", kBad);
  const CommandResult result = run({"-o", "out", "bad.json"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(
      result.err.find("bad.json:3:16: error: ior.n: -1 is out of range; a number in [0, 1000]"),
      std::string::npos)
      << result.err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "bad.json"));
}

TEST_F(MatcCli, StopsAtTheFirstFailureUnlessKeepGoing) {
  write_file(dir_ / "bad.json", kBad);
  write_file(dir_ / "good.json", kGood);
  const CommandResult stopped = run({"-o", "out", "bad.json", "good.json"});
  EXPECT_EQ(stopped.exit_code, 1);
  EXPECT_FALSE(fs::exists(dir_ / "out" / "good.json"));
  EXPECT_NE(stopped.err.find("1 not attempted"), std::string::npos) << stopped.err;

  const CommandResult kept_going = run({"-o", "out", "--keep-going", "bad.json", "good.json"});
  EXPECT_EQ(kept_going.exit_code, 1);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "good.json"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "bad.json"));
}

TEST_F(MatcCli, NamesMustBeUniqueIgnoringCase) {
  write_file(dir_ / "one.json", R"({"name": "Gold", "ior": {"n": 1.5, "k": 0}})");
  write_file(dir_ / "two.json", R"({"name": "gold", "ior": {"n": 1.6, "k": 0}})");
  const CommandResult result = run({"-o", "out", "-k", "one.json", "two.json"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(
      result.err.find("two.json:1:10: error: name: 'gold' is already used by one.json (1:10)"),
      std::string::npos)
      << result.err;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "Gold.json"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "gold.json"));
}

TEST_F(MatcCli, NeverOverwritesAnInputFile) {
  write_file(dir_ / "good.json", kGood);
  const CommandResult result = run({"-o", ".", "good.json"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("would overwrite the input good.json"), std::string::npos)
      << result.err;
  EXPECT_EQ(read_file(dir_ / "good.json"), kGood);
}

TEST_F(MatcCli, UnwritableOutputDirectoryIsAnError) {
  write_file(dir_ / "good.json", kGood);
  write_file(dir_ / "not_a_dir", "x");
  const CommandResult result = run({"-o", "not_a_dir", "good.json"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("error:"), std::string::npos) << result.err;
  EXPECT_EQ(read_file(dir_ / "not_a_dir"), "x");
}

TEST_F(MatcCli, MissingOrDirectoryInputIsAnError) {
  fs::create_directories(dir_ / "a_directory.json");
  const CommandResult missing = run({"-o", "out", "missing.json"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("missing.json: error: cannot read: no such file"), std::string::npos)
      << missing.err;
  const CommandResult directory = run({"-o", "out", "a_directory.json"});
  EXPECT_EQ(directory.exit_code, 1);
  EXPECT_NE(directory.err.find("is a directory"), std::string::npos) << directory.err;
}

TEST_F(MatcCli, EvalPrintsDecomposedAndExactFresnel) {
  const CommandResult result =
      run({"eval", std::string(MATC_EXAMPLES_DIR) + "/chromium.json", "--mu", "0,0.25,0.5,1"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json["name"], "chromium");
  EXPECT_EQ(json["basis"], "powers");
  ASSERT_EQ(json["mu"].size(), 4u);
  ASSERT_EQ(json["F"].size(), 4u);
  ASSERT_EQ(json["F_exact"].size(), 4u);
  // F as the shaders compute it: the polynomial basis holds the ends to 1e-4, not exactly.
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(json["F"][0][c].get<double>(), 1.0, 1e-4);
    EXPECT_NEAR(json["F"][3][c].get<double>(), json["F_exact"][3][c].get<double>(), 1e-5);
    EXPECT_NEAR(json["F"][1][c].get<double>(), json["F_exact"][1][c].get<double>(), 0.02);
  }
}

TEST_F(MatcCli, EvalRejectsCosinesOutsideTheUnitInterval) {
  const CommandResult result =
      run({"eval", std::string(MATC_EXAMPLES_DIR) + "/gold.json", "--mu", "0.5,1.5"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("--mu"), std::string::npos) << result.err;
}

TEST_F(MatcCli, BasisJsonHasTheDocumentedShape) {
  const CommandResult result = run({"basis", "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  ASSERT_EQ(json["mu"].size(), 1000u);
  ASSERT_EQ(json["b"].size(), 4u);
  for (const auto& b : json["b"])
    EXPECT_EQ(b.size(), 1000u);
  EXPECT_EQ(json["b"][0][500], 1.0);
  ASSERT_EQ(json["probes"].size(), 2u);
  // The default (powers) basis' probes, the peaks of b_2 and b_3; its coefficients do not use them.
  EXPECT_NEAR(json["probes"][0].get<double>(), 0.25, 0.001);
  EXPECT_NEAR(json["probes"][1].get<double>(), 0.1, 0.001);
}

TEST_F(MatcCli, PaperBasisKeepsTheAuthorsProbes) {
  const CommandResult result = run({"basis", "--json", "--basis", "paper"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_NEAR(json["probes"][0].get<double>(), 0.126, 0.005);
  EXPECT_NEAR(json["probes"][1].get<double>(), 0.43, 0.01);
  EXPECT_EQ(run({"basis", "--basis", "schlick"}).exit_code, 2);
}

TEST_F(MatcCli, UsageErrorsExitTwo) {
  EXPECT_EQ(run({}).exit_code, 2);
  EXPECT_EQ(run({"--no-such-flag", "x.json"}).exit_code, 2);
  EXPECT_EQ(run({"eval"}).exit_code, 2);
  const CommandResult version = run({"--version"});
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_EQ(version.out, "matc " MATC_VERSION "\n");
}

TEST_F(MatcCli, LutWritesTheTableAndItsManifest) {
  const CommandResult result =
      run({"lut", "-o", "tables/lut.ktx2", "--size", "16", "--samples", "64"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(read_file(dir_ / "tables" / "lut.ktx2").substr(1, 6), "KTX 20");
  const auto manifest = nlohmann::json::parse(read_file(dir_ / "tables" / "lut.ktx2.json"));
  EXPECT_EQ(manifest["size"], nlohmann::json::array({16, 16}));
  EXPECT_EQ(manifest["precision"], "f32");
  EXPECT_EQ(manifest["energy_compensation"]["average_albedo"].size(), 16u);
  EXPECT_EQ(manifest["energy_compensation"]["basis_hemispherical_averages"].size(), 4u);
}

TEST_F(MatcCli, LutFormatFollowsTheExtensionUnlessGiven) {
  ASSERT_EQ(run({"lut", "-o", "t.dds", "--size", "8", "--samples", "16"}).exit_code, 0);
  EXPECT_EQ(read_file(dir_ / "t.dds").substr(0, 4), "DDS ");
  ASSERT_EQ(
      run({"lut", "-o", "t.bin", "--size", "8", "--samples", "16", "--precision", "f16"}).exit_code,
      0);
  EXPECT_EQ(fs::file_size(dir_ / "t.bin"), 8u * 8u * 4u * 2u);
  const CommandResult unknown = run({"lut", "-o", "t.png"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("cannot infer the format"), std::string::npos) << unknown.err;
  EXPECT_FALSE(fs::exists(dir_ / "t.png"));
  EXPECT_EQ(run({"lut", "-o", "t.ktx2", "--size", "1"}).exit_code, 2);
  EXPECT_EQ(run({"lut", "-o", "t.ktx2", "--precision", "f64"}).exit_code, 2);
}

TEST_F(MatcCli, BatchBuildCanEmitTheLut) {
  write_file(dir_ / "good.json", kGood);
  const std::vector<std::string> args = {
      "-o",         "out", "--emit",        "json,lut", "--lut",    "dds",
      "--lut-size", "8",   "--lut-samples", "32",       "good.json"};
  const CommandResult first = run(args);
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "matc_lut.dds"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "matc_lut.dds.json"));
  const CommandResult second = run(args);
  // good.json, matc_lut.dds and its .json, matc_manifest.json.
  EXPECT_NE(second.err.find("0 files written, 4 unchanged"), std::string::npos) << second.err;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "good.glsl"));
  const auto compiled = nlohmann::json::parse(read_file(dir_ / "out" / "good.json"));
  EXPECT_EQ(compiled["energy_compensation"]["F_avg"].size(), 3u);
}

TEST_F(MatcCli, BasisOptionSelectsTheBasisEverywhereItIsRecorded) {
  write_file(dir_ / "good.json", kGood);
  const auto build = [&](const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> args = {"-o",         out, "--emit",        "json,lut,glsl,header",
                                     "--lut-size", "8", "--lut-samples", "32"};
    args.insert(args.end(), extra.begin(), extra.end());
    args.push_back("good.json");
    const CommandResult result = run(args);
    EXPECT_EQ(result.exit_code, 0) << result.err;
  };
  build("default", {});
  build("extended", {"--basis", "extended"});
  build("paper", {"--basis", "paper"});
  build("f82", {"--basis", "f82"});
  const auto material = [&](const std::string& out) {
    return nlohmann::json::parse(read_file(dir_ / out / "good.json"));
  };
  const auto lut = [&](const std::string& out) {
    return nlohmann::json::parse(read_file(dir_ / out / "matc_lut.ktx2.json"));
  };
  EXPECT_EQ(material("default")["basis"]["name"], "powers");
  EXPECT_EQ(material("default")["basis"]["solve"], "minimax");
  EXPECT_EQ(lut("default")["basis"], "powers");
  EXPECT_EQ(material("extended")["basis"]["name"], "extended");
  EXPECT_EQ(material("extended")["basis"]["solve"], "minimax");
  EXPECT_EQ(lut("extended")["basis"], "extended");
  EXPECT_EQ(material("paper")["basis"]["name"], "paper");
  EXPECT_EQ(material("paper")["basis"]["solve"], "probes");
  EXPECT_EQ(lut("paper")["basis"], "paper");
  EXPECT_EQ(material("f82")["basis"]["name"], "f82");
  EXPECT_EQ(material("f82")["basis"]["solve"], "minimax");
  EXPECT_EQ(lut("f82")["basis"], "f82");
  for (const std::string out : {"default", "extended", "paper", "f82"}) {
    const std::string name = out == "default" ? "powers" : out;
    const auto manifest = nlohmann::json::parse(read_file(dir_ / out / "matc_manifest.json"));
    EXPECT_EQ(manifest["basis"], name);
    EXPECT_NE(read_file(dir_ / out / "good.h").find("#define MATC_good_BASIS \"" + name + "\""),
              std::string::npos);
  }
  // Same F0 (c_0), different shape coefficients, different tables and shader polynomials.
  EXPECT_EQ(material("default")["coefficients"][0][0], material("paper")["coefficients"][0][0]);
  EXPECT_NE(material("default")["coefficients"][0][2], material("paper")["coefficients"][0][2]);
  EXPECT_NE(read_file(dir_ / "default" / "matc_lut.ktx2"),
            read_file(dir_ / "paper" / "matc_lut.ktx2"));
  EXPECT_NE(read_file(dir_ / "default" / "matc_fresnel.glsl"),
            read_file(dir_ / "paper" / "matc_fresnel.glsl"));
  EXPECT_NE(read_file(dir_ / "default" / "matc_fresnel.glsl"),
            read_file(dir_ / "f82" / "matc_fresnel.glsl"));
  EXPECT_EQ(run({"--basis", "schlick", "good.json"}).exit_code, 2);
}

// A low-tint F82-tint material: the default basis warns and names --basis f82; with it, the
// curve is held (no warning) and c_3 = 0, as F82-tint lies in span{b_1, b_2}.
TEST_F(MatcCli, F82BasisHoldsTheF82TintMaterialTheDefaultWarnsAbout) {
  write_file(dir_ / "m.json", R"({"name": "m", "f82_tint": {"f0": 0.9, "tint": 0.2}})");
  const CommandResult by_default = run({"-o", "default", "--emit", "json", "m.json"});
  ASSERT_EQ(by_default.exit_code, 0) << by_default.err;
  EXPECT_NE(by_default.err.find("compile with --basis f82"), std::string::npos) << by_default.err;
  const CommandResult f82 = run({"-o", "f82", "--emit", "json", "--basis", "f82", "m.json"});
  ASSERT_EQ(f82.exit_code, 0) << f82.err;
  EXPECT_EQ(f82.err.find("warning"), std::string::npos) << f82.err;
  const auto compiled = nlohmann::json::parse(read_file(dir_ / "f82" / "m.json"));
  EXPECT_LT(std::abs(compiled["coefficients"][0][3].get<double>()), 1e-4);
  EXPECT_LE(compiled["accuracy"]["decomposition"]["max"][0].get<double>(), 0.002);
}

TEST_F(MatcCli, ReportWritesAPlotAndSamplesPerMaterialAndAnIndex) {
  write_file(dir_ / "good.json", kGood);
  write_file(dir_ / "gold.json", R"({"name": "Gold", "spectral": {"preset": "Au"}})");
  const CommandResult result = run({"report", "-o", "rep", "good.json", "gold.json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* name : {"good.svg", "good.csv", "Gold.svg", "Gold.csv", "index.html"})
    EXPECT_TRUE(fs::exists(dir_ / "rep" / name)) << name;
  const std::string index = read_file(dir_ / "rep" / "index.html");
  EXPECT_NE(index.find("src=\"Gold.svg\""), std::string::npos);
  EXPECT_NE(index.find("basis <code>powers</code>"), std::string::npos);
  const std::string first = read_file(dir_ / "rep" / "Gold.svg");
  ASSERT_EQ(run({"report", "-o", "rep", "good.json", "gold.json"}).exit_code, 0);
  EXPECT_EQ(read_file(dir_ / "rep" / "Gold.svg"), first) << "same inputs, same bytes";
  ASSERT_EQ(run({"report", "-o", "paper", "--basis", "paper", "gold.json"}).exit_code, 0);
  EXPECT_NE(read_file(dir_ / "paper" / "index.html").find("basis <code>paper</code>"),
            std::string::npos);
}

TEST_F(MatcCli, ReportWritesNothingWhenAnyInputIsInvalid) {
  write_file(dir_ / "good.json", kGood);
  write_file(dir_ / "bad.json", kBad);
  const CommandResult bad = run({"report", "-o", "rep", "good.json", "bad.json"});
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("bad.json:3:"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir_ / "rep"));
  write_file(dir_ / "again.json", R"({"name": "GOOD", "ior": {"n": 2, "k": 0}})");
  const CommandResult clash = run({"report", "-o", "rep", "good.json", "again.json"});
  EXPECT_EQ(clash.exit_code, 1);
  EXPECT_NE(clash.err.find("is already used by"), std::string::npos) << clash.err;
  EXPECT_FALSE(fs::exists(dir_ / "rep"));
}

TEST_F(MatcCli, EvalPrintsFbarFromTheTableBesideTheReference) {
  const CommandResult result = run({"eval", std::string(MATC_EXAMPLES_DIR) + "/beryllium.json",
                                    "--ndotv", "0.2,0.9", "--roughness", "0.3,0.7"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_FALSE(json.contains("F"));
  ASSERT_EQ(json["Fbar"].size(), 2u);
  ASSERT_EQ(json["Fbar_reference"].size(), 2u);
  ASSERT_EQ(json["Fbar_analytic"].size(), 2u);
  EXPECT_EQ(json["lut"]["size"], 128);
  for (std::size_t i = 0; i < 2; ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_NEAR(json["Fbar"][i][c].get<double>(), json["Fbar_reference"][i][c].get<double>(),
                  0.02);
      // The closed form follows the table it was fitted to (issue #20: within 0.005).
      EXPECT_NEAR(json["Fbar_analytic"][i][c].get<double>(), json["Fbar"][i][c].get<double>(),
                  0.005);
      EXPECT_NE(json["Fbar_analytic"][i][c].get<double>(), json["Fbar"][i][c].get<double>());
    }
  }
  const CommandResult mismatched = run({"eval", std::string(MATC_EXAMPLES_DIR) + "/gold.json",
                                        "--ndotv", "0.2,0.9", "--roughness", "0.3"});
  EXPECT_EQ(mismatched.exit_code, 2);
  EXPECT_NE(mismatched.err.find("pair up"), std::string::npos) << mismatched.err;
}

// --no-reference drops only the split-sum integral: the table's Fbar is the same numbers.
TEST_F(MatcCli, EvalWithoutTheReferenceKeepsTheTablesFbar) {
  const std::string file = std::string(MATC_EXAMPLES_DIR) + "/beryllium.json";
  const CommandResult with = run({"eval", file, "--ndotv", "0.2,0.9", "--roughness", "0.3,0.7"});
  const CommandResult without =
      run({"eval", file, "--ndotv", "0.2,0.9", "--roughness", "0.3,0.7", "--no-reference"});
  ASSERT_EQ(without.exit_code, 0) << without.err;
  const auto full = nlohmann::json::parse(with.out);
  const auto fast = nlohmann::json::parse(without.out);
  EXPECT_FALSE(fast.contains("Fbar_reference"));
  EXPECT_EQ(fast["Fbar"], full["Fbar"]);
  EXPECT_EQ(run({"eval", file, "--ndotv", "0.5", "--roughness", "0.5", "--no-reference",
                 "--quad-light", "1,0,1;1,1,1;0,1,1;0,0,1"})
                .exit_code,
            2);
}

// Without a Vulkan driver, validation says what is missing, exits 5 and writes nothing.
TEST_F(MatcCli, ValidationWithoutAVulkanDriverIsAClearError) {
  write_file(dir_ / "good.json", kGood);
  const std::vector<std::string> no_driver = {"VK_DRIVER_FILES=/nonexistent/icd.json",
                                              "VK_ICD_FILENAMES=/nonexistent/icd.json"};
  CommandResult result = run({"validate", "good.json"}, no_driver);
  EXPECT_EQ(result.exit_code, 5);
  EXPECT_NE(result.err.find("no Vulkan driver found"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("mesa-vulkan-drivers"), std::string::npos) << result.err;

  result = run({"--validate", "-o", "out", "good.json"}, no_driver);
  EXPECT_EQ(result.exit_code, 5);
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(MatcCli, ValidationNamesTheDevicesWhenNoneMatches) {
  write_file(dir_ / "good.json", kGood);
  const CommandResult result = run({"validate", "--device", "no such device", "good.json"});
  EXPECT_EQ(result.exit_code, 5);
  EXPECT_NE(result.err.find("whose name contains 'no such device' (devices found: "),
            std::string::npos)
      << result.err;
}

// --validate checks on the device before writing, and reports both front ends.
TEST_F(MatcCli, BatchValidatesBeforeWriting) {
  write_file(dir_ / "good.json", kGood);
  const CommandResult result = run({"--validate", "-o", "out", "good.json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("good                 GLSL  F "), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("good                 HLSL  F "), std::string::npos) << result.out;
  EXPECT_TRUE(fs::exists(dir_ / "out" / "good.spv"));
}

TEST_F(MatcCli, ValidateReportsInvalidFilesAndExitsOne) {
  write_file(dir_ / "good.json", kGood);
  write_file(dir_ / "bad.json", kBad);
  const CommandResult result = run({"validate", "good.json", "bad.json"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_NE(result.err.find("bad.json:3:"), std::string::npos) << result.err;
  EXPECT_NE(result.out.find("1 of 1 materials passed on both front ends, 1 files invalid"),
            std::string::npos)
      << result.out;
}

// matc bake: the same maps give the same bytes whatever -j, a second run rewrites nothing, the
// depfile names the outputs and both maps, and a failed bake writes nothing.
TEST_F(MatcCli, BakeIsDeterministicAndItsDepfileNamesTheMaps) {
  std::vector<std::uint8_t> r(32 * 32 * 3), g(32 * 32 * 3);
  for (std::size_t i = 0; i < r.size(); ++i) {
    r[i] = static_cast<std::uint8_t>(i * 37 % 251);
    g[i] = static_cast<std::uint8_t>(i * 91 % 241);
  }
  matc::test::write_file((dir_ / "r.png").string(), matc::test::png_bytes(32, 32, 3, r));
  matc::test::write_file((dir_ / "g.png").string(), matc::test::png_bytes(32, 32, 3, g));
  const std::vector<std::string> maps = {"bake",  "--reflectivity", "r.png", "--edge-tint",
                                         "g.png", "--name",         "metal", "--f0"};
  const auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = maps;
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  const CommandResult first = run(with({"-j", "1", "--MD", "-o", "a"}));
  ASSERT_EQ(first.exit_code, 0) << first.err;
  EXPECT_NE(first.err.find("1 baked (4 files written, 0 unchanged)"), std::string::npos)
      << first.err;
  ASSERT_EQ(run(with({"-j", "2", "-o", "b"})).exit_code, 0);
  for (const char* name : {"metal_c2.ktx2", "metal_c3.ktx2", "metal_f0.ktx2", "metal_bake.json"})
    EXPECT_EQ(read_file(dir_ / "a" / name), read_file(dir_ / "b" / name)) << name;
  const CommandResult again = run(with({"-o", "a"}));
  EXPECT_NE(again.err.find("0 files written, 4 unchanged"), std::string::npos) << again.err;

  const std::string depfile = read_file(dir_ / "a" / "matc_bake.d");
  EXPECT_EQ(depfile.find((dir_ / "a" / "metal_c2.ktx2").string()), 0u) << depfile;
  EXPECT_NE(depfile.find((dir_ / "r.png").string()), std::string::npos) << depfile;
  EXPECT_NE(depfile.find((dir_ / "g.png").string()), std::string::npos) << depfile;

  const nlohmann::json manifest = nlohmann::json::parse(read_file(dir_ / "a" / "metal_bake.json"));
  EXPECT_EQ(manifest["solve"], "exact");
  EXPECT_EQ(manifest["levels"], 6);
  EXPECT_EQ(manifest["inputs"]["reflectivity"]["encoding"], "srgb");

  const CommandResult missing =
      run({"bake", "--reflectivity", "r.png", "--edge-tint", "none.png", "-o", "c"});
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("none.png: error: artistic.edge_tint: cannot read"), std::string::npos)
      << missing.err;
  EXPECT_FALSE(fs::exists(dir_ / "c"));
}

}  // namespace

namespace matc_cli_materialx {

const char* const kMetals = R"(<?xml version="1.0"?>
<materialx version="1.39">
  <standard_surface name="SR_gold" type="surfaceshader">
    <input name="base" type="float" value="1" />
    <input name="base_color" type="color3" value="0.944, 0.776, 0.373" />
    <input name="metalness" type="float" value="1" />
    <input name="specular_color" type="color3" value="0.998, 0.981, 0.751" />
  </standard_surface>
  <surfacematerial name="Gold" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="SR_gold" />
  </surfacematerial>
  <open_pbr_surface name="SR_copper" type="surfaceshader">
    <input name="base_metalness" type="float" value="1" />
    <input name="base_color" type="color3" value="0.926, 0.721, 0.504" />
  </open_pbr_surface>
  <surfacematerial name="Copper" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="SR_copper" />
  </surfacematerial>
</materialx>
)";

}  // namespace matc_cli_materialx

// A document compiles directly (beside material files), and its import compiles to the same
// coefficients: both paths hand the compiler the same material.
TEST_F(MatcCli, MaterialXCompilesDirectlyAndThroughImportAlike) {
  write_file(dir_ / "metals.mtlx", matc_cli_materialx::kMetals);
  write_file(dir_ / "good.json", kGood);
  const CommandResult direct = run({"-q", "-o", "direct", "metals.mtlx", "good.json"});
  ASSERT_EQ(direct.exit_code, 0) << direct.err;
  for (const char* name : {"Gold.json", "Gold.spv", "Copper.glsl", "good.json"})
    EXPECT_TRUE(fs::exists(dir_ / "direct" / name)) << name;
  const CommandResult imported = run({"import", "-q", "-o", "imported", "metals.mtlx"});
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  const CommandResult compiled =
      run({"-q", "-o", "compiled", "imported/Gold.json", "imported/Copper.json"});
  ASSERT_EQ(compiled.exit_code, 0) << compiled.err;
  for (const char* name : {"Gold.json", "Copper.json"}) {
    const auto a = nlohmann::json::parse(read_file(dir_ / "direct" / name));
    const auto b = nlohmann::json::parse(read_file(dir_ / "compiled" / name));
    EXPECT_EQ(a["coefficients"], b["coefficients"]) << name;
    EXPECT_EQ(a["input"], b["input"]) << name;
    EXPECT_EQ(a["source"], "metals.mtlx");
  }
  EXPECT_TRUE(
      nlohmann::json::parse(read_file(dir_ / "imported" / "Copper.json")).contains("f82_tint"));
  // Same document, same bytes.
  const std::string first = read_file(dir_ / "imported" / "Gold.json");
  ASSERT_EQ(run({"import", "-q", "-o", "imported", "metals.mtlx"}).exit_code, 0);
  EXPECT_EQ(read_file(dir_ / "imported" / "Gold.json"), first);
}

// Every command that takes materials takes MaterialX documents: eval (one material, chosen with
// --material) gives what eval of the imported file gives, and validate proves every metal.
TEST_F(MatcCli, EvalAndValidateReadMaterialXDocuments) {
  write_file(dir_ / "metals.mtlx", matc_cli_materialx::kMetals);
  ASSERT_EQ(run({"import", "-q", "-o", "imported", "metals.mtlx"}).exit_code, 0);
  const CommandResult direct =
      run({"eval", "metals.mtlx", "--material", "Copper", "--mu", "0,0.5,1"});
  ASSERT_EQ(direct.exit_code, 0) << direct.err;
  const CommandResult through_import = run({"eval", "imported/Copper.json", "--mu", "0,0.5,1"});
  ASSERT_EQ(through_import.exit_code, 0) << through_import.err;
  const auto a = nlohmann::json::parse(direct.out);
  const auto b = nlohmann::json::parse(through_import.out);
  EXPECT_EQ(a["name"], "Copper");
  EXPECT_EQ(a["F"], b["F"]);
  EXPECT_EQ(a["F_exact"], b["F_exact"]);

  const CommandResult validated = run({"validate", "metals.mtlx"});
  ASSERT_EQ(validated.exit_code, 0) << validated.err << validated.out;
  EXPECT_NE(validated.out.find("2 of 2 materials passed on both front ends"), std::string::npos)
      << validated.out;
}

TEST_F(MatcCli, ColourSpaceIsRecordedAndChangesSpectralNumbers) {
  write_file(dir_ / "gold.json", R"({"name": "Gold", "spectral": {"preset": "Au"}})");
  ASSERT_EQ(run({"-q", "-o", "rec709", "--emit", "json", "gold.json"}).exit_code, 0);
  const CommandResult acescg =
      run({"-q", "-o", "acescg", "--emit", "json", "--color-space", "lin_ap1", "gold.json"});
  ASSERT_EQ(acescg.exit_code, 0) << acescg.err;
  const auto a = nlohmann::json::parse(read_file(dir_ / "rec709" / "Gold.json"));
  const auto b = nlohmann::json::parse(read_file(dir_ / "acescg" / "Gold.json"));
  EXPECT_EQ(a["color"]["working_space"], "lin_rec709");
  EXPECT_EQ(b["color"]["working_space"], "acescg");
  EXPECT_FALSE(a["color"]["within_unit_range"].get<bool>());
  EXPECT_TRUE(b["color"]["within_unit_range"].get<bool>());
  EXPECT_NE(a["coefficients"], b["coefficients"]);
  EXPECT_EQ(nlohmann::json::parse(
                read_file(dir_ / "acescg" / "matc_manifest.json"))["color"]["working_space"],
            "acescg");
  EXPECT_EQ(acescg.err.find("note:"), std::string::npos) << "gold is inside ACEScg";
}
