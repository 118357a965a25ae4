// The GLSL output as GLSL ES 3.00 in WebGL2, run by an implementation matc did not write: headless
// Chromium (ANGLE translating for SwiftShader). Every example material's snippet is compiled with
// the shared library into a fragment shader that renders F over the cosines, Fbar from the
// preintegrated table (an RGBA32F texture, linear filtering) and Fbar from the table's closed form
// (matc_preintegrated_basis_analytic) over the (NdotV, roughness) grid of `matc validate`, into an
// RGBA32F target read back as floats. Textured metals too: coefficients
// from the coefficient table (an RG32F texture) for a few per-channel (r, g). Everything is
// compared with the CPU runtime (`matc eval`) at matc validate's tolerances: F and the closed form
// 1e-5, Fbar and anything through the coefficient table 1e-4. By default a build gives each
// material its own basis: each material through its basis' functions and its layer of the wider
// table; --basis NAME forces one basis (one layer) on every material.
//   node check-webgl2.mjs MATC MATERIALS_DIR [--basis NAME]
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import { runPage } from "./browser-page.mjs";
import { check, finish } from "./report.mjs";
import {
  compileAndEvaluate, kClosedFormTolerance, kFresnelTolerance, kPreintegratedTolerance,
  largestDifference, run, validationQueries,
} from "./shader-cases.mjs";

const [matc, materialsDir, ...rest] = process.argv.slice(2);
const basisOptions = rest[0] === "--basis" ? ["--basis", rest[1]] : [];

// The page: uploads the table and the queries, compiles one program per case, renders, reads
// back and writes the pixels (base64 floats) into <pre id="result"> as JSON.
const kPageScript = String.raw`
const data = JSON.parse(document.getElementById("data").textContent);
const out = { renderer: "", materials: [] };
try {
  const canvas = document.createElement("canvas");
  const gl = canvas.getContext("webgl2");
  if (!gl) throw new Error("no WebGL2 context");
  for (const extension of ["EXT_color_buffer_float", "OES_texture_float_linear"])
    if (!gl.getExtension(extension)) throw new Error("no " + extension);
  const info = gl.getExtension("WEBGL_debug_renderer_info");
  out.renderer = info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
  const floats = (base64) => new Float32Array(Uint8Array.from(atob(base64), (c) => c.charCodeAt(0)).buffer);
  const texture = (unit, width, height, texels, filter) => {
    const t = gl.createTexture();
    gl.activeTexture(gl.TEXTURE0 + unit);
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, height, 0, gl.RGBA, gl.FLOAT, texels);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, filter);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, filter);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    return t;
  };
  const count = data.queries.length / 4;
  texture(0, data.lutWidth, data.lutHeight, floats(data.lut), gl.LINEAR);
  texture(1, count, 1, new Float32Array(data.queries), gl.NEAREST);
  // The coefficient table's (c_2, c_3) texels, widened to RGBA.
  const table = floats(data.table);
  const tableTexels = new Float32Array(table.length * 2);
  for (let i = 0; i < table.length / 2; ++i) tableTexels.set([table[2 * i], table[2 * i + 1], 0, 0], 4 * i);
  texture(2, data.tableSize, data.tableSize, tableTexels, gl.LINEAR);
  const target = texture(3, count, 3, null, gl.NEAREST);
  const framebuffer = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, target, 0);
  if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE)
    throw new Error("RGBA32F render target incomplete");
  gl.viewport(0, 0, count, 3);
  const compile = (type, source) => {
    const shader = gl.createShader(type);
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(shader));
    return shader;
  };
  const vertex = compile(gl.VERTEX_SHADER, "#version 300 es\nvoid main() {\n" +
    "  vec2 p = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1)) - 1.0;\n" +
    "  gl_Position = vec4(p, 0.0, 1.0);\n}\n");
  for (const material of data.cases) {
    const result = { name: material.name };
    out.materials.push(result);
    try {
      const program = gl.createProgram();
      gl.attachShader(program, vertex);
      gl.attachShader(program, compile(gl.FRAGMENT_SHADER, data.prelude + data.library + material.source));
      gl.linkProgram(program);
      if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(program));
      gl.useProgram(program);
      gl.uniform1i(gl.getUniformLocation(program, "matc_lut"), 0);
      gl.uniform1i(gl.getUniformLocation(program, "matc_queries"), 1);
      gl.uniform1i(gl.getUniformLocation(program, "matc_coefficient_table"), 2);
      for (const [name, value] of Object.entries(material.uniforms || {}))
        gl.uniform3fv(gl.getUniformLocation(program, name), value);
      // A filmed metal's own table (65 x 18 RGBA32F, linear filtering; a thickness per pixel's
      // stack 65 x 18 slices) on unit 4, and the stack's thickness coordinate.
      if (material.film) {
        texture(4, 65, material.filmRows || 18, floats(material.film), gl.LINEAR);
        if (material.thickness !== undefined)
          gl.uniform1f(gl.getUniformLocation(program, "matc_thickness"), material.thickness);
        gl.uniform1i(gl.getUniformLocation(program, "matc_film"), 4);
        gl.activeTexture(gl.TEXTURE0);
      }
      gl.drawArrays(gl.TRIANGLES, 0, 3);
      const pixels = new Float32Array(count * 3 * 4);
      gl.readPixels(0, 0, count, 3, gl.RGBA, gl.FLOAT, pixels);
      // Read back as base64 of the float bytes; Node compares them with the CPU runtime.
      const bytes = new Uint8Array(pixels.buffer);
      let binary = "";
      for (let i = 0; i < bytes.length; i += 0x8000)
        binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
      result.pixels = btoa(binary);
    } catch (error) {
      result.error = String(error.message || error);
    }
  }
} catch (error) {
  out.error = String(error.message || error);
}
document.getElementById("result").textContent = JSON.stringify(out);
`;

