// The matc binary end to end, the compile (matc FILES...): outputs, manifests, determinism,
// depfiles, --emit, names, safety, --basis, --color-space, usage errors.
#include <signal.h>

#include <chrono>
#include <thread>

#include <fmt/format.h>

#include "matc_cli.h"

namespace matc::cli_test {
namespace {

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

// matc removes only files it created: not a temporary of the form its writers once used whose
// process is gone (it may be a writer in another pid namespace, or an input), not a user's file,
// not a guess at today's form.
TEST_F(MatcCli, LeavesEveryFileItDidNotCreate) {
  write_file(dir_ / "m" / "good.json", kGood);
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ASSERT_EQ(::waitpid(child, nullptr, 0), child);  // its process id now names no process
  const std::vector<fs::path> planted = {
      dir_ / "out" / (".good.glsl.tmp" + std::to_string(child)), dir_ / "out" / ".notes.tmp7",
      dir_ / "out" / ".good.hlsl.matc-0123456789abcdef.tmp",
      dir_ / "out" / ".matc_manifest.entries.matc-fedcba9876543210.tmp"};
  for (const fs::path& path : planted)
    write_file(path, "not matc's");
  ASSERT_EQ(run({"-q", "-o", "out", "m/good.json"}).exit_code, 0);
  for (const fs::path& path : planted)
    EXPECT_EQ(read_file(path), "not matc's") << path;
  // And it left none of its own.
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir_ / "out"))
    files += entry.path().filename().string().find(".matc-") == std::string::npos ? 1 : 0;
  EXPECT_EQ(files, 17u + 2u);  // its 17 and the two planted files of other forms
}

// `count` metals of different indices written as m/m<i>.json under `directory`; their paths
// relative to it.
std::vector<std::string> write_metal_batch(const fs::path& directory, int count) {
  std::vector<std::string> files;
  for (int i = 0; i < count; ++i) {
    const std::string name = fmt::format("m{:04}", i);
    write_file(directory / "m" / (name + ".json"),
               fmt::format(R"({{"name": "{}", "ior": {{"n": {}, "k": 3}}}})", name,
                           0.2 + i * 2.0 / count));
    files.push_back("m/" + name + ".json");
  }
  return files;
}

// matc started with `args` in `directory` as a child process (to be signalled); its pid.
pid_t start_matc(const fs::path& directory, const std::vector<std::string>& args) {
  const pid_t child = ::fork();
  if (child == 0) {
    ::chdir(directory.c_str());
    std::vector<char*> argv = {const_cast<char*>(MATC_BINARY)};
    for (const std::string& arg : args)
      argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    ::execv(MATC_BINARY, argv.data());
    ::_exit(127);
  }
  return child;
}

// Ctrl-C (SIGINT) or SIGTERM mid-run: matc removes the temporaries it had in flight, nothing
// else, and dies of the signal. Whenever the signal lands, no temporary may remain.
TEST_F(MatcCli, AnInterruptedRunRemovesItsTemporariesAndNothingElse) {
  std::vector<std::string> args = {"-q", "-j", "2", "-o", "out"};
  for (const std::string& file : write_metal_batch(dir_, 200))
    args.push_back(file);
  write_file(dir_ / "out" / ".notes.tmp7", "not matc's");
  for (const int signal : {SIGINT, SIGTERM}) {
    const pid_t child = start_matc(dir_, args);
    ASSERT_GT(child, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ::kill(child, signal);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE((WIFSIGNALED(status) && WTERMSIG(status) == signal) ||
                (WIFEXITED(status) && WEXITSTATUS(status) == 0))
        << status;
    for (const auto& entry : fs::directory_iterator(dir_ / "out"))
      EXPECT_EQ(entry.path().filename().string().find(".matc-"), std::string::npos) << entry.path();
    EXPECT_EQ(read_file(dir_ / "out" / ".notes.tmp7"), "not matc's");
  }
}

// A run killed outright (SIGKILL: a build system cancelling an action, a CI time-out) cannot
// clean up, so its files have no name until they are complete (O_TMPFILE): eight kills at
// different moments of a 1,000-material batch, then a complete run, leave no temporary, and the
// complete run's files equal a run's that was never killed.
TEST_F(MatcCli, RunsKilledOutrightLeaveNoTemporaries) {
  std::vector<std::string> args = {"-q", "-j", "2", "-o", "out"};
  for (const std::string& file : write_metal_batch(dir_, 1000))
    args.push_back(file);
  int killed = 0;
  for (int kill = 0; kill < 8; ++kill) {
    const pid_t child = start_matc(dir_, args);
    ASSERT_GT(child, 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(40 + 45 * kill));
    ::kill(child, SIGKILL);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    killed += WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL ? 1 : 0;
  }
  EXPECT_GE(killed, 4);  // most kills land mid-run (a finished run is no test of this)
  const CommandResult complete = run(args);
  ASSERT_EQ(complete.exit_code, 0) << complete.err;
  std::vector<std::string> fresh = args;
  fresh[4] = "fresh";
  ASSERT_EQ(run(fresh).exit_code, 0);
  std::size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir_ / "out")) {
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(name.find(".matc-"), std::string::npos) << name;
    EXPECT_EQ(read_file(entry.path()), read_file(dir_ / "fresh" / name)) << name;
    ++files;
  }
  EXPECT_EQ(files, 1000u * 6 + 11);  // six per material, the shared files and the manifest
}

