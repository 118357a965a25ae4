// The matc binary end to end, `matc lut`: the table, its manifest, its format.
#include "matc_cli.h"

namespace matc::cli_test {
namespace {

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
}  // namespace
}  // namespace matc::cli_test
