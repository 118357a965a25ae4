// The matc binary end to end, `matc bake`: deterministic textures, a depfile that names the maps,
// located map errors.
#include "matc_cli.h"

namespace matc::cli_test {
namespace {

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
}  // namespace matc::cli_test
