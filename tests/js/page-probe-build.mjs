// In the engine checks' pages: the build the probes render with. By default the build directory
// /out/ (`matc -o`); with config.compileInPage, the probe materials compiled in the page by the
// npm package mounted at /web/ (its WebAssembly compiler, its tables, its engine integrations),
// with no `matc -o` step.
// `directoryBuild` is /out/ either way: the bad-input checks name its files. A compiled build's
// own refusals (a name where a CompiledMaterial belongs, another basis than its tables') are
// checked here, each missing one an error in out.errors.
//   const { build, directoryBuild, loadProbeMaterial } = await probeBuild(out, config, loadMatcBuild);
export async function probeBuild(out, config, loadMatcBuild, { language = "glsl" } = {}) {
  const directoryBuild = await loadMatcBuild("/out/");
  if (!config.compileInPage) {
    return { build: directoryBuild, directoryBuild, loadProbeMaterial: (name) => directoryBuild.loadMaterial(name) };
  }
  const { createMatc } = await import("/web/index.mjs");
  const { compiledMatcBuildFiles } = await import("/web/matc-build.mjs");
  const matc = await createMatc();
  const build = await loadMatcBuild(await compiledMatcBuildFiles(matc, { language }));
  const compile = (name, options) =>
    matc.compile(matc.parseMaterial(config.materialTexts[name], { path: `${name}.json` }), options);
  const refused = async (what, call, pattern) => {
    try {
      await call();
      out.errors.push(`compiled build: ${what} was not refused`);
    } catch (error) {
      if (!pattern.test(error.message)) out.errors.push(`compiled build: ${what}: ${error.message}`);
    }
  };
  await refused("a material's name", () => build.loadMaterial(config.materials[0]), /takes a CompiledMaterial/);
  await refused("another basis", () => build.loadMaterial(compile(config.materials[0], { basis: "extended" })),
                /compiled with basis extended, but the tables are auto \(powers, f82\)/);
  return { build, directoryBuild, loadProbeMaterial: (name) => build.loadMaterial(compile(name)) };
}

// The coated F0-table probe's source ({ material, f0Table }: its coat and snippet from the build,
// its coefficients in air and under the coat per pixel from its table), or null when no render
// draws it (a build compiled in the page does not hold it).
export async function coatedF0TableSource(build, config) {
  const { name, coefficients, underCoatCoefficients } = config.f0TableCoated;
  if (!config.renders.some((render) => render.source === name)) return null;
  return { material: await build.loadMaterial(name), f0Table: { coefficients, underCoatCoefficients } };
}
