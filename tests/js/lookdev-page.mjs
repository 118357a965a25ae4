// Serves the look-development page as a web developer's project would (node_modules/matc: the
// staged npm package, node_modules/three: the pinned three.js, side by side) and runs it in
// headless Chromium with lookdev-check-page.mjs added after its own module: the page's HTML is
// the package's, plus a console recorder first in <head> and the check's config and module.
//   const result = await runLookdevPage({ npmDir, config, dir });
import { mkdirSync, readFileSync, symlinkSync } from "node:fs";
import { dirname, join, resolve } from "node:path";
import { fileURLToPath } from "node:url";
import { runPage } from "./browser-page.mjs";

const here = dirname(fileURLToPath(import.meta.url));
export const kLookdevPath = "/node_modules/matc/lookdev/index.html";

// Every console error and warning, uncaught exception and rejected promise of the page.
const kConsoleRecorder = `<script>
window.lookdevConsole = [];
for (const level of ["error", "warn"]) {
  const original = console[level].bind(console);
  console[level] = (...args) => { window.lookdevConsole.push(level + ": " + args.map(String).join(" ")); original(...args); };
}
addEventListener("error", (event) => window.lookdevConsole.push("uncaught: " + event.message));
addEventListener("unhandledrejection", (event) => window.lookdevConsole.push("unhandled rejection: " + String(event.reason)));
</script>`;

export function lookdevProject(npmDir, dir) {
  const modules = join(dir, "node_modules");
  mkdirSync(modules, { recursive: true });
  symlinkSync(resolve(npmDir), join(modules, "matc"));
  symlinkSync(join(here, "node_modules", "three"), join(modules, "three"));
  return modules;
}

export async function runLookdevPage({ npmDir, config, dir, realTime = false, windowSize = "1280,800", budgetMs,
                                       fragment = "", screenshot = null, style = "" }) {
  const page = readFileSync(join(npmDir, "lookdev", "index.html"), "utf8");
  const html = page.replace("<head>", () => `<head>\n${kConsoleRecorder}${style ? `<style>${style}</style>` : ""}`).replace("</body>", () =>
    `<script type="application/json" id="lookdev-check-config">${JSON.stringify(config).replaceAll("<", "\\u003c")}</script>\n` +
    `<script type="module" src="/checks/lookdev-check-page.mjs"></script>\n</body>`);
  return runPage({ html, pagePath: kLookdevPath, fragment, dir, realTime, budgetMs, screenshot,
                   roots: { node_modules: lookdevProject(npmDir, dir), checks: here },
                   browserArgs: [`--window-size=${windowSize}`] });
}
