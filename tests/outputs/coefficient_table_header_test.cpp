// The coefficient table as `matc --emit coefficient-table --lut header` writes it: the header
// compiles and holds the runtime's table bit for bit, and its manifest describes the layout the
// runtime and the shaders read.
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "matc/runtime/coefficient_table.h"
#include "matc_coefficient_table.h"  // generated at build time by tests/CMakeLists.txt

namespace {

TEST(CoefficientTableHeader, HoldsTheRuntimeTableBitForBit) {
  const matc::runtime::CoefficientTableView table = matc::runtime::shipped_coefficient_table();
  ASSERT_EQ(matc_coefficient_table::kSize, table.size);
  ASSERT_EQ(std::size(matc_coefficient_table::kTexels), table.texels.size());
  for (std::size_t i = 0; i < table.texels.size(); ++i)
    ASSERT_EQ(matc_coefficient_table::kTexels[i], table.texels[i]) << "texel value " << i;
}

TEST(CoefficientTableHeader, ManifestDescribesTheLayout) {
  std::ifstream in(MATC_TABLE_MANIFEST);
  const nlohmann::json manifest = nlohmann::json::parse(in);
  EXPECT_EQ(manifest["kind"], "matc Fresnel coefficient table");
  EXPECT_EQ(manifest["format"], "header");
  EXPECT_EQ(manifest["precision"], "f32");
  EXPECT_EQ(manifest["basis"], "powers");
  const std::size_t size = matc::runtime::shipped_coefficient_table().size;
  EXPECT_EQ(manifest["size"], nlohmann::json::array({size, size}));
  EXPECT_EQ(manifest["channels"], nlohmann::json::array({"c_2", "c_3"}));
  EXPECT_NE(manifest["layout"]["rows"].get<std::string>().find("1 - sqrt(1 - g)"),
            std::string::npos);
  EXPECT_NE(manifest["layout"]["columns"].get<std::string>().find("(r^(1/4) + r^2) / 2"),
            std::string::npos);
}

}  // namespace
