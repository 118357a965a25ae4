// The LTC table as `matc --emit ltc --lut header` writes it: the header compiles and holds the
// runtime's table bit for bit, and its manifest describes the layout the shaders read.
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "matc/runtime/ltc.h"
#include "matc_ltc.h"  // generated at build time by tests/CMakeLists.txt

namespace {

TEST(LtcHeader, HoldsTheRuntimeTableBitForBit) {
  const matc::runtime::LtcTableView table = matc::runtime::shipped_ltc_table();
  ASSERT_EQ(matc_ltc::kSize, table.size);
  ASSERT_EQ(std::size(matc_ltc::kTexels), table.texels.size());
  for (std::size_t i = 0; i < table.texels.size(); ++i)
    ASSERT_EQ(matc_ltc::kTexels[i], table.texels[i]) << "texel value " << i;
}

TEST(LtcHeader, ManifestDescribesTheLayout) {
  std::ifstream in(MATC_LTC_MANIFEST);
  const nlohmann::json manifest = nlohmann::json::parse(in);
  EXPECT_EQ(manifest["format"], "header");
  EXPECT_EQ(manifest["precision"], "f32");
  const std::size_t size = matc::runtime::shipped_ltc_table().size;
  EXPECT_EQ(manifest["size"], nlohmann::json::array({size, size}));
  EXPECT_EQ(manifest["channels"], nlohmann::json::array({"a", "b", "c", "d"}));
  EXPECT_NE(manifest["matrix"].get<std::string>().find("[[a, 0, b], [0, 1, 0], [c, 0, d]]"),
            std::string::npos);
  EXPECT_NE(manifest["layout"]["columns"].get<std::string>().find("u = 1 - sqrt(1 - NdotV)"),
            std::string::npos);
}

}  // namespace
