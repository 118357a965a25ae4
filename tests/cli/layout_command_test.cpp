// The matc binary end to end, `matc layout`: the file names a compile writes and the CMake and
// Bazel lists.
#include "matc_cli.h"

namespace matc::cli_test {
namespace {

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
}  // namespace
}  // namespace matc::cli_test
