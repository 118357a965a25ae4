// The matc binary end to end, `matc eval`: decomposed and exact Fresnel, Fbar from the table, its
// bad inputs.
#include <cmath>

#include "matc_cli.h"

namespace matc::cli_test {
namespace {

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

// --no-reference drops only the Monte-Carlo references: the table's Fbar and the quad light's LTC
// radiance are the same numbers.
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
  const std::string quad = "1,0,1;1,1,1;0,1,1;0,0,1";
  for (const std::string& material :
       {file, std::string(MATC_EXAMPLES_DIR) + "/copper_lacquered.json"}) {
    const std::vector<std::string> lit = {
        "eval",    material,       "--ndotv", "0.5,0.8",         "--roughness",
        "0.5,0.3", "--quad-light", quad,      "--light-samples", "16"};
    const CommandResult referenced = run(lit);
    std::vector<std::string> unreferenced_arguments = lit;
    unreferenced_arguments.push_back("--no-reference");
    const CommandResult unreferenced = run(unreferenced_arguments);
    ASSERT_EQ(unreferenced.exit_code, 0) << unreferenced.err;
    const auto reference = nlohmann::json::parse(referenced.out);
    const auto shaders_only = nlohmann::json::parse(unreferenced.out);
    const bool coated = reference.contains("coat");
    for (const char* key : {"L_reference", "L_reference_standard_error", "L_ltc_exact_fresnel",
                            "Fbar_reference", "Fbar_layered_reference"})
      EXPECT_FALSE(shaders_only.contains(key)) << material << ": " << key;
    EXPECT_FALSE(shaders_only["quad_light"].contains("reference_samples"));
    EXPECT_TRUE(reference.contains("L_reference"));
    EXPECT_EQ(shaders_only["quad_light"]["vertices"], reference["quad_light"]["vertices"]);
    for (const char* key :
         coated ? std::vector<const char*>{"L_ltc", "L_ltc_base", "L_ltc_coat"}
                : std::vector<const char*>{"L_ltc", "L_ltc_following", "L_ltc_schlick"}) {
      ASSERT_TRUE(reference.contains(key)) << material << ": " << key;
      EXPECT_EQ(shaders_only[key], reference[key]) << material << ": " << key;
    }
  }
}

// A coated material: both lobes and their sum, for direct lights and from the table (what the web
// engines' probe tests compare renders with, lobe by lobe), and the exact curve of each lobe.
// --metalness: glTF's metal-rough mix with glTF's dielectric (F0 0.04, F90 1). At 0 it is the
// dielectric, at 1 the metal, between them the linear mix; the dielectric's Fbar is Schlick's
// split sum (at roughness 0, its F at NdotV). Refused for a coated metal, the coefficient-table
// path, and outside [0, 1].
TEST_F(MatcCli, EvalMixesTheMetalWithGltfsDielectricByMetalness) {
  const std::string chromium = std::string(MATC_EXAMPLES_DIR) + "/chromium.json";
  const auto eval = [&](const std::string& metalness) {
    const CommandResult result =
        run({"eval", chromium, "--mu", "0.1,0.5,1", "--ndotv", "0.3,1", "--roughness", "0,0.6",
             "--no-reference", "--metalness", metalness});
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return nlohmann::json::parse(result.out);
  };
  const auto none = eval("0"), full = eval("1"), quarter = eval("0.25");
  for (const char* key : {"F", "Fbar"}) {
    const std::string term = key;
    for (std::size_t i = 0; i < full[term].size(); ++i) {
      for (std::size_t c = 0; c < 3; ++c) {
        const double metal = full[term][i][c], dielectric = none[term + "_dielectric"][i][c];
        EXPECT_DOUBLE_EQ(full[term + "_metal_rough"][i][c].get<double>(), metal);
        EXPECT_DOUBLE_EQ(none[term + "_metal_rough"][i][c].get<double>(), dielectric);
        EXPECT_NEAR(quarter[term + "_metal_rough"][i][c].get<double>(),
                    0.75 * dielectric + 0.25 * metal, 1e-15);
      }
    }
  }
  // Schlick's curve from 0.04 to 1, and its split sum at roughness 0 (a mirror: F at NdotV).
  EXPECT_NEAR(none["F_dielectric"][0][0].get<double>(), 0.04 + 0.96 * std::pow(0.9, 5), 1e-15);
  EXPECT_NEAR(none["F_dielectric"][2][1].get<double>(), 0.04, 1e-15);
  EXPECT_NEAR(none["Fbar_dielectric"][0][2].get<double>(), 0.04 + 0.96 * std::pow(0.7, 5), 2e-3);
  EXPECT_EQ(quarter["metalness"], 0.25);
  EXPECT_EQ(run({"eval", chromium, "--mu", "0.5", "--metalness", "1.5"}).exit_code, 2);
  EXPECT_EQ(run({"eval", chromium, "--mu", "0.5", "--metalness", "nan"}).exit_code, 2);
  // A coated metal: the coat lobe over the mix, the dielectric under the coat's transmission
  // (1 - the coat lobe's F at NdotV, here mu), the metal's part the base lobe.
  const CommandResult coated =
      run({"eval", std::string(MATC_EXAMPLES_DIR) + "/copper_lacquered.json", "--mu", "0.2,0.5,1",
           "--no-reference", "--metalness", "0.5"});
  ASSERT_EQ(coated.exit_code, 0) << coated.err;
  const auto layered = nlohmann::json::parse(coated.out);
  for (std::size_t i = 0; i < 3; ++i) {
    const double coat = layered["F_coat"][i].get<double>();
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_NEAR(layered["F_metal_rough"][i][c].get<double>(),
                  coat + 0.5 * (1.0 - coat) * layered["F_dielectric"][i][c].get<double>() +
                      0.5 * layered["F_base"][i][c].get<double>(),
                  1e-15);
    }
  }
  EXPECT_EQ(run({"eval", "--reflectivity", "0.5", "--edge-tint", "0.5", "--mu", "0.5",
                 "--metalness", "0.5"})
                .exit_code,
            2);
}

