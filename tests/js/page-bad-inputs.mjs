// Runs in the engine pages (served as /checks/page-bad-inputs.mjs): the inputs an integration must
// refuse, each recorded as { thrown, message, logged } in out.failures for engine-probes.mjs's
// checkFailures. The engine page says how to load a build, make a matc material from a source,
// and change the engine's shader text (returning a function that restores it).
export function recordConsoleErrors(out) {
  out.consoleErrors = [];
  const consoleError = console.error;
  console.error = (...args) => { out.consoleErrors.push(args.join(" ")); consoleError(...args); };
}

export async function checkBadInputs(out, { loadMatcBuild, build, material, coated, filmed, useMatc, changeEngine, texture }) {
  out.failures = {};
  const failure = async (key, action) => {
    const before = out.consoleErrors.length;
    try {
      await action();
      out.failures[key] = { thrown: false };
    } catch (error) {
      out.failures[key] = { thrown: true, message: String(error.message), logged: out.consoleErrors.length > before };
    }
  };
  await failure("missing_directory", () => loadMatcBuild("/nothing-here/"));
  await failure("no_glsl_no_lut", () => loadMatcBuild("/json-only/"));
  await failure("table_of_another_basis", () => loadMatcBuild("/mixed-table/"));
  await failure("coefficients_of_another_basis", () => build.loadMaterial("beryllium_extended"));
  await failure("unknown_material", () => build.loadMaterial("unobtainium"));
  await failure("engine_changed", () => {
    const restore = changeEngine();
    try {
      useMatc({ material });
    } finally {
      restore();
    }
  });
  await failure("unknown_area_light_option", () => useMatc({ material }, { areaLights: "fast" }));
  // Text from an argument is quoted: a line break cannot forge a console line.
  await failure("area_light_option_escaped", () => useMatc({ material }, { areaLights: "x\nmatc: forged" }));
  await failure("bare_film_not_boolean", () => useMatc({ material }, { bareFilm: "yes" }));
  await failure("textured_without_edge_tint", () => useMatc({ reflectivityMap: texture }));
  // Rows that are not a Schlick curve's at F0 = 0 (a compiled material's coefficients).
  await failure("schlick_not_zero_f0", () => useMatc({ schlick: { basis: material.basis, zeroF0Coefficients: material.coefficients } }));
  // An F0 table without the material it belongs to.
  await failure("f0_table_without_material", () => useMatc({ f0Table: { coefficients: [] } }));
  // A coated metal's F0 table without its rows under the coat.
  await failure("coated_f0_table_without_under_coat", () =>
    useMatc({ material: coated, f0Table: { coefficients: Array.from({ length: 33 }, () => coated.coefficients) } }));
  await failure("coated_quality_area_lights", () => useMatc({ material: coated }, { areaLights: "quality" }));
  // The quality level follows the 4-term basis across the lobe, which a film's table is not.
  await failure("filmed_quality_area_lights", () => useMatc({ material: filmed }, { areaLights: "quality" }));
  // A film's table holds one metal: its F0 is not followed per pixel.
  await failure("filmed_f0_table", () =>
    useMatc({ material: filmed, f0Table: { coefficients: Array.from({ length: 33 }, () => filmed.coefficients) } }));
  await failure("coated_without_snippet", () => build.loadMaterial(`${coated.name}_without_snippet`));
}
