// The look-development page's picture in docs (docs/images/lookdev.png): the page as served from a
// project's node_modules, opened on a link (a coated gold), in headless Chromium at 1280 x 800.
//   node lookdev-screenshot.mjs NPM_DIR OUT_PNG
import { mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { runLookdevPage } from "./lookdev-page.mjs";

const [npmDir, png] = process.argv.slice(2);
const material = { name: "gold_lacquered", spectral: { preset: "Au" }, roughness: 0.25,
                   coat: { ior: 1.5, roughness: 0.08, color: [0.96, 0.9, 0.78] } };
const fragment = `#${new URLSearchParams({ material: JSON.stringify(material), space: "lin_rec709", view: "split" })}`;
const dir = mkdtempSync(join(tmpdir(), "matc-lookdev-screenshot-"));
try {
  // Headless Chromium lays the page out in a shorter viewport than the screenshot's (its window
  // keeps room for a toolbar) and does not redraw on resize: the page's height is fixed at the picture's.
  await runLookdevPage({ npmDir, config: { cases: [] }, dir, fragment, screenshot: resolve(png), budgetMs: 30000,
                         style: "body { height: 800px; }" });
} finally {
  rmSync(dir, { recursive: true, force: true });
}
