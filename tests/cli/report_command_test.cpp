// The matc binary end to end, `matc report`: plots, samples, the index, nothing written for invalid
// inputs.
#include "matc_cli.h"

namespace matc::cli_test {
namespace {

TEST_F(MatcCli, ReportWritesAPlotAndSamplesPerMaterialAndAnIndex) {
  write_file(dir_ / "good.json", kGood);
  write_file(dir_ / "gold.json", R"({"name": "Gold", "spectral": {"preset": "Au"}})");
  const CommandResult result = run({"report", "-o", "rep", "good.json", "gold.json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* name : {"good.svg", "good.csv", "Gold.svg", "Gold.csv", "index.html"})
    EXPECT_TRUE(fs::exists(dir_ / "rep" / name)) << name;
  const std::string index = read_file(dir_ / "rep" / "index.html");
  EXPECT_NE(index.find("src=\"Gold.svg\""), std::string::npos);
  // The default gives each material its basis: measured gold powers.
  EXPECT_NE(index.find("basis <code>auto</code>"), std::string::npos);
  const std::string first = read_file(dir_ / "rep" / "Gold.svg");
  EXPECT_NE(first.find("basis powers"), std::string::npos);
  ASSERT_EQ(run({"report", "-o", "rep", "good.json", "gold.json"}).exit_code, 0);
  EXPECT_EQ(read_file(dir_ / "rep" / "Gold.svg"), first) << "same inputs, same bytes";
  write_file(dir_ / "tinted.json", R"({"name": "tinted", "f82_tint": {"f0": 0.9, "tint": 0.3}})");
  ASSERT_EQ(run({"report", "-o", "tinted", "tinted.json"}).exit_code, 0);
  EXPECT_NE(read_file(dir_ / "tinted" / "tinted.svg").find("basis f82"), std::string::npos);
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
}  // namespace
}  // namespace matc::cli_test