TEST_F(MatcCli, EvalPrintsBothLobesOfACoatedMaterialAndTheirSum) {
  const CommandResult result =
      run({"eval", std::string(MATC_EXAMPLES_DIR) + "/copper_lacquered.json", "--mu", "0.3,0.9",
           "--ndotv", "0.3,0.9", "--roughness", "0.3,0.3", "--no-reference"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const auto json = nlohmann::json::parse(result.out);
  EXPECT_EQ(json["coat"]["roughness"], 0.1);
  for (std::size_t i = 0; i < 2; ++i) {
    const double coat = json["F_coat"][i].get<double>();
    const double coat_bar = json["Fbar_coat"][i].get<double>();
    EXPECT_GT(coat, 0.03);
    EXPECT_GT(coat_bar, 0.03);
    for (std::size_t c = 0; c < 3; ++c) {
      EXPECT_DOUBLE_EQ(json["F"][i][c].get<double>(), json["F_base"][i][c].get<double>() + coat);
      EXPECT_DOUBLE_EQ(json["Fbar"][i][c].get<double>(),
                       json["Fbar_base"][i][c].get<double>() + coat_bar);
      EXPECT_NEAR(json["F"][i][c].get<double>(), json["F_exact"][i][c].get<double>(), 0.003);
      // The exact curve lobe by lobe: what the web engines' references integrate apart.
      const double exact_coat = json["F_exact_coat"][i].get<double>();
      EXPECT_NEAR(json["F_exact_base"][i][c].get<double>() + exact_coat,
                  json["F_exact"][i][c].get<double>(), 1e-15);
      EXPECT_NEAR(json["F_base"][i][c].get<double>(), json["F_exact_base"][i][c].get<double>(),
                  0.003);
      EXPECT_NEAR(coat, exact_coat, 0.003);
    }
  }
}
}  // namespace
}  // namespace matc::cli_test
