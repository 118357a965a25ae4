// The coat lobe's F for a direct light, its weight included: mu = dot(V, H).
fn matc_coat_fresnel_{{name}}(mu: f32) -> f32 {
  let f = clamp(dot(matc_coat_coefficients_{{name}}, matc_basis(mu)), 0.0, 1.0);
  return matc_coat_weight_{{name}} * f;
}

// glTF's metal-rough model under this coat (docs/gltf.md): the engine's dielectric is layered as
// glTF layers a clear coat, everything it reflects (its diffuse too) times
// matc_coat_transmission_{{name}}(NdotV), 1 - the coat lobe's F at NdotV; the metal's part is this
// material's base lobe (the metal through the coat). matc_metal_rough_{{name}} mixes a lobe's
// dielectric term and this material's base lobe (F or preintegrated F) by metalness.
fn matc_coat_transmission_{{name}}(NdotV: f32) -> f32 {
  return 1.0 - matc_coat_fresnel_{{name}}(NdotV);
}
fn matc_metal_rough_{{name}}(dielectric: vec3f, metal: vec3f, metalness: f32, NdotV: f32) -> vec3f {
  return matc_metal_rough(dielectric * matc_coat_transmission_{{name}}(NdotV), metal, metalness);
}
