
// A thickness per pixel: {{film_slices}} slices of films over [{{film_minimum}}, {{film_maximum}}] nm in
// {{name}}.film.<ext> (docs/thin-film.md). thickness: the coordinate in [0, 1] over that range
// (the thickness texture's green channel). Linear over the thickness, F is within
// {{film_stack_error}} of the exact film midway between slices. Fetch the texels with
//   matc_film_stack_fresnel(film, film_sampler, mu, thickness, matc_film_slices_{{name}})
//   matc_film_stack_preintegrated(film, film_sampler, NdotV, roughness, thickness,
//                                 matc_film_slices_{{name}})
const matc_film_slices_{{name}}: f32 = {{film_slices}}.0;

// The thickness coordinate of a film of `nm` nanometres.
fn matc_film_thickness_{{name}}(nm: f32) -> f32 {
  return clamp((nm - {{film_minimum_float}}) * (1.0 / ({{film_maximum_float}} - {{film_minimum_float}})), 0.0, 1.0);
}
