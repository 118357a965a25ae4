// The three.js integration example (examples/web/matc-three.mjs) in headless Chromium: gold's
// GLSL files in a three.js ShaderMaterial on a plane facing a perspective camera, rendered into a
// float render target by three.js itself (npm `three`, pinned in package-lock.json). At chosen
// pixels, whose NdotV follows from the camera, the result must be the CPU runtime's
// Fbar * (1 + F0 (1 - E) / E) (`matc eval`; E the table's directional albedo) within 1e-4.
//   node check-three.mjs MATC MATERIALS_DIR EXAMPLES_WEB_DIR
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { kWebRoots, modulePage, runPage, threeVersion } from "./browser-page.mjs";
import { check, finish } from "./report.mjs";
import { compensatedFbar, kPreintegratedTolerance, run } from "./shader-cases.mjs";

const [matc, materialsDir, webDir] = process.argv.slice(2);
const kSize = 64;
// Pixels of the 64 x 64 target and the roughness each is rendered at (one render per roughness).
const kPixels = [[32, 32], [5, 60], [60, 10], [0, 0], [40, 20]];
const kRoughness = [0.0, 0.3, 0.6, 1.0];

// The camera sits at z = 1 with a 90 degree field of view over the plane z = 0: pixel (x, y) sees
// the point (u, v, 0) with u, v = 2 (x + 0.5) / 64 - 1, so NdotV = 1 / sqrt(1 + u^2 + v^2).
const ndotvAt = ([x, y]) => {
  const u = (2 * (x + 0.5)) / kSize - 1, v = (2 * (y + 0.5)) / kSize - 1;
  return Math.fround(1 / Math.sqrt(1 + u * u + v * v));
};

const kPage = modulePage({}, {
  head: `import * as THREE from "three";
import { createMatcMaterial } from "/web/matc-three.mjs";`,
  body: `
  out.pixels = [];
  const fetchText = async (path) => (await fetch(path)).text();
  const lut = new Float32Array(await (await fetch("/out/matc_lut.bin")).arrayBuffer());
  const renderer = new THREE.WebGLRenderer({ canvas: document.createElement("canvas") });
  renderer.debug.onShaderError = (gl, program, vertex, fragment) =>
    out.errors.push(gl.getShaderInfoLog(fragment) || gl.getShaderInfoLog(vertex) || gl.getProgramInfoLog(program));
  const target = new THREE.WebGLRenderTarget(${kSize}, ${kSize}, { type: THREE.FloatType });
  const camera = new THREE.PerspectiveCamera(90, 1, 0.1, 10);
  camera.position.set(0, 0, 1);
  const material = createMatcMaterial(THREE, {
    library: await fetchText("/out/matc_fresnel.glsl"), material: await fetchText("/out/gold.glsl"),
    name: "gold", lut, roughness: 0 });
  const scene = new THREE.Scene();
  scene.add(new THREE.Mesh(new THREE.PlaneGeometry(4, 4), material));
  renderer.setRenderTarget(target);
  for (const roughness of ${JSON.stringify(kRoughness)}) {
    material.uniforms.matc_roughness.value = roughness;
    renderer.render(scene, camera);
    for (const [x, y] of ${JSON.stringify(kPixels)}) {
      const texel = new Float32Array(4);
      renderer.readRenderTargetPixels(target, x, y, 1, 1, texel);
      out.pixels.push(Array.from(texel.subarray(0, 3)));
    }
  }`,
});

const dir = mkdtempSync(join(tmpdir(), "matc-three-"));
try {
  const gold = join(materialsDir, "gold.json");
  run(matc, ["-q", "-o", join(dir, "out"), "--emit", "glsl,json,lut", "--lut", "raw",
             "--lut-precision", "f32", gold]);
  const f0 = JSON.parse(readFileSync(join(dir, "out", "gold.json"), "utf8")).coefficients
               .map((channel) => channel[0]);
  const ndotv = kRoughness.flatMap(() => kPixels.map(ndotvAt));
  const roughness = kRoughness.flatMap((r) => kPixels.map(() => r));
  const evaluate = (args) => JSON.parse(run(matc, [
    "eval", ...args, "--lut-precision", "f32", "--no-reference", "--ndotv", ndotv.join(","),
    "--roughness", roughness.join(",")]));
  const fbar = evaluate([gold]).Fbar;
  const albedo = evaluate(["--reflectivity", "1", "--edge-tint", "1"]).Fbar_table.map((e) => e[0]);

  const result = await runPage({ html: kPage, roots: { ...kWebRoots, web: webDir, out: join(dir, "out") },
                                 dir, budgetMs: 60000 });
  check(result.errors.length === 0, `three.js: ${result.errors.join("\n")}`);
  check(result.pixels.length === ndotv.length, `${result.pixels.length} of ${ndotv.length} pixels read`);
  let worst = 0;
  result.pixels.forEach((pixel, i) => {
    const expectedRgb = compensatedFbar(fbar[i], f0, albedo[i]);
    for (let c = 0; c < 3; ++c) {
      const expected = expectedRgb[c];
      const difference = Math.abs(pixel[c] - expected);
      worst = Math.max(worst, difference);
      check(difference <= kPreintegratedTolerance,
            `pixel ${kPixels[i % kPixels.length]} at roughness ${roughness[i]} (NdotV ${ndotv[i]}), ` +
            `channel ${c}: three.js ${pixel[c]}, CPU ${expected}`);
    }
  });
  console.log(`three.js ${threeVersion()}: ` +
              `${result.pixels.length} pixels of gold's compensated Fbar, largest difference ${worst.toExponential(2)}`);
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
