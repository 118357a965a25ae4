
// A thickness per pixel: {{film_slices}} slices of films over [{{film_minimum}}, {{film_maximum}}] nm in
// {{name}}.film.<ext> (docs/thin-film.md). thickness: the coordinate in [0, 1] over that range
// (the thickness texture's green channel). Linear over the thickness, F is within
// {{film_stack_error}} of the exact film midway between slices. Fetch the texels with
//   MATC_FILM_STACK_FRESNEL(film, mu, thickness, matc_film_slices_{{name}})
//   MATC_FILM_STACK_PREINTEGRATED(film, matc_film_stack_preintegrated_texcoords(
//       NdotV, roughness, thickness, matc_film_slices_{{name}}))
const float matc_film_slices_{{name}} = {{film_slices}}.0;

// The thickness coordinate of a film of `nm` nanometres.
float matc_film_thickness_{{name}}(float nm) {
  return clamp((nm - {{film_minimum_float}}) * (1.0 / ({{film_maximum_float}} - {{film_minimum_float}})), 0.0, 1.0);
}