// What every fragment shader puts before the library, and what follows it: row 0 of the target
// is F(mu), row 1 Fbar(NdotV, roughness) through the table, row 2 the same from its closed form,
// one column per query. COEFFICIENTS is a compiled
// material's constant or the coefficient table's result.
const kPrelude = "#version 300 es\nprecision highp float;\nprecision highp int;\n" +
                 "precision highp sampler2D;\n";
// `suffix`: the material's basis' functions in a per-material build ("_f82"), else none.
const main = (coefficients, suffix = "") => `
uniform sampler2D matc_lut;
uniform sampler2D matc_queries;
uniform sampler2D matc_coefficient_table;
uniform vec3 matc_reflectivity;
uniform vec3 matc_edge_tint;
out vec4 matc_result;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 query = texelFetch(matc_queries, ivec2(pixel.x, 0), 0);  // mu, NdotV, roughness
  vec3 r = matc_reflectivity;
  vec3 g = matc_edge_tint;
  MatcFresnelCoefficients c = ${coefficients};
  vec3 value = pixel.y == 0
      ? matc_fresnel${suffix}(c, query.x)
      : matc_fresnel_preintegrated(c, pixel.y == 1
            ? texture(matc_lut, matc_lut_texcoord${suffix}(query.y, query.z))
            : matc_preintegrated_basis_analytic${suffix}(query.y, query.z));
  matc_result = vec4(value, 1.0);
}
`;

// The same for coated material `name` through its own functions: both lobes summed, the coat's
// texel sampled at the coat's roughness.
const coatedMain = (name) => `
uniform sampler2D matc_lut;
uniform sampler2D matc_queries;
out vec4 matc_result;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 query = texelFetch(matc_queries, ivec2(pixel.x, 0), 0);  // mu, NdotV, roughness
  float coat_roughness = matc_coat_roughness_${name};
  vec4 bbar = pixel.y == 1 ? texture(matc_lut, matc_lut_texcoord(query.y, query.z))
                           : matc_preintegrated_basis_analytic(query.y, query.z);
  vec4 coat_bbar = pixel.y == 1 ? texture(matc_lut, matc_lut_texcoord(query.y, coat_roughness))
                                : matc_preintegrated_basis_analytic(query.y, coat_roughness);
  vec3 value = pixel.y == 0
      ? matc_fresnel_${name}(query.x) + matc_coat_fresnel_${name}(query.x)
      : matc_fresnel_preintegrated_${name}(bbar, coat_bbar, query.y) +
            matc_coat_fresnel_preintegrated_${name}(coat_bbar);
  matc_result = vec4(value, 1.0);
}
`;

// The same for filmed material `name` through its own table (docs/thin-film.md): row 0 F(mu),
// rows 1 and 2 Fbar(NdotV, roughness), both fetched from the table (it has no closed form).
const filmMain = (name) => `
uniform sampler2D matc_film;
uniform sampler2D matc_queries;
out vec4 matc_result;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 query = texelFetch(matc_queries, ivec2(pixel.x, 0), 0);  // mu, NdotV, roughness
  vec3 value = pixel.y == 0
      ? matc_fresnel_${name}(MATC_FILM_FRESNEL(matc_film, query.x))
      : matc_fresnel_preintegrated_${name}(MATC_FILM_PREINTEGRATED(matc_film, query.y, query.z));
  matc_result = vec4(value, 1.0);
}
`;

