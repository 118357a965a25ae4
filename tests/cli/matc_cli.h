// The fixture of the CLI suites (one file per command, tests/cli/): runs the matc binary in a
// fresh directory per test and reads what it printed and wrote.
#pragma once

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

#include "emit/output_layout.h"
#include "example_files.h"
#include "lut/lut_files.h"
#include "options/option_names.h"
#include "test_images.h"

namespace matc::cli_test {

namespace fs = std::filesystem;

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_file(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// Single-quotes a word for the shell. Built with append(): GCC 12 warns falsely (-Wrestrict,
// PR 105329) on chains of std::string operator+.
inline std::string quote(const std::string& word) {
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

inline constexpr const char* kGood = R"({"name": "good", "ior": {"n": 1.5, "k": 0}})";
inline constexpr const char* kBad =
    "{\n  \"name\": \"bad\",\n  \"ior\": {\"n\": -1, \"k\": 0}\n}\n";

}  // namespace matc::cli_test
