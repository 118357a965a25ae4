// The look-development page's response to its controls, on the wall clock in headless Chromium
// (WebGL on SwiftShader, this machine's CPU): from a control's input event to the new frame drawn
// and finished (recompile in WebAssembly, uniforms or a new program, plot, exports, link), per
// kind of control, and the frame time of the render itself. Prints docs/performance.md's block.
//   node bench/lookdev_latency.mjs NPM_DIR [REPEAT]
import { mkdtempSync, rmSync } from "node:fs";
import { cpus, tmpdir } from "node:os";
import { join } from "node:path";
import { runLookdevPage } from "../tests/js/lookdev-page.mjs";

const [npmDir, repeatText = "20"] = process.argv.slice(2);
const repeat = Number(repeatText);
const input = (selector, value) => ({ selector, value });
const select = (selector, value) => ({ selector, value, event: "change" });
const kTimings = [
  { key: "roughness (a measured metal: uniforms)", setup: [input("#preset", "Cu")],
    steps: [input("#roughness", "0.5"), input("#roughness", "0.3")] },
  { key: "preset (spectral compile)", steps: [input("#preset", "Au"), input("#preset", "Cu")] },
  { key: "edge tint colour (Gulbrandsen compile)", setup: [select("#model", "artistic")],
    steps: [input("#edge-tint", "#ffc070"), input("#edge-tint", "#c0a0ff")] },
  { key: "n, k typed (complex index compile)", setup: [select("#model", "ior")],
    steps: [input("[data-field='ior.k'][data-channel='1']", "2.4"), input("[data-field='ior.k'][data-channel='1']", "2.6")] },
  { key: "coat index (coated compile, new program)",
    setup: [select("#model", "spectral"), input("#preset", "Cu"), { selector: "#coated", checked: true }],
    steps: [input("#coat-ior", "1.6"), input("#coat-ior", "1.5")] },
];

const median = (values) => {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)];
};
const dir = mkdtempSync(join(tmpdir(), "matc-lookdev-bench-"));
try {
  const result = await runLookdevPage({
    npmDir, dir, realTime: true, budgetMs: 300000,
    config: { timings: kTimings.map((timing) => ({ ...timing, repeat })), frameTimes: 30 } });
  if (result.errors.length || result.console.length) throw new Error([...result.errors, ...result.console].join("\n"));
  const ms = (value) => value.toFixed(1);
  console.log(`Measured in headless Chromium (WebGL2 on SwiftShader) on ${cpus().length} CPU(s) (${cpus()[0].model.trim()}), ` +
              `the page's canvas ${result.canvas.join(" x ")} in split view, ${repeat} changes of each control, medians:\n`);
  console.log("| control changed | compile (ms) | upload (ms) | plot, exports, link (ms) | to the finished frame (ms) | slowest (ms) |");
  console.log("|---|---:|---:|---:|---:|---:|");
  for (const timing of kTimings) {
    const samples = result.timings[timing.key];
    const of = (field) => median(samples.map((sample) => sample[field]));
    console.log(`| ${timing.key} | ${ms(of("compileMs"))} | ${ms(of("uploadMs"))} | ${ms(of("plotMs"))} | ` +
                `${ms(of("totalMs"))} | ${ms(Math.max(...samples.map((sample) => sample.totalMs)))} |`);
  }
  console.log(`\nThe render alone (both sides, sphere and torus, environment and rect light): ` +
              `${ms(median(result.frameTimes))} ms a frame (median of ${result.frameTimes.length}).`);
} finally {
  rmSync(dir, { recursive: true, force: true });
}
