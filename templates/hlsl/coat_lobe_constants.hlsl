// The coat's dielectric Fresnel (index {{coat_ior}}); largest |F - exact|: {{coat_max_error}}.
static const float4 matc_coat_coefficients_{{name}} = float4({{coat}});
static const float matc_coat_weight_{{name}} = {{coat_weight}};
// Sample the table at this roughness for the coat lobe (perceptual, as matc_lut_texcoord takes).
static const float matc_coat_roughness_{{name}} = {{coat_roughness}};
