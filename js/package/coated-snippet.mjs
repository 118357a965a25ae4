// A coated metal's GLSL or WGSL snippet made from its MATC_materials_fresnel (docs/gltf.md), for a
// page with neither the compiler nor a build directory that compiled the asset: matc's own template
// (templates/<language>/material_coated.<language>, which stage.mjs puts into the package's
// templates.mjs)
// filled with the extension's values as the compiler fills it (compiler/src/emit/material_snippet.cpp),
// so the functions, and the layering they compute, are the compiler's. Only the template's notes
// of the under-coat and coat fits' own errors, which the extension does not carry, say so instead.

// A float constant as the compiler writes it (fmt's shortest form): the fewest digits that read
// back to the same float32, fixed for decimal exponents in [-4, 16), else as d.ddde-XX; with a
// decimal point or an exponent.
function floatLiteral(value) {
  const single = Math.fround(value);
  let shortest = single;
  for (let digits = 1; digits <= 9; ++digits) {
    const candidate = Number(single.toPrecision(digits));
    if (Math.fround(candidate) === single) {
      shortest = candidate;
      break;
    }
  }
  const [mantissa, exponent] = shortest.toExponential().split("e");
  const power = Number(exponent);
  const text = shortest === 0 || (power >= -4 && power < 16)
    ? String(shortest)
    : `${mantissa}e${power < 0 ? "-" : "+"}${String(Math.abs(power)).padStart(2, "0")}`;
  return /[.e]/.test(text) ? text : `${text}.0`;
}

const floatList = (values) => values.map(floatLiteral).join(", ");

// The snippet of the metal `name` from `template` (the coated-material template of `language`,
// "glsl" or "wgsl", or with `film` the film-under-a-coat one, material_film_coated) and checked
// extension values: `coefficients` (3 rows, the metal in air), `colorSpace`, `maxError` (3
// numbers), `coat` ({ weight, ior, roughness, color, underCoatCoefficients, coatCoefficients }) and
// `film` ({ weight, ior, thickness }: its table holds the base lobe, so the template has only the
// coat lobe's functions and the film's description).
// `versionNumber`: the shader library's MATC_VERSION, which the snippet checks.
export function coatedSnippet(template, { name, coefficients, colorSpace, maxError, coat, film = null, versionNumber,
                                          version, language = "glsl" }) {
  if (language !== "glsl" && language !== "wgsl") throw new Error(`matc: no coated template in ${language}`);
  const wgsl = language === "wgsl";
  const vector = wgsl ? "vec3f" : "vec3";
  const log2Colour = coat.color.map((value) => (value >= 1 ? 0 : Math.log2(Math.max(value, 1e-30))));
  const inverseIorSquared = 1 / (coat.ior * coat.ior);
  const notCarried = "(not in MATC_materials_fresnel)";
  const shared = {
    name, version, version_number: String(versionNumber), source_file: "MATC_materials_fresnel",
    inputs_hash: "of the extension", f0: coefficients.map((row) => row[0].toFixed(4)).join(", "),
    color_space: colorSpace, red: floatList(coefficients[0]), green: floatList(coefficients[1]),
    blue: floatList(coefficients[2]), under_red: floatList(coat.underCoatCoefficients[0]),
    under_green: floatList(coat.underCoatCoefficients[1]), under_blue: floatList(coat.underCoatCoefficients[2]),
    coat: floatList(coat.coatCoefficients), coat_weight: floatLiteral(coat.weight),
    coat_roughness: floatLiteral(coat.roughness), coat_ior: String(coat.ior),
    layered_max_error: Math.max(...maxError).toFixed(4), coat_max_error: notCarried,
  };
  // The film's numbers as the compiler prints them (fmt's "{}" of a double: 45, 2.4).
  const values = film ? {
    ...shared, film_ior: String(film.ior), film_thickness: String(film.thickness), film_weight: String(film.weight),
    max_error: notCarried, fit_max_error: notCarried, layer_texcoord: "",
  } : {
    ...shared,
    // A clear coat tints nothing: no exponentials where the common case needs none.
    tint_body: log2Colour.every((value) => value === 0)
      ? `  return ${vector}(1.0);`
      : `  ${wgsl ? "let" : "float"} inverse_mu_inside = ${wgsl ? "inverseSqrt" : "inversesqrt"}(` +
        `${floatLiteral(1 - inverseIorSquared)} + ${floatLiteral(inverseIorSquared)} * mu * mu);\n` +
        `  return exp2(${vector}(${floatList(log2Colour)}) * inverse_mu_inside);`,
    // A full coat leaves nothing of the metal in air.
    base: coat.weight >= 1 ? "through" : `mix(matc_combine(in_air, values), through, matc_coat_weight_${name})`,
    under_coat_max_error: notCarried,
  };
  const used = new Set();
  const snippet = template.replace(/\{\{(\w+)\}\}/g, (_, key) => {
    if (!(key in values)) throw new Error(`matc: the coated template's {{${key}}} has no value here`);
    used.add(key);
    return values[key];
  });
  const unused = Object.keys(values).filter((key) => !used.has(key));
  if (unused.length > 0) throw new Error(`matc: the coated template no longer uses ${unused.join(", ")}`);
  return snippet;
}
