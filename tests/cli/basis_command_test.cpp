// The matc binary end to end, `matc basis`: its JSON and the paper basis' probes.
#include "matc_cli.h"

namespace matc::cli_test {
namespace {

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
}  // namespace
}  // namespace matc::cli_test
