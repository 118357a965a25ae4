// The WGSL output, compiled and run by an implementation matc did not write: Dawn (npm `webgpu`,
// whose WGSL compiler is Tint) on the SwiftShader Vulkan driver that Debian's chromium ships.
// Compute kernels evaluate, over the query grid of `matc validate`:
// - every example material's snippet: F(mu), Fbar(NdotV, roughness) from the table's closed form
//   (matc_preintegrated_basis_analytic), and Fbar(NdotV, roughness) from the preintegrated
//   table (rgba16float, linear sampler);
// - textured metals: coefficients from the coefficient table (rg16float) for per-channel (r, g);
// - an area light: gold under two quads (one crossing the horizon), with the LTC table
//   (rgba32float, which needs the "float32-filterable" feature);
// - glTF's metal-rough mix of gold with glTF's dielectric (matc_metal_rough);
// and everything is compared with the CPU runtime (`matc eval`) at matc validate's tolerances.
// examples/web/specular.wgsl (docs/shaders.md shows it) must give Fbar with energy compensation,
// and the library with an embedded table (--embed-lut, a copy of each layer) must compile too.
// These run in a one-basis build (--basis powers); the default build (a basis per material) runs
// every bare example through its basis' functions and its layer of the side-by-side table, and the
// F82-tint example under a quad light (its _f82 area-light function).
//   VK_ICD_FILENAMES=/usr/lib/chromium/vk_swiftshader_icd.json \
//     node check-webgpu.mjs MATC MATERIALS_DIR EXAMPLES_WEB_DIR
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { create, globals } from "webgpu";
import { check, finish } from "./report.mjs";
import {
  compensatedFbar, compileAndEvaluate, kClosedFormTolerance, kFresnelTolerance, kPreintegratedTolerance,
  largestDifference, run,
  validationQueries,
} from "./shader-cases.mjs";

const [matc, materialsDir, webDir] = process.argv.slice(2);
Object.assign(globalThis, globals);

// Quads in the shading frame of `matc eval --quad-light` (normal +z, view in the xz-plane towards
// +x, shading point at the origin): one overhead, one tilted across the horizon.
const kQuads = ["-1,-1,2;1,-1,2;1,1,2;-1,1,2", "-1,-1,0.5;1,-1,-0.3;1,1,-0.3;-1,1,0.5"];

const kBindings = `
@group(0) @binding(0) var<storage, read> matc_queries: array<vec4f>;
@group(0) @binding(1) var<storage, read_write> matc_results: array<vec4f>;
@group(0) @binding(2) var matc_lut: texture_2d<f32>;
@group(0) @binding(3) var matc_coefficient_table: texture_2d<f32>;
@group(0) @binding(4) var matc_ltc: texture_2d<f32>;
@group(0) @binding(5) var matc_linear: sampler;
@group(0) @binding(6) var matc_film: texture_2d<f32>;
`;

// A compute kernel over the queries (mu, NdotV, roughness each): `body` runs for query i.
const perQueryKernel = (body) => `${kBindings}
@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3u) {
  let i = id.x;
  if (i >= arrayLength(&matc_queries)) {
    return;
  }
  let query = matc_queries[i];
${body}}
`;

// Three results per query: F(mu), Fbar(NdotV, roughness) through the table and Fbar from the
// table's closed form, for the coefficients `coefficients`.
// `suffix`: a per-material build's functions of the material's basis ("_f82"), else none.
const fresnelKernel = (coefficients, suffix = "") => perQueryKernel(`  let c = ${coefficients};
  let bbar = textureSampleLevel(matc_lut, matc_linear, matc_lut_texcoord${suffix}(query.y, query.z), 0.0);
  matc_results[3u * i] = vec4f(matc_fresnel${suffix}(c, query.x), 1.0);
  matc_results[3u * i + 1u] = vec4f(matc_fresnel_preintegrated(c, bbar), 1.0);
  matc_results[3u * i + 2u] = vec4f(matc_fresnel_preintegrated(
                                        c, matc_preintegrated_basis_analytic${suffix}(query.y, query.z)), 1.0);`);

