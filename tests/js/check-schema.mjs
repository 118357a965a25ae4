// Checks docs/material.schema.json with an independent validator (Ajv) and checks that the schema
// and the matc binary agree: every case must be accepted by both or rejected by both.
//   node check-schema.mjs SCHEMA EXAMPLES_DIR MATC_BINARY
import { spawnSync } from "node:child_process";
import { mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";
import Ajv from "ajv";
import { check, finish } from "./report.mjs";

const [schemaPath, examplesDir, matc] = process.argv.slice(2);
// strictRequired would reject the standard `oneOf: [{required: [...]}]` idiom used for "exactly one of".
const ajv = new Ajv({ allErrors: true, strict: true, strictRequired: false });
const validate = ajv.compile(JSON.parse(readFileSync(schemaPath, "utf8")));

// Accepted means: compiles with exit 0 and prints no warning about the file (a poor-fit warning
// is about the physics of the values, which no schema can see, so it does not count).
function matcAccepts(text) {
  const dir = mkdtempSync(join(tmpdir(), "matc-schema-"));
  try {
    writeFileSync(join(dir, "m.json"), text);
    const run = spawnSync(matc, ["-q", "-o", join(dir, "out"), join(dir, "m.json")], {
      encoding: "utf8",
    });
    const warnings = run.stderr
      .split("\n")
      .filter((line) => line.includes("warning:") && !line.includes("poor fit"));
    return run.status === 0 && warnings.length === 0;
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

const ior = '"ior": {"n": 1.5, "k": 0}';
const cases = [
  // [description, material text, valid?]
  ["grey scalars", `{"name": "a", "artistic": {"reflectivity": 0.5, "edge_tint": 1}}`, true],
  ["rgb arrays", `{"name": "a", "artistic": {"reflectivity": [0, 0.5, 0.99], "edge_tint": [0, 0.5, 1]}}`, true],
  ["ior with extras", `{"$schema": "x", "name": "A_b1_", "description": "d", ${ior}, "roughness": 1}`, true],
  ["preset", `{"name": "a", "spectral": {"preset": "Cu"}}`, true],
  ["f82-tint", `{"name": "a", "f82_tint": {"f0": [0.9, 0.6, 0.3], "tint": 0.9}}`, true],
  ["f82-tint tint above 1", `{"name": "a", "f82_tint": {"f0": 0.9, "tint": 1.2}}`, false],
  ["f82-tint missing tint", `{"name": "a", "f82_tint": {"f0": 0.9}}`, false],
  ["f82-tint and ior", `{"name": "a", ${ior}, "f82_tint": {"f0": 0.9, "tint": 1}}`, false],
  ["colour space", `{"name": "a", "color_space": "acescg", ${ior}}`, true],
  ["colour space alias", `{"name": "a", "color_space": "lin_srgb", ${ior}}`, true],
  ["unknown colour space", `{"name": "a", "color_space": "srgb_texture", ${ior}}`, false],
  ["colour space not a string", `{"name": "a", "color_space": 1, ${ior}}`, false],
  ["missing name", `{${ior}}`, false],
  ["no model", `{"name": "a"}`, false],
  ["two models", `{"name": "a", ${ior}, "spectral": {"preset": "Au"}}`, false],
  ["unknown field", `{"name": "a", ${ior}, "roughnes": 0.5}`, false],
  ["unknown nested field", `{"name": "a", "ior": {"n": 1.5, "k": 0, "x": 1}}`, false],
  ["leading underscore", `{"name": "_a", ${ior}}`, false],
  ["double underscore", `{"name": "a__b", ${ior}}`, false],
  ["dash in name", `{"name": "a-b", ${ior}}`, false],
  ["digit first", `{"name": "1a", ${ior}}`, false],
  ["long name", `{"name": "${"a".repeat(65)}", ${ior}}`, false],
  ["reflectivity 1", `{"name": "a", "artistic": {"reflectivity": 1, "edge_tint": 0}}`, false],
  ["edge tint 1.1", `{"name": "a", "artistic": {"reflectivity": 0.5, "edge_tint": [0, 1.1, 0]}}`, false],
  ["two components", `{"name": "a", "ior": {"n": [1, 2], "k": 0}}`, false],
  ["negative k", `{"name": "a", "ior": {"n": 1, "k": -0.5}}`, false],
  ["huge n", `{"name": "a", "ior": {"n": 1001, "k": 0}}`, false],
  ["roughness 2", `{"name": "a", ${ior}, "roughness": 2}`, false],
  ["unknown preset", `{"name": "a", "spectral": {"preset": "Gold"}}`, false],
  ["zinc (warns)", `{"name": "a", "spectral": {"preset": "Zn"}}`, false],
  ["preset and file", `{"name": "a", "spectral": {"preset": "Au", "file": "x.csv"}}`, false],
  ["string number", `{"name": "a", "ior": {"n": "1.5", "k": 0}}`, false],
  ["film", `{"name": "a", "spectral": {"preset": "Ti"}, "film": {"ior": 2.3, "thickness": 40}}`, true],
  ["film, defaults", `{"name": "a", ${ior}, "film": {"thickness": 0}}`, true],
  ["film without thickness", `{"name": "a", ${ior}, "film": {"ior": 1.5}}`, false],
  ["film thickness negative", `{"name": "a", ${ior}, "film": {"thickness": -1}}`, false],
  ["film index below 1", `{"name": "a", ${ior}, "film": {"ior": 0.9, "thickness": 10}}`, false],
  ["film under a coat", `{"name": "a", ${ior}, "coat": {}, "film": {"thickness": 10}}`, true],
  ["basis pinned", `{"name": "a", "f82_tint": {"f0": 0.9, "tint": 0.5}, "basis": "powers"}`, true],
  ["basis f82 pinned", `{"name": "a", ${ior}, "basis": "f82"}`, true],
  ["basis fitted", `{"name": "a", ${ior}, "basis": "extended"}`, false],
  ["basis not a name", `{"name": "a", ${ior}, "basis": 1}`, false],
  ["basis f82 under a coat", `{"name": "a", ${ior}, "coat": {}, "basis": "f82"}`, false],
  ["basis powers under a coat", `{"name": "a", ${ior}, "coat": {}, "basis": "powers"}`, true],
];

for (const file of readdirSync(examplesDir).filter((f) => f.endsWith(".json")).sort()) {
  const valid = validate(JSON.parse(readFileSync(join(examplesDir, file), "utf8")));
  check(valid, `example ${file} violates the schema: ${ajv.errorsText(validate.errors)}`);
}
for (const [description, text, expected] of cases) {
  const schemaValid = validate(JSON.parse(text));
  check(schemaValid === expected, `schema ${schemaValid ? "accepts" : "rejects"} '${description}'`);
  const matcValid = matcAccepts(text);
  check(matcValid === expected, `matc ${matcValid ? "accepts" : "rejects"} '${description}'`);
}
finish();
