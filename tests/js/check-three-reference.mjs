// three.js's MeshPhysicalMaterial with matc's Fresnel (examples/web/three) and the stock one
// (F0 = the material's F0, Schlick's Fresnel), both against the project's Monte-Carlo reference of
// the same scene (tests/js/engine-scene.mjs: a sphere under an environment map, a point light and
// a rect area light), rendered by WebGLRenderer in headless Chromium for the Figure 2 material
// and beryllium. Errors are radiance-weighted (sum |render - reference| / sum reference) per
// region of the sphere by NdotV: where the Fresnel dominates (grazing, NdotV < 0.3), matc's must
// be at most half the stock material's; elsewhere within the split sum's own error (no more than
// the stock material's plus 10% of it, where both have the exact F0).
// The textured inlay (examples/textured) is rendered the same way through the coefficient table
// and through its bake, against a reference with each pixel's exact conductor Fresnel.
//   node check-three-reference.mjs MATC MATERIALS_DIR EXAMPLES_WEB_DIR MATC_EXAMPLE_MAPS
//        EXAMPLES_TEXTURED_DIR [--markdown] [--images DIR] [--size N] [--lights PATH] [--timing]
// --markdown prints docs/web-engines.md's table (the checks' lines go to stderr); --images
// writes the comparison panels as PNG.
import { cpSync, mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { kWebImportMap, kWebRoots, runPage, threeVersion } from "./browser-page.mjs";
import { environmentTexels, kReferenceFragmentShader, kReferenceVertexShader, kScene,
         rectLightGeometry, sceneWith } from "./engine-scene.mjs";
import { displayByte, writePng } from "./png.mjs";
import { check, finish } from "./report.mjs";
import { run } from "./shader-cases.mjs";

const [matc, materialsDir, webDir, exampleMaps, texturedDir, ...options] = process.argv.slice(2);
const markdown = options.includes("--markdown");
const optionValue = (name) => options.includes(name) ? options[options.indexOf(name) + 1] : null;
const imagesDir = optionValue("--images");
const lightPaths = optionValue("--lights") ?? "all";  // one light path alone: environment, point, rect
const size = Number(optionValue("--size") ?? kScene.size);
const print = console.log;
if (markdown) console.log = (...args) => console.error(...args);

const kMaterials = ["figure2_edge_tint", "beryllium"];
// Regions of the sphere by NdotV, and what each must show. The silhouette's pixels shade with a
// roughness the normal's derivative widened towards 1 and sit where the split sum is poorest:
// there matc's material must be closer than the stock one. Grazing and middle angles are where
// Schlick's curve leaves the exact one: at most half the stock error. At the centre both have
// the exact F0, and what is left is the split sum's own error.
const kRegions = [
  { name: "silhouette (NdotV < 0.1)", test: (nv) => nv < 0.1, bound: 1.0, means: "closer than stock" },
  { name: "grazing (0.1-0.3)", test: (nv) => nv >= 0.1 && nv < 0.3, bound: 0.5, means: "at most half" },
  { name: "middle (0.3-0.7)", test: (nv) => nv >= 0.3 && nv < 0.7, bound: 0.5, means: "at most half" },
  { name: "centre (NdotV >= 0.7)", test: (nv) => nv >= 0.7, bound: 1.1,
    means: "the split sum's own error: no more than stock + 10%" },
];

const kPage = (config) => `<!doctype html><html><body><pre id="result">not run</pre>
<script type="application/json" id="config">${JSON.stringify(config)}</script>
<script type="importmap">${kWebImportMap}</script>
<script type="module">
import * as THREE from "three";
import { RectAreaLightUniformsLib } from "three/addons/lights/RectAreaLightUniformsLib.js";
import { KTX2Loader } from "three/addons/loaders/KTX2Loader.js";
import { loadMatcBuild, useMatcFresnel } from "/web/three/matc-three.mjs";
${environmentTexels.toString()}
const config = JSON.parse(document.getElementById("config").textContent);
const scene = config.scene;
const out = { errors: [], images: {} };
const base64 = (floats) => {
  const bytes = new Uint8Array(floats.buffer);
  let binary = "";
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(binary);
};
try {
  const renderer = new THREE.WebGLRenderer({ canvas: document.createElement("canvas") });
  renderer.debug.onShaderError = (gl, program, vertex, fragment) =>
    out.errors.push(gl.getShaderInfoLog(fragment) || gl.getShaderInfoLog(vertex) || gl.getProgramInfoLog(program));
  renderer.setClearColor(0x000000, 0);
  RectAreaLightUniformsLib.init();
  const build = await loadMatcBuild("/out/");
  const size = scene.size;
  const target = new THREE.WebGLRenderTarget(size, size, { type: THREE.FloatType });
  const camera = new THREE.PerspectiveCamera(scene.camera.fov, 1, scene.camera.near, scene.camera.far);
  camera.position.set(...scene.camera.position);
  camera.lookAt(0, 0, 0);
  const equirect = new THREE.DataTexture(environmentTexels(scene.environment.width, scene.environment.height, scene.environment.intensity),
                                         scene.environment.width, scene.environment.height,
                                         THREE.RGBAFormat, THREE.FloatType);
  equirect.mapping = THREE.EquirectangularReflectionMapping;
  equirect.magFilter = equirect.minFilter = THREE.LinearFilter;
  equirect.wrapS = THREE.RepeatWrapping;
  equirect.needsUpdate = true;
  const environment = new THREE.PMREMGenerator(renderer).fromEquirectangular(equirect).texture;
  const sphere = new THREE.SphereGeometry(1, 256, 128);
  const lights = () => {
    const point = new THREE.PointLight(0xffffff, scene.point.intensity, 0, 2);
    point.position.set(...scene.point.position);
    const rect = new THREE.RectAreaLight(0xffffff, scene.rect.intensity, scene.rect.width, scene.rect.height);
    rect.position.set(...scene.rect.position);
    rect.lookAt(0, 0, 0);
    return [point, rect];
  };
  const draw = (key, material, withLights) => {
    const world = new THREE.Scene();
    world.add(new THREE.Mesh(sphere, material));
    if (withLights) {
      world.environment = environment;
      world.add(...lights());
    }
    renderer.setRenderTarget(target);
    renderer.render(world, camera);  // compiles
    const pixels = new Float32Array(size * size * 4);
    renderer.readRenderTargetPixels(target, 0, 0, size, size, pixels);
    out.images[key] = base64(pixels);
    // Frame time (--timing): the same frame drawn again, finished by reading a pixel back; timed
    // from outside, as the page's clock is virtual.
    if (withLights && config.timing?.kind && key.endsWith(config.timing.kind)) {
      for (let i = 0; i < config.timing.frames; ++i) renderer.render(world, camera);
      renderer.readRenderTargetPixels(target, 0, 0, 1, 1, new Float32Array(4));
    }
  };
  const references = (material) => ({
      reference_environment: { value: equirect }, reference_albedo: { value: build.lut },
      reference_roughness: { value: material.roughness },
      reference_point_position: { value: new THREE.Vector3(...scene.point.position) },
      reference_point_intensity: { value: scene.point.intensity },
      reference_rect_origin: { value: new THREE.Vector3(...config.rect.origin) },
      reference_rect_u: { value: new THREE.Vector3(...config.rect.edgeU) },
      reference_rect_v: { value: new THREE.Vector3(...config.rect.edgeV) },
      reference_rect_normal: { value: new THREE.Vector3(...config.rect.normal) },
      reference_rect_intensity: { value: scene.rect.intensity },
      reference_environment_samples: { value: scene.samples.environment },
      reference_rect_side: { value: scene.samples.rectSide },
      reference_lut_size: { value: build.lut.image.width },
      reference_textured: { value: 0 }, reference_f0: { value: new THREE.Vector3() },
  });
  const referenceMaterial = (uniforms) => new THREE.ShaderMaterial({
      glslVersion: THREE.GLSL3, uniforms, vertexShader: config.vertexShader, fragmentShader: config.fragmentShader });
  if (config.textured) {
    // The inlay: its sRGB maps (rows as stored, like the bake's KTX2 files), the bake's textures
    // sampled trilinearly.
    const textured = config.textured;
    const loader = new THREE.TextureLoader();
    const map = async (url) => {
      const texture = await loader.loadAsync(url);
      texture.colorSpace = THREE.SRGBColorSpace;
      texture.flipY = false;
      return texture;
    };
    const reflectivity = await map("/textured/maps/inlaid_metals_r.png");
    const edgeTint = await map("/textured/maps/inlaid_metals_g.png");
    const ktx2 = new KTX2Loader().detectSupport(renderer);
    const baked = async (file) => ktx2.loadAsync("/textured/baked/" + file);
    const uniforms = { ...references(textured), reference_textured: { value: 1 },
                       reference_reflectivity_map: { value: reflectivity }, reference_edge_tint_map: { value: edgeTint } };
    if (!config.timing) draw(textured.name + " reference", referenceMaterial(uniforms), false);
    draw(textured.name + " stock", new THREE.MeshPhysicalMaterial({ metalness: 1, roughness: textured.roughness,
                                                                    map: reflectivity }), true);
    draw(textured.name + " matc", useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness: textured.roughness }),
                                                 build, { reflectivityMap: reflectivity, edgeTintMap: edgeTint }), true);
    draw(textured.name + " baked", useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness: textured.roughness }),
        build, { baked: { c2Map: await baked("inlaid_metals_c2.ktx2"), c3Map: await baked("inlaid_metals_c3.ktx2"),
                          f0Map: await baked("inlaid_metals_f0.ktx2") } }), true);
  }
  for (const material of config.materials) {
    const fresnel = new THREE.DataTexture(new Float32Array(material.exactFresnel), material.exactFresnel.length / 4, 1,
                                          THREE.RGBAFormat, THREE.FloatType);
    fresnel.magFilter = fresnel.minFilter = THREE.LinearFilter;
    fresnel.needsUpdate = true;
    const uniforms = { ...references(material), reference_fresnel: { value: fresnel },
                       reference_f0: { value: new THREE.Vector3(...material.f0) } };
    if (!config.timing) draw(material.name + " reference", referenceMaterial(uniforms), false);
    const stock = new THREE.MeshPhysicalMaterial({ metalness: 1, roughness: material.roughness,
      color: new THREE.Color().setRGB(...material.f0, THREE.LinearSRGBColorSpace) });
    draw(material.name + " stock", stock, true);
    const ours = useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness: material.roughness }), build,
                                { material: await build.loadMaterial(material.name) });
    draw(material.name + " matc", ours, true);
  }
} catch (error) {
  out.errors.push(String(error.stack || error));
}
document.getElementById("result").textContent = JSON.stringify(out);
</script></body></html>
`;

const floats = (text) => new Float32Array(Buffer.from(text, "base64").buffer.slice(0));

// Radiance-weighted error per region and channel: sum |x - reference| / sum reference.
function regionErrors(image, reference) {
  return kRegions.map((region) => {
    const difference = [0, 0, 0], total = [0, 0, 0];
    let pixels = 0;
    for (let i = 0; i < reference.length; i += 4) {
      if (reference[i + 3] === 0) continue;  // background
      const nv = reference[i + 3] - 1;
      if (!region.test(nv)) continue;
      pixels += 1;
      for (let c = 0; c < 3; ++c) {
        difference[c] += Math.abs(image[i + c] - reference[i + c]);
        total[c] += reference[i + c];
      }
    }
    const all = difference.reduce((a, b) => a + b) / total.reduce((a, b) => a + b);
    return { pixels, channels: difference.map((d, c) => d / total[c]), all };
  });
}

function writePanels(path, panels) {
  const rgb = new Uint8Array(size * panels.length * size * 3);
  panels.forEach(({ image, scaleBy, against }, p) => {
    for (let y = 0; y < size; ++y) {
      for (let x = 0; x < size; ++x) {
        const i = 4 * ((size - 1 - y) * size + x);  // render targets are bottom-up
        const o = 3 * (y * size * panels.length + p * size + x);
        for (let c = 0; c < 3; ++c) {
          rgb[o + c] = against
              ? Math.round(Math.min(1, Math.abs(image[i + c] - against[i + c]) * scaleBy) * 255)
              : displayByte(image[i + c]);
        }
      }
    }
  });
  writePng(path, size * panels.length, size, rgb);
}

const dir = mkdtempSync(join(tmpdir(), "matc-three-reference-"));
try {
  const out = join(dir, "out");
  run(matc, ["-q", "-o", out, "--emit", "glsl,json,lut,ltc,coefficient-table", "--lut-precision", "f32",
             ...kMaterials.map((name) => join(materialsDir, `${name}.json`))]);
  const cosines = Array.from({ length: kScene.fresnelSamples }, (_, i) => i / (kScene.fresnelSamples - 1));
  const materials = kMaterials.map((name) => {
    const compiled = JSON.parse(readFileSync(join(out, `${name}.json`), "utf8"));
    const exact = JSON.parse(run(matc, ["eval", join(materialsDir, `${name}.json`), "--mu", cosines.join(",")]))
                    .F_exact;
    return { name, roughness: compiled.roughness, f0: compiled.coefficients.map((row) => row[0]),
             exactFresnel: exact.flatMap((rgb) => [...rgb, 1]) };
  });
  // The inlay's maps and bake, as the examples' build makes them.
  const textured = join(dir, "textured");
  run(exampleMaps, ["--size", "512", "-o", join(textured, "maps")]);
  cpSync(join(texturedDir, "inlaid_metals.json"), join(textured, "inlaid_metals.json"));
  run(matc, ["bake", "-q", "--f0", "-o", join(textured, "baked"), join(textured, "inlaid_metals.json")]);
  const config = { textured: { name: "inlaid_metals", roughness: 0.3 }, scene: { ...sceneWith(lightPaths), size }, materials, rect: rectLightGeometry(kScene.rect),
                   vertexShader: kReferenceVertexShader, fragmentShader: kReferenceFragmentShader };
  const result = await runPage({ html: kPage(config), roots: { ...kWebRoots, web: webDir, out, textured }, dir,
                                 budgetMs: 600000 });
  check(result.errors.length === 0, `three.js: ${result.errors.join("\n")}`);
  const rows = [];
  for (const { name } of materials) {
    const images = ["reference", "stock", "matc"].map((kind) => result.images[`${name} ${kind}`]);
    check(images.every(Boolean), `${name}: not every image was rendered`);
    if (!images.every(Boolean)) continue;
    const [reference, stock, ours] = images.map(floats);
    const stockErrors = regionErrors(stock, reference), oursErrors = regionErrors(ours, reference);
    kRegions.forEach((region, r) => {
      const s = stockErrors[r], o = oursErrors[r];
      check(o.pixels > 50, `${name}, ${region.name}: only ${o.pixels} pixels`);
      check(o.all <= region.bound * s.all, `${name}, ${region.name}: matc's error ${o.all.toFixed(4)} ` +
                                           `against the stock material's ${s.all.toFixed(4)}: not ${region.means}`);
      rows.push({ name, region: region.name, pixels: o.pixels, stock: s, ours: o });
    });
    if (imagesDir) {
      writePanels(join(imagesDir, `three_${name}.png`), [{ image: reference }, { image: stock }, { image: ours }]);
      writePanels(join(imagesDir, `three_${name}_difference.png`), [
        { image: stock, against: reference, scaleBy: 4 }, { image: ours, against: reference, scaleBy: 4 }]);
    }
  }
  // The inlay through the coefficient table and through its bake.
  const inlay = config.textured.name;
  const texturedImages = ["reference", "stock", "matc", "baked"].map((kind) => result.images[`${inlay} ${kind}`]);
  check(texturedImages.every(Boolean), `${inlay}: not every image was rendered`);
  if (texturedImages.every(Boolean)) {
    const [reference, stock, table, baked] = texturedImages.map(floats);
    const stockErrors = regionErrors(stock, reference);
    for (const [label, image] of [["coefficient table", table], ["baked", baked]]) {
      regionErrors(image, reference).forEach((o, r) => {
        const s = stockErrors[r];
        check(o.all <= s.all, `${inlay} (${label}), ${kRegions[r].name}: matc's error ${o.all.toFixed(4)} ` +
                              `is not below the stock material's ${s.all.toFixed(4)}`);
        rows.push({ name: `${inlay} (${label})`, region: kRegions[r].name, pixels: o.pixels, stock: s, ours: o });
      });
    }
    if (imagesDir) {
      writePanels(join(imagesDir, `three_${inlay}.png`),
                  [{ image: reference }, { image: stock }, { image: table }, { image: baked }]);
      writePanels(join(imagesDir, `three_${inlay}_difference.png`), [
        { image: stock, against: reference, scaleBy: 4 }, { image: table, against: reference, scaleBy: 4 },
        { image: baked, against: reference, scaleBy: 4 }]);
    }
  }
  const percent = (x) => `${(100 * x).toFixed(1)}%`;
  const table = [
    `three.js ${threeVersion()} (WebGLRenderer, ANGLE on SwiftShader), ${size}x${size} pixels; ` +
    `reference: ${kScene.samples.environment} environment samples and ${kScene.samples.rectSide ** 2} ` +
    "rect-light samples per pixel. Radiance-weighted error against the reference, " +
    "sum |render - reference| / sum reference, per region of the sphere (all channels; R, G, B):",
    "",
    "| material | region | pixels | stock three.js | with matc | stock R, G, B | matc R, G, B |",
    "|---|---|---:|---:|---:|---|---|",
    ...rows.map(({ name, region, pixels, stock, ours }) =>
      `| ${name} | ${region} | ${pixels} | ${percent(stock.all)} | ${percent(ours.all)} | ` +
      `${stock.channels.map(percent).join(", ")} | ${ours.channels.map(percent).join(", ")} |`),
  ];
  if (options.includes("--timing")) {
    // The page's extra frames cost, timed from outside: (frames drawn 100 times) - (0 times).
    const frames = 100;
    const seconds = async (timing) => {
      const start = process.hrtime.bigint();
      await runPage({ html: kPage({ ...config, timing }), roots: { ...kWebRoots, web: webDir, out, textured }, dir,
                      budgetMs: 600000 });
      return Number(process.hrtime.bigint() - start) / 1e9;
    };
    const perFrame = {};  // the inlay's two matc paths count as one material
    for (const kind of ["stock", "matc"]) {
      perFrame[kind] = (1000 * ((await seconds({ kind, frames })) - (await seconds({ kind, frames: 0 })))) /
                       (frames * (materials.length + 1));
    }
    table.push("", `Frame time of this ${size}x${size} frame on SwiftShader (Chromium's CPU rasteriser: ` +
               "it shows the shaders' ALU and texture work, not a GPU's timing), from the wall-clock " +
               `time of ${frames} extra frames per material: stock ${perFrame.stock.toFixed(1)} ms, ` +
               `with matc ${perFrame.matc.toFixed(1)} ms.`);
  }
  if (markdown) print(table.join("\n"));
  else console.log(table.join("\n"));
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
