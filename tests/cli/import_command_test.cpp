// The matc binary end to end, `matc import` and MaterialX inputs: a document compiled directly and
// through the import alike, eval and validate reading documents.
#include "matc_cli.h"

namespace matc::cli_test {
namespace {

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

// A document compiles directly (beside material files), and its import compiles to the same
// coefficients: both paths hand the compiler the same material.
TEST_F(MatcCli, MaterialXCompilesDirectlyAndThroughImportAlike) {
  write_file(dir_ / "metals.mtlx", kMetals);
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
  write_file(dir_ / "metals.mtlx", kMetals);
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
}  // namespace
}  // namespace matc::cli_test