// The same for coated material `name` through its own functions: both lobes summed, the coat's
// texel sampled at the coat's roughness.
const coatedKernel = (name) => perQueryKernel(`  let bbar = textureSampleLevel(matc_lut, matc_linear, matc_lut_texcoord(query.y, query.z), 0.0);
  let coat_bbar = textureSampleLevel(matc_lut, matc_linear,
                                     matc_lut_texcoord(query.y, matc_coat_roughness_${name}), 0.0);
  let analytic = matc_preintegrated_basis_analytic(query.y, query.z);
  let coat_analytic = matc_preintegrated_basis_analytic(query.y, matc_coat_roughness_${name});
  matc_results[3u * i] = vec4f(matc_fresnel_${name}(query.x) + matc_coat_fresnel_${name}(query.x), 1.0);
  matc_results[3u * i + 1u] = vec4f(matc_fresnel_preintegrated_${name}(bbar, coat_bbar, query.y) +
                                    matc_coat_fresnel_preintegrated_${name}(coat_bbar), 1.0);
  matc_results[3u * i + 2u] = vec4f(matc_fresnel_preintegrated_${name}(analytic, coat_analytic, query.y) +
                                    matc_coat_fresnel_preintegrated_${name}(coat_analytic), 1.0);`);

// Two results per query for filmed material `name` (docs/thin-film.md): F(mu) and Fbar(NdotV,
// roughness) from its own table, bound at binding 6.
const filmKernel = (name) => perQueryKernel(`  matc_results[2u * i] = vec4f(matc_fresnel_${name}(matc_film_fresnel(matc_film, matc_linear, query.x)), 1.0);
  matc_results[2u * i + 1u] = vec4f(matc_fresnel_preintegrated_${name}(
                                        matc_film_preintegrated(matc_film, matc_linear, query.y, query.z)), 1.0);`);

// The same for a thickness per pixel (docs/thin-film.md "A thickness per pixel"): the stack read at
// each query's thickness coordinate (w).
const filmStackKernel = (name) => perQueryKernel(`  let slices = matc_film_slices_${name};
  matc_results[2u * i] = vec4f(matc_fresnel_${name}(
                                   matc_film_stack_fresnel(matc_film, matc_linear, query.x, query.w, slices)), 1.0);
  matc_results[2u * i + 1u] = vec4f(matc_fresnel_preintegrated_${name}(matc_film_stack_preintegrated(
                                        matc_film, matc_linear, query.y, query.z, query.w, slices)), 1.0);`);

// The same for a filmed material under a coat (docs/thin-film.md, "Under a coat"): the base lobe
// from its table, the coat lobe from matc_lut at the coat's roughness, summed.
const filmCoatedKernel = (name) => perQueryKernel(`  let coat_bbar = textureSampleLevel(matc_lut, matc_linear,
                                     matc_lut_texcoord(query.y, matc_coat_roughness_${name}), 0.0);
  matc_results[2u * i] = vec4f(matc_fresnel_${name}(matc_film_fresnel(matc_film, matc_linear, query.x)) +
                               matc_coat_fresnel_${name}(query.x), 1.0);
  matc_results[2u * i + 1u] = vec4f(matc_fresnel_preintegrated_${name}(
                                        matc_film_preintegrated(matc_film, matc_linear, query.y, query.z)) +
                                    matc_coat_fresnel_preintegrated_${name}(coat_bbar), 1.0);`);

// One result per query: a quad light of radiance 1 seen from the origin (`light` names the
// one-shape function or the quality level's, which also takes the roughness).
const quadLightKernel = (coefficients, quad, light = "matc_ltc_quad_light", suffix = "") => {
  const roughnessArgument = light.includes("_following") ? "query.z, " : "";
  const vertices = quad.split(";").map((v) => `vec3f(${v.split(",").map(Number).map((x) => x.toFixed(6)).join(", ")})`);
  return perQueryKernel(`  let V = vec3f(sqrt(max(1.0 - query.y * query.y, 0.0)), 0.0, query.y);
  let bbar = textureSampleLevel(matc_lut, matc_linear, matc_lut_texcoord${suffix}(query.y, query.z), 0.0);
  let ltc = textureSampleLevel(matc_ltc, matc_linear, matc_ltc_texcoord(query.y, query.z), 0.0);
  matc_results[i] = vec4f(${light}(${coefficients}, bbar, ltc, ${roughnessArgument}vec3f(0.0, 0.0, 1.0),
                                  V, vec3f(0.0), ${vertices.join(", ")}), 1.0);
`);
};

