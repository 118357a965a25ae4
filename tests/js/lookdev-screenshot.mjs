// The look-development page's pictures in docs: the page as served from a project's node_modules,
// in headless Chromium at 1280 x 800. docs/images/lookdev.png: opened on a link (a coated gold);
// docs/images/lookdev_asset.png (`asset`): a dropped glTF asset whose metalness is painted in a
// texture (gltf-assets.mjs, metalnessStripesAsset), in the asset view.
//   node lookdev-screenshot.mjs NPM_DIR OUT_PNG [asset]
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { metalnessStripesAsset } from "./gltf-assets.mjs";
import { runLookdevPage } from "./lookdev-page.mjs";

const [npmDir, png, what = "link"] = process.argv.slice(2);
const material = { name: "gold_lacquered", spectral: { preset: "Au" }, roughness: 0.25,
                   coat: { ior: 1.5, roughness: 0.08, color: [0.96, 0.9, 0.78] } };
const dir = mkdtempSync(join(tmpdir(), "matc-lookdev-screenshot-"));
try {
  let fragment = "", config = { cases: [] };
  if (what === "asset") {
    const glb = join(dir, "metalness_stripes.glb");
    await metalnessStripesAsset(glb);
    config = { cases: [{ key: "asset", lights: [], steps: [{ drop: [{ name: "metalness_stripes.glb",
                                                                    base64: readFileSync(glb).toString("base64") }] }] }] };
  } else {
    fragment = `#${new URLSearchParams({ material: JSON.stringify(material), space: "lin_rec709", view: "split" })}`;
  }
  // Headless Chromium lays the page out in a shorter viewport than the screenshot's (its window
  // keeps room for a toolbar) and does not redraw on resize: the page's height is fixed at the picture's.
  await runLookdevPage({ npmDir, config, dir: join(dir, "page"), fragment, screenshot: resolve(png), budgetMs: 30000,
                         style: "body { height: 800px; }" });
} finally {
  rmSync(dir, { recursive: true, force: true });
}
