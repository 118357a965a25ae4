// matc's Fresnel inside three.js's own MeshPhysicalMaterial (examples/web/three/matc-three.mjs),
// rendered by WebGLRenderer in headless Chromium into a float target and compared, at probe
// pixels, with what the CPU runtime (`matc eval`) predicts for the same normal, view, roughness
// and light, to 1e-4 (relative above 1):
//   - image lighting under a white environment (PMREM of a constant): compensated Fbar;
//   - a point light: irradiance x GGX (D, height-correlated Smith, as three.js writes them) x
//     matc's F(v.h) x matc's energy compensation;
//   - a rect area light: the light's radiance x `L_ltc` of `matc eval --quad-light`;
// for the Figure 2 material and beryllium (compiled coefficients), a textured metal through the
// coefficient table and a `matc bake` result. Then the inputs that must fail: a build without
// the files the integration needs, a table of another basis than the build or the coefficients,
// and a three.js whose patched chunk changed; each must throw and write to the console.
//   node check-three-engine.mjs MATC MATERIALS_DIR EXAMPLES_WEB_DIR
import { cpSync, mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { kWebImportMap, kWebRoots, runPage, threeVersion } from "./browser-page.mjs";
import { check, finish } from "./report.mjs";
import { compensatedFbar, kPreintegratedTolerance, run } from "./shader-cases.mjs";

const [matc, materialsDir, webDir] = process.argv.slice(2);
const kSize = 64;
const kPixels = [[32, 32], [5, 60], [60, 10], [1, 1], [40, 20], [62, 40]];
const kRoughness = [0.3, 0.7];
const kMaterials = ["figure2_edge_tint", "beryllium"];
const kPointLight = { position: [0.3, 0.2, 0.8], intensity: 0.7 };
const kRectLight = { position: [-0.4, 0.3, 0.9], width: 0.8, height: 0.5, intensity: 2.0 };
const kTextured = { reflectivity: [0.9, 0.6, 0.3], edgeTint: [0.8, 0.5, 0.2] };
const kBaked = { reflectivity: [0.95, 0.64, 0.54], edgeTint: [1.0, 0.75, 0.4] };

// Vector helpers (double precision; the GPU's float32 stays well within the tolerance).
const sub = (a, b) => a.map((x, i) => x - b[i]);
const add = (a, b) => a.map((x, i) => x + b[i]);
const scale = (a, s) => a.map((x) => x * s);
const dot = (a, b) => a.reduce((s, x, i) => s + x * b[i], 0);
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const normalize = (a) => scale(a, 1 / Math.sqrt(dot(a, a)));

// The camera sits at z = 1 looking down -z with a 90 degree field of view over the plane z = 0
// (normal +z): pixel (x, y), y up, sees P = (u, v, 0), u, v = 2 (x + 0.5) / 64 - 1.
const pointAt = ([x, y]) => [(2 * (x + 0.5)) / kSize - 1, (2 * (y + 0.5)) / kSize - 1, 0];
const viewAt = (pixel) => normalize(sub([0, 0, 1], pointAt(pixel)));
const kNormal = [0, 0, 1];

// three.js's BRDF_GGX without F: D_GGX x V_GGX_SmithCorrelated, roughness clamped at 0.045.
function ggxWithoutFresnel(l, v, roughness) {
  const alpha = Math.max(roughness, 0.045) ** 2;
  const a2 = alpha * alpha;
  const h = normalize(add(l, v));
  const nl = Math.max(dot(kNormal, l), 0), nv = Math.max(dot(kNormal, v), 0);
  const nh = Math.max(dot(kNormal, h), 0);
  const gv = nl * Math.sqrt(a2 + (1 - a2) * nv * nv);
  const gl = nv * Math.sqrt(a2 + (1 - a2) * nl * nl);
  const visibility = 0.5 / Math.max(gv + gl, 1e-6);
  const d = a2 / (Math.PI * (nh * nh * (a2 - 1) + 1) ** 2);
  return { value: d * visibility, vdoth: Math.max(dot(v, h), 0) };
}

// The rect light's corners as three.js computes them: the light looks at the origin (its -z),
// halfWidth along its local x, halfHeight along its local y, in the order of RE_Direct_RectArea.
function rectCorners({ position, width, height }) {
  const z = normalize(position);  // eye - target
  const x = normalize(cross([0, 1, 0], z));
  const y = cross(z, x);
  const hw = scale(x, width / 2), hh = scale(y, height / 2);
  return [sub(add(position, hw), hh), sub(sub(position, hw), hh), add(sub(position, hw), hh),
          add(add(position, hw), hh)];
}

// A corner in the CPU runtime's shading frame: normal +z, the view in the xz-plane towards +x.
function toShadingFrame(corner, pixel) {
  const p = pointAt(pixel), v = viewAt(pixel);
  const t1 = normalize(sub(v, scale(kNormal, dot(v, kNormal))));
  const t2 = cross(kNormal, t1);
  const d = sub(corner, p);
  return [dot(d, t1), dot(d, t2), dot(d, kNormal)];
}

const kPage = (config) => `<!doctype html><html><body><pre id="result">not run</pre>
<script type="application/json" id="config">${JSON.stringify(config)}</script>
<script type="importmap">${kWebImportMap}</script>
<script type="module">
import * as THREE from "three";
import { KTX2Loader } from "three/addons/loaders/KTX2Loader.js";
import { RectAreaLightUniformsLib } from "three/addons/lights/RectAreaLightUniformsLib.js";
import { loadMatcBuild, useMatcFresnel } from "/web/three/matc-three.mjs";
const config = JSON.parse(document.getElementById("config").textContent);
const out = { errors: [], renders: {}, failures: {}, consoleErrors: [] };
const consoleError = console.error;
console.error = (...args) => { out.consoleErrors.push(args.join(" ")); consoleError(...args); };
try {
  const renderer = new THREE.WebGLRenderer({ canvas: document.createElement("canvas") });
  renderer.debug.onShaderError = (gl, program, vertex, fragment) =>
    out.errors.push(gl.getShaderInfoLog(fragment) || gl.getShaderInfoLog(vertex) || gl.getProgramInfoLog(program));
  RectAreaLightUniformsLib.init();
  const build = await loadMatcBuild("/out/");
  const target = new THREE.WebGLRenderTarget(${kSize}, ${kSize}, { type: THREE.FloatType });
  const camera = new THREE.PerspectiveCamera(90, 1, 0.1, 10);
  camera.position.set(0, 0, 1);
  const pmrem = new THREE.PMREMGenerator(renderer);
  const white = new THREE.DataTexture(new Float32Array(64 * 32 * 4).fill(1), 64, 32, THREE.RGBAFormat, THREE.FloatType);
  white.mapping = THREE.EquirectangularReflectionMapping;
  white.needsUpdate = true;
  const environment = pmrem.fromEquirectangular(white).texture;
  const constant = (rgb) => {
    const texture = new THREE.DataTexture(new Float32Array([...rgb, 1]), 1, 1, THREE.RGBAFormat, THREE.FloatType);
    texture.needsUpdate = true;
    return texture;
  };
  const ktx2 = new KTX2Loader().detectSupport(renderer);
  const baked = async (name) => ktx2.loadAsync("/baked/" + name);
  const sources = {};
  for (const name of config.materials) sources[name] = { material: await build.loadMaterial(name) };
  sources.textured = { reflectivityMap: constant(config.textured.reflectivity),
                       edgeTintMap: constant(config.textured.edgeTint) };
  sources.baked = { baked: { c2Map: await baked("probe_c2.ktx2"), c3Map: await baked("probe_c3.ktx2"),
                             f0Map: await baked("probe_f0.ktx2") } };
  for (const render of config.renders) {
    const scene = new THREE.Scene();
    const material = useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness: render.roughness }),
                                    build, sources[render.source]);
    scene.add(new THREE.Mesh(new THREE.PlaneGeometry(4, 4), material));
    if (render.light === "environment") scene.environment = environment;
    if (render.light === "point") {
      const light = new THREE.PointLight(0xffffff, config.point.intensity, 0, 2);
      light.position.set(...config.point.position);
      scene.add(light);
    }
    if (render.light === "rect") {
      const light = new THREE.RectAreaLight(0xffffff, config.rect.intensity, config.rect.width, config.rect.height);
      light.position.set(...config.rect.position);
      light.lookAt(0, 0, 0);
      scene.add(light);
    }
    renderer.setRenderTarget(target);
    renderer.render(scene, camera);
    const pixels = [];
    for (const [x, y] of config.pixels) {
      const texel = new Float32Array(4);
      renderer.readRenderTargetPixels(target, x, y, 1, 1, texel);
      pixels.push(Array.from(texel.subarray(0, 3)));
    }
    out.renders[render.key] = pixels;
  }
  // Inputs that must fail: each must throw (and write to the console).
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
  const original = THREE.ShaderChunk.lights_physical_pars_fragment;
  await failure("engine_chunk_changed", () => {
    THREE.ShaderChunk.lights_physical_pars_fragment = original.replaceAll("F_Schlick( f0, f90, dotVH )", "F_Schlick( f0, f90, saturate( dotVH ) )");
    try {
      useMatcFresnel(new THREE.MeshPhysicalMaterial(), build, sources.beryllium);
    } finally {
      THREE.ShaderChunk.lights_physical_pars_fragment = original;
    }
  });
  await failure("textured_without_edge_tint", () =>
    useMatcFresnel(new THREE.MeshPhysicalMaterial(), build, { reflectivityMap: constant([1, 1, 1]) }));
} catch (error) {
  out.errors.push(String(error.stack || error));
}
document.getElementById("result").textContent = JSON.stringify(out);
</script></body></html>
`;

const dir = mkdtempSync(join(tmpdir(), "matc-three-engine-"));
try {
  const out = join(dir, "out");
  const materialFiles = kMaterials.map((name) => join(materialsDir, `${name}.json`));
  run(matc, ["-q", "-o", out, "--emit", "glsl,json,lut,ltc,coefficient-table",
             "--lut-precision", "f32", "--coefficient-table-precision", "f32", ...materialFiles]);
  run(matc, ["bake", "-q", "--reflectivity", kBaked.reflectivity.join(","), "--edge-tint",
             kBaked.edgeTint.join(","), "--name", "probe", "--precision", "f32", "--f0", "-o",
             join(dir, "baked")]);
  // The failing builds: coefficients only; the powers build with the extended basis' table; and
  // an extended-basis material beside the powers tables.
  run(matc, ["-q", "-o", join(dir, "json-only"), "--emit", "json", materialFiles[1]]);
  const extended = join(dir, "extended");
  run(matc, ["-q", "-o", extended, "--basis", "extended", "--emit", "glsl,json,lut",
             "--lut-precision", "f32", materialFiles[1]]);
  cpSync(out, join(dir, "mixed-table"), { recursive: true });
  for (const file of ["matc_lut.ktx2", "matc_lut.ktx2.json"]) {
    cpSync(join(extended, file), join(dir, "mixed-table", file));
  }
  cpSync(join(extended, "beryllium.json"), join(out, "beryllium_extended.json"));

  // The renders: every material at every roughness under each light; the textured and baked
  // metals under the environment and the point light.
  const renders = [];
  for (const source of kMaterials) {
    for (const roughness of kRoughness) {
      for (const light of ["environment", "point", "rect"]) {
        renders.push({ key: `${source} ${light} r=${roughness}`, source, light, roughness });
      }
    }
  }
  for (const source of ["textured", "baked"]) {
    for (const light of ["environment", "point"]) {
      renders.push({ key: `${source} ${light} r=0.3`, source, light, roughness: 0.3 });
    }
  }
  const config = { materials: kMaterials, pixels: kPixels, renders, point: kPointLight,
                   rect: kRectLight, textured: kTextured };
  const roots = { ...kWebRoots, web: webDir, out, baked: join(dir, "baked"),
                  "json-only": join(dir, "json-only"), "mixed-table": join(dir, "mixed-table") };
  const result = await runPage({ html: kPage(config), roots, dir });
  check(result.errors.length === 0, `three.js: ${result.errors.join("\n")}`);

  // The CPU runtime's values: F at each pixel's v.h for the point light, compensated Fbar at
  // each pixel's NdotV, L_ltc for the rect light.
  const ndotv = kPixels.map((pixel) => Math.fround(dot(kNormal, viewAt(pixel))));
  const pointTerms = kRoughness.map((roughness) => kPixels.map((pixel) => {
    const toLight = sub(kPointLight.position, pointAt(pixel));
    const distance2 = dot(toLight, toLight);
    const l = normalize(toLight);
    const brdf = ggxWithoutFresnel(l, viewAt(pixel), roughness);
    return { irradiance: (kPointLight.intensity / Math.max(distance2, 0.01)) * Math.max(l[2], 0),
             ggx: brdf.value, vdoth: brdf.vdoth };
  }));
  const corners = rectCorners(kRectLight);
  const list = (values) => values.join(",");
  const albedo = (roughness) => JSON.parse(run(matc, [
    "eval", "--reflectivity", "1", "--edge-tint", "1", "--lut-precision", "f32", "--no-reference",
    "--ndotv", list(ndotv), "--roughness", list(ndotv.map(() => roughness))])).Fbar_table.map((e) => e[0]);
  const expected = {};
  for (const [source, args, f0Of, fbarKey, fKey] of [
    ...kMaterials.map((name) => [name, [join(materialsDir, `${name}.json`)], null, "Fbar", "F"]),
    ["textured", ["--reflectivity", list(kTextured.reflectivity), "--edge-tint", list(kTextured.edgeTint),
                  "--coefficient-table-precision", "f32"], kTextured.reflectivity, "Fbar_table", "F_table"],
    ["baked", ["--reflectivity", list(kBaked.reflectivity), "--edge-tint", list(kBaked.edgeTint)],
     kBaked.reflectivity, "Fbar_compiled", "F_compiled"],
  ]) {
    for (const roughness of source === "textured" || source === "baked" ? [0.3] : kRoughness) {
      const terms = pointTerms[kRoughness.indexOf(roughness)];
      const evaluated = JSON.parse(run(matc, [
        "eval", ...args, "--lut-precision", "f32", "--no-reference", "--ndotv", list(ndotv),
        "--roughness", list(ndotv.map(() => roughness)), "--mu", list(terms.map((t) => t.vdoth))]));
      const f0 = f0Of ?? JSON.parse(readFileSync(join(out, `${source}.json`), "utf8"))
                            .coefficients.map((row) => row[0]);
      const e = albedo(roughness);
      const compensation = (i) => f0.map((f, c) => 1 + f * (1 - Math.max(e[i], 1e-4)) / Math.max(e[i], 1e-4));
      expected[`${source} environment r=${roughness}`] =
          evaluated[fbarKey].map((fbar, i) => compensatedFbar(fbar, f0, e[i]));
      expected[`${source} point r=${roughness}`] = terms.map((t, i) =>
          evaluated[fKey][i].map((f, c) => t.irradiance * t.ggx * f * compensation(i)[c]));
      if (kMaterials.includes(source)) {
        expected[`${source} rect r=${roughness}`] = kPixels.map((pixel, i) => {
          const quad = corners.map((corner) => toShadingFrame(corner, pixel).join(",")).join(";");
          const light = JSON.parse(run(matc, [
            "eval", ...args, "--lut-precision", "f32", "--ndotv", String(ndotv[i]),
            "--roughness", String(roughness), "--quad-light", quad, "--light-samples", "16"]));
          return light.L_ltc[0].map((value) => value * kRectLight.intensity);
        });
      }
    }
  }
  let worst = 0;
  for (const [key, pixels] of Object.entries(expected)) {
    const rendered = result.renders[key];
    check(Array.isArray(rendered), `${key}: not rendered`);
    if (!Array.isArray(rendered)) continue;
    pixels.forEach((rgb, i) => rgb.forEach((value, c) => {
      const difference = Math.abs(rendered[i][c] - value) / Math.max(1, Math.abs(value));
      worst = Math.max(worst, difference);
      check(difference <= kPreintegratedTolerance,
            `${key}, pixel ${kPixels[i]}, channel ${c}: three.js ${rendered[i][c]}, CPU runtime ${value}`);
    }));
  }
  // Every light must reach the probes (a light that lit nothing would pass trivially).
  for (const key of Object.keys(expected)) {
    const lit = expected[key].filter((rgb) => rgb.some((value) => value > 1e-3)).length;
    check(lit >= 3, `${key}: only ${lit} of ${kPixels.length} probes lit`);
  }

  const kFailures = {
    missing_directory: "is this a matc output directory",
    no_glsl_no_lut: "no glsl output",
    table_of_another_basis: "a table of basis extended",
    coefficients_of_another_basis: "do not belong together",
    unknown_material: "is unobtainium one of this build's materials",
    engine_chunk_changed: "the shader source lights_physical_pars_fragment changed",
    textured_without_edge_tint: "needs both reflectivityMap and edgeTintMap",
  };
  for (const [key, phrase] of Object.entries(kFailures)) {
    const failure = result.failures[key];
    check(failure?.thrown === true, `${key}: did not throw`);
    if (!failure?.thrown) continue;
    check(failure.message.includes(phrase), `${key}: "${failure.message}" does not say "${phrase}"`);
    check(failure.logged === true, `${key}: nothing written to the console`);
  }
  console.log(`three.js ${threeVersion()} MeshPhysicalMaterial with matc's Fresnel: ` +
              `${Object.keys(expected).length} renders x ${kPixels.length} probes, largest difference ` +
              `from the CPU runtime ${worst.toExponential(2)}; ${Object.keys(kFailures).length} bad inputs refused`);
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