const dir = mkdtempSync(join(tmpdir(), "matc-webgpu-"));
try {
  const gpu = create([]);
  const adapter = await gpu.requestAdapter();
  check(adapter !== null, "Dawn found no adapter (VK_ICD_FILENAMES must name SwiftShader's ICD)");
  const device = await adapter.requestDevice({ requiredFeatures: ["float32-filterable"] });
  console.log(`Dawn adapter: ${adapter.info.description || adapter.info.vendor}`);
  const errors = [];
  device.addEventListener("uncapturederror", (event) => errors.push(event.error.message));

  const precision = ["--lut-precision", "f16", "--coefficient-table-precision", "f16"];
  const options = [...precision, "--basis", "powers"];
  const queries = validationQueries();
  const out = join(dir, "out");
  const cases = compileAndEvaluate(matc, materialsDir, out, "wgsl", options, queries,
                                   ["ltc", "json"]);

  // A table file as a texture: square, or `layers` squares side by side.
  const texture = (file, format, texelBytes, directory = out, layers = 1) => {
    const bytes = readFileSync(join(directory, file));
    const size = Math.round(Math.sqrt(bytes.length / texelBytes / layers));
    const t = device.createTexture({ size: [size * layers, size], format,
                                     usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST });
    device.queue.writeTexture({ texture: t }, bytes, { bytesPerRow: size * layers * texelBytes },
                              [size * layers, size]);
    return t;
  };
  const textures = [texture("matc_lut.bin", "rgba16float", 8),
                    texture("matc_coefficient_table.bin", "rg16float", 4),
                    texture("matc_ltc.bin", "rgba32float", 16)];
  // A filmed metal's table (65 x 18; a thickness per pixel's stack 65 x 18 slices), bound at
  // binding 6; other kernels see a placeholder.
  const filmTexture = (name, directory = out, slices = 1) => {
    const bytes = readFileSync(join(directory, `${name}.film.bin`));
    const rows = 18 * slices;
    const t = device.createTexture({ size: [65, rows], format: "rgba16float",
                                     usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST });
    check(bytes.length === 65 * rows * 8, `${name}.film.bin holds 65 x ${rows} RGBA16F texels`);
    device.queue.writeTexture({ texture: t }, bytes, { bytesPerRow: 65 * 8 }, [65, rows]);
    return t;
  };
  const placeholder = device.createTexture({ size: [1, 1], format: "rgba16float",
                                             usage: GPUTextureUsage.TEXTURE_BINDING });
  let film = placeholder;
  const sampler = device.createSampler({ magFilter: "linear", minFilter: "linear",
                                         addressModeU: "clamp-to-edge", addressModeV: "clamp-to-edge" });
  const layout = device.createBindGroupLayout({ entries: [
    { binding: 0, visibility: GPUShaderStage.COMPUTE, buffer: { type: "read-only-storage" } },
    { binding: 1, visibility: GPUShaderStage.COMPUTE, buffer: { type: "storage" } },
    ...[2, 3, 4, 6].map((binding) => ({ binding, visibility: GPUShaderStage.COMPUTE,
                                        texture: { sampleType: "float" } })),
    { binding: 5, visibility: GPUShaderStage.COMPUTE, sampler: { type: "filtering" } },
  ] });

  // Compiles library + extra into a kernel, runs it over `flat` queries and returns
  // `perQuery` vec4 results per query (or throws Tint's messages).
  const dispatch = async (source, flat, perQuery) => {
    const module = device.createShaderModule({ code: source });
    const messages = (await module.getCompilationInfo()).messages.filter((m) => m.type === "error");
    if (messages.length > 0)
      throw new Error(messages.map((m) => `${m.lineNum}:${m.linePos}: ${m.message}`).join("\n"));
    const pipeline = device.createComputePipeline({
      layout: device.createPipelineLayout({ bindGroupLayouts: [layout] }),
      compute: { module, entryPoint: "main" } });
    const input = device.createBuffer({ size: flat.byteLength, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST });
    device.queue.writeBuffer(input, 0, flat);
    const bytes = (flat.length / 4) * perQuery * 16;
    const output = device.createBuffer({ size: bytes, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC });
    const readback = device.createBuffer({ size: bytes, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
    const group = device.createBindGroup({ layout, entries: [
      { binding: 0, resource: { buffer: input } }, { binding: 1, resource: { buffer: output } },
      ...textures.map((t, k) => ({ binding: 2 + k, resource: t.createView() })),
      { binding: 5, resource: sampler }, { binding: 6, resource: film.createView() }] });
    const encoder = device.createCommandEncoder();
    const pass = encoder.beginComputePass();
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, group);
    pass.dispatchWorkgroups(Math.ceil(flat.length / 4 / 64));
    pass.end();
    encoder.copyBufferToBuffer(output, 0, readback, 0, bytes);
    device.queue.submit([encoder.finish()]);
    await readback.mapAsync(GPUMapMode.READ);
    const values = new Float32Array(readback.getMappedRange().slice(0));
    readback.unmap();
    return values;
  };

  const report = (name, measured, tolerance) => {
    console.log(`${name}: ${measured.map(([what, d]) => `${what} ${d.max_abs.toExponential(2)}`).join(", ")}`);
    for (const [what, d] of measured)
      check(d.max_abs <= tolerance[what], `${name}: |${what}_dawn - ${what}_cpu| = ${d.max_abs} at query ${d.query}`);
  };
  const attempt = async (name, body) => {
    try {
      await body();
    } catch (error) {
      check(false, `${name}: ${error.message}`);
    }
  };

  // A filmed metal through its own table: F and Fbar both sampled, hence the table's tolerance.
  const checkFilmed = async (built, material, directory, label) => {
    film = filmTexture(material.name, directory);
    try {
      const kernel = material.coated ? filmCoatedKernel(material.name) : filmKernel(material.name);
      const values = await dispatch(built.library + material.snippet + kernel, queries.flat, 2);
      report(label, [["F", largestDifference(values, material.F, 8, 0)],
                     ["Fbar", largestDifference(values, material.Fbar, 8, 4)]],
             { F: kPreintegratedTolerance, Fbar: kPreintegratedTolerance });
    } finally {
      film = placeholder;
    }
  };
  // A thickness per pixel: tests/data/film_stack's material at three thicknesses of its range,
  // the stack sampled at each against matc eval --film-thickness.
  await attempt("film stack", async () => {
    const file = new URL("../data/film_stack/titanium_heat_tint.json", import.meta.url).pathname;
    const stackOut = join(dir, "stack");
    run(matc, ["-q", "-o", stackOut, "--emit", "wgsl,lut,json", "--lut", "raw", ...options, file]);
    const described = JSON.parse(readFileSync(join(stackOut, "titanium_heat_tint.json"), "utf8"));
    const { slices, thickness_nm: [minimum, maximum] } = described.film_stack;
    const snippet = readFileSync(join(stackOut, "titanium_heat_tint.wgsl"), "utf8");
    const library = readFileSync(join(stackOut, "matc_fresnel.wgsl"), "utf8");
    film = filmTexture("titanium_heat_tint", stackOut, slices);
    try {
      for (const coordinate of [0, 0.3719, 1]) {
        const nm = minimum + coordinate * (maximum - minimum);
        const list = (values) => Array.from(values).join(",");
        const evaluated = JSON.parse(run(matc, [
          "eval", file, ...options, "--no-reference", "--film-thickness", String(nm),
          "--mu", list(queries.mu), "--ndotv", list(queries.ndotv), "--roughness", list(queries.roughness)]));
        const flat = Float32Array.from(queries.flat, (v, k) => (k % 4 === 3 ? evaluated.film_thickness.coordinate : v));
        const values = await dispatch(library + snippet + filmStackKernel("titanium_heat_tint"), flat, 2);
        report(`titanium_heat_tint (${slices} slices, ${nm.toFixed(1)} nm)`,
               [["F", largestDifference(values, evaluated.F, 8, 0)],
                ["Fbar", largestDifference(values, evaluated.Fbar, 8, 4)]],
               { F: kPreintegratedTolerance, Fbar: kPreintegratedTolerance });
      }
    } finally {
      film = placeholder;
    }
  });
  for (const material of cases.materials) {
    await attempt(material.name, async () => {
      if (material.filmed) return checkFilmed(cases, material, out, `${material.name} (film table)`);
      const kernel = material.coated ? coatedKernel(material.name)
                                     : fresnelKernel(`matc_coefficients_${material.name}`);
      const values = await dispatch(cases.library + material.snippet + kernel, queries.flat, 3);
      report(material.name, [["F", largestDifference(values, material.F, 12, 0)],
                             ["Fbar", largestDifference(values, material.Fbar, 12, 4)],
                             ["Fbar_analytic", largestDifference(values, material.FbarAnalytic, 12, 8)]],
             { F: kFresnelTolerance, Fbar: kPreintegratedTolerance, Fbar_analytic: kClosedFormTolerance });
    });
  }
  for (const metal of cases.textured) {
    await attempt(metal.name, async () => {
      const vector = (v) => `vec3f(${v.map((x) => x.toFixed(6)).join(", ")})`;
      const values = await dispatch(cases.library + fresnelKernel(
        `matc_coefficients_from_table_texture(matc_coefficient_table, matc_linear, ` +
        `${vector(metal.reflectivity)}, ${vector(metal.edgeTint)})`), queries.flat, 3);
      report(metal.name, [["F", largestDifference(values, metal.F, 12, 0)],
                          ["Fbar", largestDifference(values, metal.Fbar, 12, 4)],
                          ["Fbar_analytic", largestDifference(values, metal.FbarAnalytic, 12, 8)]],
             { F: kPreintegratedTolerance, Fbar: kPreintegratedTolerance,
               Fbar_analytic: kPreintegratedTolerance });
    });
  }

  // Area lights: an 8 x 8 grid of (NdotV, roughness), NdotV short of 1 (where any tangent frame
  // will do and the two sides may pick different ones).
  const ndotv = [], roughness = [];
  for (let i = 0; i < 8; ++i) {
    for (let j = 0; j < 8; ++j) {
      ndotv.push(Math.fround(0.02 + 0.96 * i / 7));
      roughness.push(Math.fround(j / 7));
    }
  }
  const lightQueries = new Float32Array(ndotv.flatMap((v, k) => [0, v, roughness[k], 0]));
  const gold = cases.materials.find((m) => m.name === "gold");
  for (const quad of kQuads) {
    await attempt(`gold, quad ${quad}`, async () => {
      const expected = JSON.parse(run(matc, [
        "eval", join(materialsDir, "gold.json"), ...options, "--ndotv", ndotv.join(","),
        "--roughness", roughness.join(","), "--quad-light", quad, "--no-reference"]));
      const values = await dispatch(cases.library + gold.snippet +
                                    quadLightKernel("matc_coefficients_gold", quad), lightQueries, 1);
      const following = await dispatch(
        cases.library + gold.snippet +
          quadLightKernel("matc_coefficients_gold", quad, "matc_ltc_quad_light_following"),
        lightQueries, 1);
      report(`gold, quad light ${quad}`,
             [["L", largestDifference(values, expected.L_ltc, 4, 0)],
              ["L_following", largestDifference(following, expected.L_ltc_following, 4, 0)]],
             { L: kPreintegratedTolerance, L_following: kPreintegratedTolerance });
    });
  }

  // glTF's metal-rough mix (matc_metal_rough of glTF's dielectric, matc_dielectric_fresnel, and
  // gold) against `matc eval --metalness`'s F_metal_rough at the queries' cosines.
  await attempt("gold, metal-rough mix", async () => {
    const kMetalness = 0.35;
    const count = queries.flat.length / 4;
    const mu = Array.from({ length: count }, (_, i) => queries.flat[4 * i]);
    const expected = JSON.parse(run(matc, ["eval", join(materialsDir, "gold.json"), ...options,
                                           "--mu", mu.join(","), "--metalness", String(kMetalness)]));
    const values = await dispatch(cases.library + gold.snippet + perQueryKernel(
      `  matc_results[i] = vec4f(matc_metal_rough(matc_dielectric_fresnel(vec3f(0.04), vec3f(1.0), query.x),
                                             matc_fresnel(matc_coefficients_gold, query.x), ${kMetalness}), 1.0);`),
                                  queries.flat, 1);
    report("gold, metal-rough mix at metalness 0.35", [["F", largestDifference(values, expected.F_metal_rough, 4, 0)]],
           { F: kFresnelTolerance });
  });

  // The documented example: specular_gold(NdotV, roughness) = Fbar (1 + F0 (1 - E) / E), E the
  // table's directional albedo (Fbar of r = 1 from the coefficient-table path). Compared
  // relative to the value (E is small at grazing, where the scale is large), from NdotV = 0.1.
  // In the default build (a basis per material, its layered table bound): `built` its cases.
  const checkSpecularExample = async (built, builtOut, builtOptions) => {
    const kernel = `
@group(0) @binding(0) var<storage, read> matc_queries: array<vec4f>;
@group(0) @binding(1) var<storage, read_write> matc_results: array<vec4f>;
@group(0) @binding(3) var matc_coefficient_table: texture_2d<f32>;
@group(0) @binding(4) var matc_ltc: texture_2d<f32>;
@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3u) {
  let i = id.x;
  if (i >= arrayLength(&matc_queries)) {
    return;
  }
  matc_results[i] = vec4f(specular_gold(matc_queries[i].y, matc_queries[i].z), 1.0);
}
`;
    const gold = built.materials.find((m) => m.name === "gold");
    const values = await dispatch(built.library + gold.snippet +
                                  readFileSync(join(webDir, "specular.wgsl"), "utf8") + kernel,
                                  queries.flat, 1);
    const f0 = JSON.parse(readFileSync(join(builtOut, "gold.json"), "utf8")).coefficients.map((c) => c[0]);
    const albedo = JSON.parse(run(matc, [
      "eval", "--reflectivity", "1", "--edge-tint", "1", ...builtOptions, "--no-reference",
      "--ndotv", Array.from(queries.ndotv).join(","),
      "--roughness", Array.from(queries.roughness).join(",")])).Fbar_table;
    let worst = 0, where = 0;
    for (let i = 0; i < queries.count; ++i) {
      if (queries.ndotv[i] < 0.1) continue;
      const expected = compensatedFbar(gold.Fbar[i], f0, albedo[i][0]);
      for (let c = 0; c < 3; ++c) {
        const relative = Math.abs(values[4 * i + c] - expected[c]) / expected[c];
        if (!(relative <= worst)) {
          worst = relative;
          where = i;
        }
      }
    }
    report("examples/web/specular.wgsl (relative)", [["specular", { max_abs: worst, query: where }]],
           { specular: kPreintegratedTolerance });
  };

  // The embedded table (a constant array indexed at run time) must compile.
  await attempt("embedded table", async () => {
    const embedded = join(dir, "embedded");
    run(matc, ["-q", "-o", embedded, "--emit", "wgsl", "--embed-lut", "--embed-lut-size", "8",
               join(materialsDir, "gold.json")]);
    const library = readFileSync(join(embedded, "matc_fresnel.wgsl"), "utf8");
    await dispatch(library + fresnelKernel("matc_coefficients_from_baked(vec3f(0.9), vec3f(0.01), vec3f(0.0))")
                     .replace("let bbar = textureSampleLevel(matc_lut, matc_linear, matc_lut_texcoord(query.y, query.z), 0.0);",
                              "let bbar = matc_preintegrated_basis_embedded(query.y, query.z);"),
                   queries.flat.subarray(0, 256), 2);
    check(true, "embedded table compiles");
    // The default build embeds each layer: the f82 basis' copy compiles too.
    await dispatch(library + fresnelKernel("matc_coefficients_from_baked(vec3f(0.9), vec3f(0.01), vec3f(0.0))")
                     .replace("let bbar = textureSampleLevel(matc_lut, matc_linear, matc_lut_texcoord(query.y, query.z), 0.0);",
                              "let bbar = matc_preintegrated_basis_embedded_f82(query.y, query.z);"),
                   queries.flat.subarray(0, 256), 2);
    check(true, "the f82 layer's embedded table compiles");
    // matc_coefficients_from_f0 compiles in WGSL too (its values: the engines' probe checks).
    await dispatch(library + fresnelKernel("matc_coefficients_from_f0(matc_coefficients_from_baked(vec3f(0.0), vec3f(0.3), vec3f(0.9)), vec3f(0.9))")
                     .replace("let bbar = textureSampleLevel(matc_lut, matc_linear, matc_lut_texcoord(query.y, query.z), 0.0);",
                              "let bbar = matc_preintegrated_basis_embedded(query.y, query.z);"),
                   queries.flat.subarray(0, 256), 2);
    check(true, "matc_coefficients_from_f0 compiles");
  });
  // The default build, a basis per material: the same checks through each material's basis and
  // layer.
  await attempt("per-material build", async () => {
    const autoOptions = precision;
    const autoOut = join(dir, "auto");
    const auto = compileAndEvaluate(matc, materialsDir, autoOut, "wgsl", autoOptions, queries,
                                    ["ltc", "json"]);
    const layers = JSON.parse(readFileSync(join(autoOut, "matc_lut.bin.json"), "utf8")).layers;
    check(layers?.length === 2, "a per-material build's table has two layers");
    const oneBasisTable = textures[0];
    textures[0] = texture("matc_lut.bin", "rgba16float", 8, autoOut, layers.length);
    const suffix = (basis) => (basis === layers[0].basis ? "" : `_${basis}`);
    for (const material of auto.materials.filter((m) => !m.coated)) {
      if (material.filmed) {
        await checkFilmed(auto, material, autoOut, `${material.name} (default build, film table)`);
        continue;
      }
      const values = await dispatch(
        auto.library + material.snippet +
          fresnelKernel(`matc_coefficients_${material.name}`, suffix(material.basis)),
        queries.flat, 3);
      report(`${material.name} (default build: ${material.basis})`,
             [["F", largestDifference(values, material.F, 12, 0)],
              ["Fbar", largestDifference(values, material.Fbar, 12, 4)],
              ["Fbar_analytic", largestDifference(values, material.FbarAnalytic, 12, 8)]],
             { F: kFresnelTolerance, Fbar: kPreintegratedTolerance, Fbar_analytic: kClosedFormTolerance });
    }
    const tinted = auto.materials.find((m) => m.basis !== layers[0].basis);
    check(tinted !== undefined, "the default build gave some example a second basis");
    const quad = kQuads[1];
    const expected = JSON.parse(run(matc, [
      "eval", join(materialsDir, `${tinted.name}.json`), ...autoOptions, "--ndotv", ndotv.join(","),
      "--roughness", roughness.join(","), "--quad-light", quad, "--no-reference"]));
    const following = await dispatch(
      auto.library + tinted.snippet +
        quadLightKernel(`matc_coefficients_${tinted.name}`, quad,
                        `matc_ltc_quad_light_following${suffix(tinted.basis)}`, suffix(tinted.basis)),
      lightQueries, 1);
    report(`${tinted.name} (default build), quad light ${quad}`,
           [["L_following", largestDifference(following, expected.L_ltc_following, 4, 0)]],
           { L_following: kPreintegratedTolerance });
    await attempt("examples/web/specular.wgsl", () => checkSpecularExample(auto, autoOut, autoOptions));
    textures[0] = oneBasisTable;
  });
  check(errors.length === 0, `WebGPU errors: ${errors.join("; ")}`);
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
