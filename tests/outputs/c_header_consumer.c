/* The generated headers compiled as C99: two materials in one translation unit. */
#include "beryllium.h"
#include "gold.h"

const MatcFresnelCoefficients* gold_coefficients_from_c(void) {
  return &matc_coefficients_gold;
}
const uint32_t* gold_spirv_from_c(void) {
  return matc_spirv_gold;
}
unsigned long gold_spirv_words_from_c(void) {
  return (unsigned long)(sizeof matc_spirv_gold / sizeof matc_spirv_gold[0]);
}
const char* beryllium_lut_file_from_c(void) {
  return MATC_beryllium_LUT_FILE;
}
