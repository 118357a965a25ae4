/* matc {{version}}: material {{name}} from {{source_file}}. Generated (inputs {{inputs_hash}});
 * do not edit, rerun matc. C99 and C++; no dependency beside <stdint.h>. */
#ifndef MATC_MATERIAL_{{name}}_H
#define MATC_MATERIAL_{{name}}_H

#include <stdint.h>

#ifndef MATC_FRESNEL_COEFFICIENTS_DEFINED
#define MATC_FRESNEL_COEFFICIENTS_DEFINED
/* c_0..c_3 per colour channel; the layout of the shaders' MatcFresnelCoefficients (48 bytes,
 * std140/std430/HLSL constant buffer), ready to copy into a uniform buffer. */
typedef struct MatcFresnelCoefficients {
  float red[4];
  float green[4];
  float blue[4];
} MatcFresnelCoefficients;
#endif

#define MATC_{{name}}_MATC_VERSION "{{version}}"
#define MATC_{{name}}_INPUTS_HASH "{{inputs_hash}}"

/* F0 = ({{f0}}) in {{color_space}}; largest |F - exact Fresnel| over 2001 cosines: {{max_error}}. */
static const MatcFresnelCoefficients matc_coefficients_{{name}} = {
    {{red_c}},
    {{green_c}},
    {{blue_c}}};{{coat_block}}{{film_block}}

/* The preintegrated table these coefficients are sampled with. */
#define MATC_{{name}}_LUT_FILE "{{lut_file}}"
#define MATC_{{name}}_LUT_SIZE {{lut_size}}
#define MATC_{{name}}_LUT_HASH "{{lut_hash}}"
/* The Fresnel basis both belong to (matc --basis). */
#define MATC_{{name}}_BASIS "{{basis}}"{{lut_layer}}

/* {{name}}.spv: a SPIR-V library module (Linkage capability) exporting matc_fresnel_{{name}} and
 * matc_fresnel_preintegrated_{{name}}, for linking with spirv-link or spvtools::Link. */
static const uint32_t matc_spirv_{{name}}[{{spirv_word_count}}] = {
{{spirv_words}}};

#endif /* MATC_MATERIAL_{{name}}_H */
