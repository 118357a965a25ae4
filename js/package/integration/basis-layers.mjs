// A per-material build (matc --basis auto; docs/lut.md): its table holds a layer per basis side by
// side and each material's coefficients are in one basis of them. The integrations pick a
// material's functions by a define, MATC_BASIS_<NAME> for a basis after the first, that the
// shader aliases below turn into the library's names (matc_fresnel_f82, matc_lut_texcoord_f82,
// ...): a one-basis build has no layers, no define and the library's plain names.

// The bases a build's coefficients may be in: its layers, or its one basis.
export function buildBases(build) {
  return build.layers ?? [build.basis];
}

// Whether coefficients of `basis` belong to the build's tables.
export function holdsBasis(build, basis) {
  return buildBases(build).includes(basis);
}

// The define that selects `basis`' functions, or null for the build's first basis.
export function basisDefine(build, basis) {
  return basis === buildBases(build)[0] ? null : `MATC_BASIS_${basis.toUpperCase()}`;
}

// The library functions a material's basis changes, by the alias the patched shaders call.
const kAliased = [["matc_source_fresnel", "matc_fresnel"], ["matc_source_lut_texcoord", "matc_lut_texcoord"],
                  ["matc_source_ltc_quad_light_following", "matc_ltc_quad_light_following"]];

// The GLSL aliases after the library: each further layer's names under its define, else the first's.
export function basisAliasesGlsl(build) {
  const further = buildBases(build).slice(1);
  const names = (suffix) => kAliased.map(([alias, name]) => `\t#define ${alias} ${name}${suffix}\n`).join("");
  let out = "";
  for (const [i, basis] of further.entries())
    out += `${i === 0 ? "#if" : "#elif"} defined(${basisDefine(build, basis)})\n${names(`_${basis}`)}`;
  return further.length ? `${out}#else\n${names("")}#endif\n` : names("");
}

// The suffix of `basis`' functions in the library ("_f82"), empty for the first basis.
export function basisSuffix(build, basis) {
  return basis === buildBases(build)[0] ? "" : `_${basis}`;
}
