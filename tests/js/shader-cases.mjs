// What the browser (WebGL2) and Dawn (WGSL) checks share: the query grid of `matc validate`, the
// example materials compiled once, and the CPU runtime's values for them from `matc eval`.
import { spawnSync } from "node:child_process";
import { readFileSync, readdirSync } from "node:fs";
import { join } from "node:path";

// matc validate's tolerances (docs/validation.md).
export const kFresnelTolerance = 1e-5;
export const kPreintegratedTolerance = 1e-4;
// Fbar from the table's closed form (matc_preintegrated_basis_analytic): float32 arithmetic only.
export const kClosedFormTolerance = 1e-5;

// Textured metals: per-channel (reflectivity, edge tint), the coefficient table's corners among
// them.
export const kTexturedMetals = [
  [[0.9, 0.6, 0.3], [0.8, 0.5, 0.2]],
  [[0.02, 0.5, 0.98], [1.0, 0.0, 0.5]],
  [[0.0, 1.0, 0.45], [0.0, 1.0, 1.0]],
];

export function run(command, args, options = {}) {
  const result = spawnSync(command, args, { encoding: "utf8", maxBuffer: 256 << 20, ...options });
  if (result.status !== 0) {
    throw new Error(`${command} ${args.slice(0, 3).join(" ")} ...: exit ${result.status}\n` +
                    `${result.stderr}`);
  }
  return result.stdout;
}

// matc validate's grid: (NdotV, roughness) = (i, j) / 40 over 41 x 41, each beside a cosine
// mu_k = k / (n - 1). Values are float32, as the shaders read them; `flat` is (mu, NdotV,
// roughness, 0) per query.
export function validationQueries() {
  const grid = 41;
  const count = grid * grid;
  const mu = new Float32Array(count), ndotv = new Float32Array(count);
  const roughness = new Float32Array(count), flat = new Float32Array(count * 4);
  for (let i = 0; i < grid; ++i) {
    for (let j = 0; j < grid; ++j) {
      const k = i * grid + j;
      mu[k] = k / (count - 1);
      ndotv[k] = i / (grid - 1);
      roughness[k] = j / (grid - 1);
      flat.set([mu[k], ndotv[k], roughness[k], 0], 4 * k);
    }
  }
  return { count, mu, ndotv, roughness, flat };
}

// Compiles every example material into `out` with the given options (which must fix the tables'
// precisions; `emit` names more outputs than the snippets and the two tables) and returns, per material, its name, its snippet in `language` and the CPU runtime's
// F, Fbar and Fbar from the table's closed form at the queries; then the textured metals' F and
// both Fbar through the coefficient table.
export function compileAndEvaluate(matc, materialsDir, out, language, options, queries, emit = []) {
  const files = readdirSync(materialsDir).filter((f) => f.endsWith(".json")).sort()
                  .map((f) => join(materialsDir, f));
  run(matc, ["-q", "-o", out, "--emit", [language, "lut", "coefficient-table", ...emit].join(","), "--lut", "raw",
             ...options, ...files]);
  const list = (values) => Array.from(values).join(",");
  const evaluate = (args) => JSON.parse(run(matc, [
    "eval", ...args, ...options, "--no-reference", "--mu", list(queries.mu),
    "--ndotv", list(queries.ndotv), "--roughness", list(queries.roughness)]));
  const materials = files.map((file) => {
    const evaluated = evaluate([file]);
    // A coated material's F and Fbar are its two lobes' sum (docs/coating.md); a filmed one's
    // come from its own table, <name>.film.<ext> (docs/thin-film.md), and it has no closed form.
    return { name: evaluated.name, basis: evaluated.basis, F: evaluated.F, Fbar: evaluated.Fbar,
             FbarAnalytic: evaluated.Fbar_analytic, coated: "coat" in evaluated,
             filmed: "film_table" in evaluated,
             snippet: readFileSync(join(out, `${evaluated.name}.${language}`), "utf8") };
  });
  const textured = kTexturedMetals.map(([reflectivity, edgeTint]) => {
    const evaluated = evaluate(["--reflectivity", reflectivity.join(","),
                                "--edge-tint", edgeTint.join(",")]);
    return { name: `table r=${reflectivity} g=${edgeTint}`, reflectivity, edgeTint,
             F: evaluated.F_table, Fbar: evaluated.Fbar_table,
             FbarAnalytic: evaluated.Fbar_analytic_table };
  });
  return { materials, textured, library: readFileSync(join(out, `matc_fresnel.${language}`), "utf8") };
}

// The largest |actual - expected| over the queries and RGB channels, and where; `actual` holds
// `stride` floats per query starting at `offset`.
export function largestDifference(actual, expected, stride, offset) {
  let worst = 0, where = 0;
  for (let i = 0; i < expected.length; ++i) {
    for (let c = 0; c < 3; ++c) {
      const difference = Math.abs(actual[i * stride + offset + c] - expected[i][c]);
      if (!(difference <= worst)) {
        worst = difference;
        where = i;
      }
    }
  }
  return { max_abs: worst, query: where };
}

// What the shaders' matc_fresnel_preintegrated(c, bbar) * matc_energy_compensation(c, bbar)
// give, from the CPU runtime's Fbar, the coefficients' c_0 (F0) and the table's directional
// albedo E = bbar_0 (Fbar of r = 1 through the coefficient table): Fbar (1 + F0 (1 - E) / E).
export function compensatedFbar(fbar, f0, albedo) {
  const e = Math.max(albedo, 1e-4);  // the shaders' guard for the NdotV = 0 column
  return fbar.map((value, c) => value * (1 + f0[c] * (1 - e) / e));
}
