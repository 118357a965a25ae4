// The matc binary end to end, `matc validate` and `matc --validate`: clear errors without a driver
// or a matching device, validation before writing, invalid files.
#include "matc_cli.h"

namespace matc::cli_test {
namespace {

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
}  // namespace
}  // namespace matc::cli_test