// The same for a thickness per pixel (docs/thin-film.md "A thickness per pixel"): the stack read
// at the thickness coordinate matc_thickness.
const filmStackMain = (name) => `
uniform sampler2D matc_film;
uniform sampler2D matc_queries;
uniform float matc_thickness;
out vec4 matc_result;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 query = texelFetch(matc_queries, ivec2(pixel.x, 0), 0);  // mu, NdotV, roughness
  float slices = matc_film_slices_${name};
  vec3 value = pixel.y == 0
      ? matc_fresnel_${name}(MATC_FILM_STACK_FRESNEL(matc_film, query.x, matc_thickness, slices))
      : matc_fresnel_preintegrated_${name}(MATC_FILM_STACK_PREINTEGRATED(matc_film,
            matc_film_stack_preintegrated_texcoords(query.y, query.z, matc_thickness, slices)));
  matc_result = vec4(value, 1.0);
}
`;

// The same for a filmed material under a coat (docs/thin-film.md, "Under a coat"): the base lobe
// from its table, the coat lobe from matc_lut at the coat's roughness, summed.
const filmCoatedMain = (name) => `
uniform sampler2D matc_lut;
uniform sampler2D matc_film;
uniform sampler2D matc_queries;
out vec4 matc_result;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 query = texelFetch(matc_queries, ivec2(pixel.x, 0), 0);  // mu, NdotV, roughness
  vec4 coat_bbar = texture(matc_lut, matc_lut_texcoord(query.y, matc_coat_roughness_${name}));
  vec3 value = pixel.y == 0
      ? matc_fresnel_${name}(MATC_FILM_FRESNEL(matc_film, query.x)) + matc_coat_fresnel_${name}(query.x)
      : matc_fresnel_preintegrated_${name}(MATC_FILM_PREINTEGRATED(matc_film, query.y, query.z)) +
            matc_coat_fresnel_preintegrated_${name}(coat_bbar);
  matc_result = vec4(value, 1.0);
}
`;