// With -k a material whose files cannot all be written leaves none of them (all or none), and
// the other materials are written whole.
TEST_F(MatcCli, KeepGoingWritesEachMaterialAllOrNone) {
  write_file(dir_ / "m" / "a.json", R"({"name": "a", "ior": {"n": 0.2, "k": 3}})");
  write_file(dir_ / "m" / "b.json", R"({"name": "b", "ior": {"n": 0.3, "k": 3}})");
  fs::create_directories(dir_ / "out" / "b.spv" / "in_the_way");  // b's SPIR-V cannot be written
  const CommandResult result = run({"-q", "-k", "-o", "out", "m/a.json", "m/b.json"});
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_NE(result.err.find("b.spv"), std::string::npos) << result.err;
  for (const char* extension : {".json", ".glsl", ".hlsl", ".wgsl", ".spv", ".h"}) {
    EXPECT_TRUE(fs::is_regular_file(dir_ / "out" / (std::string("a") + extension))) << extension;
    if (std::string(extension) != ".spv") {
      EXPECT_FALSE(fs::exists(dir_ / "out" / (std::string("b") + extension))) << extension;
    }
  }
  for (const auto& entry : fs::directory_iterator(dir_ / "out"))
    EXPECT_EQ(entry.path().filename().string().find(".matc-"), std::string::npos) << entry.path();
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
  // Six files a material, the filmed examples' own tables (one bare, one under a coat) and ten
  // shared files.
  EXPECT_EQ(compared, files.size() * 6 + 2 + 10);
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
  // Six files a material, the filmed examples' own tables, ten shared files and the manifest.
  EXPECT_EQ(compared, files.size() * 6 + 2 + 11);
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

TEST_F(MatcCli, UsageErrorsExitTwo) {
  EXPECT_EQ(run({}).exit_code, 2);
  EXPECT_EQ(run({"--no-such-flag", "x.json"}).exit_code, 2);
  EXPECT_EQ(run({"eval"}).exit_code, 2);
  const CommandResult version = run({"--version"});
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_EQ(version.out, "matc " MATC_VERSION "\n");
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
  build("powers", {"--basis", "powers"});
  build("extended", {"--basis", "extended"});
  build("paper", {"--basis", "paper"});
  build("f82", {"--basis", "f82"});
  const auto material = [&](const std::string& out) {
    return nlohmann::json::parse(read_file(dir_ / out / "good.json"));
  };
  const auto lut = [&](const std::string& out) {
    return nlohmann::json::parse(read_file(dir_ / out / "matc_lut.ktx2.json"));
  };
  // The default gives each material its basis (powers for this one) and the table a layer each.
  EXPECT_EQ(material("default")["basis"]["name"], "powers");
  EXPECT_EQ(material("default")["basis"]["solve"], "minimax");
  EXPECT_EQ(material("default")["basis"]["lut_layer"], 0);
  EXPECT_EQ(lut("default")["basis"], "auto");
  EXPECT_EQ(material("powers")["basis"]["name"], "powers");
  EXPECT_FALSE(material("powers")["basis"].contains("lut_layer"));
  EXPECT_EQ(lut("powers")["basis"], "powers");
  EXPECT_EQ(material("extended")["basis"]["name"], "extended");
  EXPECT_EQ(material("extended")["basis"]["solve"], "minimax");
  EXPECT_EQ(lut("extended")["basis"], "extended");
  EXPECT_EQ(material("paper")["basis"]["name"], "paper");
  EXPECT_EQ(material("paper")["basis"]["solve"], "probes");
  EXPECT_EQ(lut("paper")["basis"], "paper");
  EXPECT_EQ(material("f82")["basis"]["name"], "f82");
  EXPECT_EQ(material("f82")["basis"]["solve"], "minimax");
  EXPECT_EQ(lut("f82")["basis"], "f82");
  for (const std::string out : {"default", "powers", "extended", "paper", "f82"}) {
    const std::string name = out == "default" ? "powers" : out;
    const auto manifest = nlohmann::json::parse(read_file(dir_ / out / "matc_manifest.json"));
    EXPECT_EQ(manifest["basis"], out == "default" ? "auto" : name);
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

// A low-tint F82-tint material: by default (a basis per material, as --basis auto) and with --basis
// f82 the curve is held (no warning) and c_3 = 0, as F82-tint lies in span{b_1, b_2}; --basis
// powers forced on it warns and names --basis auto.
TEST_F(MatcCli, F82BasisHoldsTheF82TintMaterialPowersWarnsAbout) {
  write_file(dir_ / "m.json", R"({"name": "m", "f82_tint": {"f0": 0.9, "tint": 0.2}})");
  const CommandResult forced =
      run({"-o", "powers", "--emit", "json", "--basis", "powers", "m.json"});
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_NE(forced.err.find("compile with --basis auto"), std::string::npos) << forced.err;
  for (const std::string basis : {"default", "f82", "auto"}) {
    std::vector<std::string> args = {"-o", basis, "--emit", "json", "m.json"};
    if (basis != "default") args.insert(args.begin(), {"--basis", basis});
    const CommandResult held = run(args);
    ASSERT_EQ(held.exit_code, 0) << held.err;
    EXPECT_EQ(held.err.find("warning"), std::string::npos) << held.err;
    const auto compiled = nlohmann::json::parse(read_file(dir_ / basis / "m.json"));
    EXPECT_EQ(compiled["basis"]["name"], "f82");
    EXPECT_LT(std::abs(compiled["coefficients"][0][3].get<double>()), 1e-4);
    EXPECT_LE(compiled["accuracy"]["decomposition"]["max"][0].get<double>(), 0.002);
  }
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
}  // namespace
}  // namespace matc::cli_test
