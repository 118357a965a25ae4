// The C/C++ headers matc writes: they compile as C99 and C++20, hold the coefficients the
// compiler solved (rounded to float), the LUT reference, and a valid SPIR-V library module.
#include <gtest/gtest.h>

#include "beryllium.h"
#include "compile/compile.h"
#include "gold.h"
#include "material/parse.h"
#include "spirv/spirv_tools.h"

extern "C" {
const MatcFresnelCoefficients* gold_coefficients_from_c(void);
const uint32_t* gold_spirv_from_c(void);
unsigned long gold_spirv_words_from_c(void);
const char* beryllium_lut_file_from_c(void);
}

namespace matc {
namespace {

TEST(GeneratedHeader, CoefficientsAreTheCompiledOnesAsFloats) {
  const ParseResult parsed = read_material_file(MATC_EXAMPLES_DIR "/gold.json");
  ASSERT_TRUE(parsed.material);
  const CompiledMaterial compiled = compile_material(*parsed.material, runtime::shipped_basis());
  const float* rows[3] = {matc_coefficients_gold.red, matc_coefficients_gold.green,
                          matc_coefficients_gold.blue};
  for (std::size_t channel = 0; channel < 3; ++channel) {
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_EQ(rows[channel][i], static_cast<float>(compiled.coefficients[channel][i]))
          << "channel " << channel << ", c_" << i;
    }
  }
  static_assert(sizeof(MatcFresnelCoefficients) == 48, "the shaders' std140 layout");
}

TEST(GeneratedHeader, CAndCppSeeTheSameData) {
  const MatcFresnelCoefficients* from_c = gold_coefficients_from_c();
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(from_c->red[i], matc_coefficients_gold.red[i]);
    EXPECT_EQ(from_c->blue[i], matc_coefficients_gold.blue[i]);
  }
  EXPECT_EQ(gold_spirv_words_from_c(), std::size(matc_spirv_gold));
  EXPECT_STREQ(beryllium_lut_file_from_c(), "matc_lut.ktx2");
  EXPECT_EQ(MATC_gold_LUT_SIZE, 16);
  EXPECT_STREQ(MATC_gold_MATC_VERSION, MATC_VERSION);
  EXPECT_EQ(std::string(MATC_gold_INPUTS_HASH).size(), 16u);
}

TEST(GeneratedHeader, SpirvWordsAreAValidLibraryModule) {
  const SpirvWords words(gold_spirv_from_c(), gold_spirv_from_c() + gold_spirv_words_from_c());
  EXPECT_EQ(words[0], 0x07230203u);
  EXPECT_NO_THROW(validate_spirv(words, SpirvTarget::universal_1_3, "gold.h"));
  EXPECT_NE(disassemble_spirv(words).find("\"matc_fresnel_gold\" Export"), std::string::npos);
}

}  // namespace
}  // namespace matc