const dir = mkdtempSync(join(tmpdir(), "matc-webgl2-"));
try {
  const queries = validationQueries();
  const { materials, textured, library } = compileAndEvaluate(
      matc, materialsDir, join(dir, "out"), "glsl",
      ["--lut-precision", "f32", "--coefficient-table-precision", "f32", ...basisOptions], queries);
  const layers = JSON.parse(readFileSync(join(dir, "out", "matc_lut.bin.json"), "utf8")).layers;
  const suffix = (basis) => (layers && basis !== layers[0].basis ? `_${basis}` : "");
  const cases = materials.map((m) => m.filmed ? {
    // Sampled: the table's tolerance; rows 1 and 2 both Fbar.
    name: m.name, F: m.F, Fbar: m.Fbar, FbarAnalytic: m.Fbar, tolerance: kPreintegratedTolerance,
    film: readFileSync(join(dir, "out", `${m.name}.film.bin`)).toString("base64"),
    source: m.snippet + (m.coated ? filmCoatedMain(m.name) : filmMain(m.name)) } : {
    name: m.name, F: m.F, Fbar: m.Fbar, FbarAnalytic: m.FbarAnalytic, tolerance: kFresnelTolerance,
    source: m.snippet + (m.coated ? coatedMain(m.name)
                                  : main(`matc_coefficients_${m.name}`, suffix(m.basis))) });
  const bases = new Set(materials.map((m) => m.basis));
  if (basisOptions.length) {
    check(bases.size === 1 && !layers, `--basis ${basisOptions[1]} gave bases ${[...bases]}`);
  } else {
    check(bases.size > 1 && layers?.length === 2, `a default build gave every material one basis (${[...bases]})`);
  }
  for (const metal of textured) {
    cases.push({ name: metal.name, F: metal.F, Fbar: metal.Fbar, FbarAnalytic: metal.FbarAnalytic,
                 tolerance: kPreintegratedTolerance,
                 uniforms: { matc_reflectivity: metal.reflectivity, matc_edge_tint: metal.edgeTint },
                 source: main("MATC_COEFFICIENTS_FROM_TABLE(matc_coefficient_table, r, g)") });
  }
  {
    // A thickness per pixel: tests/data/film_stack's material at one thickness of its range,
    // against matc eval --film-thickness.
    const file = new URL("../data/film_stack/titanium_heat_tint.json", import.meta.url).pathname;
    const stackOut = join(dir, "stack");
    const options = ["--lut-precision", "f32", ...basisOptions];
    run(matc, ["-q", "-o", stackOut, "--emit", "glsl,lut,json", "--lut", "raw", ...options, file]);
    const described = JSON.parse(readFileSync(join(stackOut, "titanium_heat_tint.json"), "utf8"));
    const { slices, thickness_nm: [minimum, maximum] } = described.film_stack;
    const nm = minimum + 0.3719 * (maximum - minimum);
    const list = (values) => Array.from(values).join(",");
    const evaluated = JSON.parse(run(matc, [
      "eval", file, ...options, "--no-reference", "--film-thickness", String(nm), "--mu", list(queries.mu),
      "--ndotv", list(queries.ndotv), "--roughness", list(queries.roughness)]));
    cases.push({ name: `titanium_heat_tint (${slices} slices, ${nm.toFixed(1)} nm)`, F: evaluated.F,
                 Fbar: evaluated.Fbar, FbarAnalytic: evaluated.Fbar, tolerance: kPreintegratedTolerance,
                 film: readFileSync(join(stackOut, "titanium_heat_tint.film.bin")).toString("base64"),
                 filmRows: 18 * slices, thickness: evaluated.film_thickness.coordinate,
                 source: readFileSync(join(stackOut, "titanium_heat_tint.glsl"), "utf8") +
                         filmStackMain("titanium_heat_tint") });
  }
  const lut = readFileSync(join(dir, "out", "matc_lut.bin"));
  const table = readFileSync(join(dir, "out", "matc_coefficient_table.bin"));
  const data = {
    prelude: kPrelude, library, queries: Array.from(queries.flat),
    cases: cases.map(({ name, source, uniforms, film, filmRows, thickness }) =>
      ({ name, source, uniforms, film, filmRows, thickness })),
    lut: lut.toString("base64"), lutHeight: Math.round(Math.sqrt(lut.length / 16 / (layers?.length ?? 1))),
    lutWidth: Math.round(Math.sqrt(lut.length / 16 / (layers?.length ?? 1))) * (layers?.length ?? 1),
    table: table.toString("base64"), tableSize: Math.round(Math.sqrt(table.length / 8)),
  };
  const html = "<!doctype html><html><body><pre id=\"result\">not run</pre>\n" +
               "<script type=\"application/json\" id=\"data\">" +
               JSON.stringify(data).replaceAll("</", "<\\/") + "</script>\n" +
               `<script>${kPageScript}</script></body></html>\n`;
  const result = await runPage({ html, roots: {}, dir, budgetMs: 60000 });
  check(!result.error, `WebGL2: ${result.error}`);
  console.log(`WebGL2 renderer: ${result.renderer}`);
  check(result.materials.length === cases.length,
        `${result.materials.length} of ${cases.length} cases ran`);
  for (const [index, m] of result.materials.entries()) {
    const tolerance = cases[index].tolerance;
    if (m.error) {
      check(false, `${m.name}: ${m.error}`);
      continue;
    }
    const pixels = new Float32Array(Uint8Array.from(Buffer.from(m.pixels, "base64")).buffer);
    const count = queries.count;
    const fresnel = largestDifference(pixels, cases[index].F, 4, 0);           // row 0: F(mu)
    const preintegrated = largestDifference(pixels, cases[index].Fbar, 4, count * 4);  // row 1
    const closedForm = largestDifference(pixels, cases[index].FbarAnalytic, 4, count * 8);  // row 2
    console.log(`${m.name}: F ${fresnel.max_abs.toExponential(2)}, ` +
                `Fbar ${preintegrated.max_abs.toExponential(2)}, ` +
                `Fbar_analytic ${closedForm.max_abs.toExponential(2)}`);
    check(closedForm.max_abs <= Math.max(tolerance, kClosedFormTolerance),
          `${m.name}: |Fbar_analytic_webgl2 - Fbar_analytic_cpu| = ${closedForm.max_abs} at query ` +
          `${closedForm.query}`);
    check(fresnel.max_abs <= tolerance,
          `${m.name}: |F_webgl2 - F_cpu| = ${fresnel.max_abs} at query ${fresnel.query}`);
    check(preintegrated.max_abs <= kPreintegratedTolerance,
          `${m.name}: |Fbar_webgl2 - Fbar_cpu| = ${preintegrated.max_abs} at query ` +
          `${preintegrated.query}`);
  }
} finally {
  rmSync(dir, { recursive: true, force: true });
}
finish();
