// The coat's dielectric Fresnel (index {{coat_ior}}); largest |F - exact|: {{coat_max_error}}.
const matc_coat_coefficients_{{name}} = vec4f({{coat}});
const matc_coat_weight_{{name}} = {{coat_weight}};
// Sample the table at this roughness for the coat lobe (perceptual, as matc_lut_texcoord takes).
const matc_coat_roughness_{{name}} = {{coat_roughness}};
