// Runs one page in headless Chromium (Debian's package; WebGL2 through ANGLE on SwiftShader) and
// returns what the page wrote into <pre id="result"> as JSON. The page is served from 127.0.0.1
// with folders mounted under /<root>/ (e.g. /three/ for three.js's build), so that module imports
// and fetches work as on a real site.
//   const result = await runPage({ html, roots: { out: "/tmp/x/out" }, dir: "/tmp/x" });
import { spawn, spawnSync } from "node:child_process";
import { createServer } from "node:http";
import { readFileSync, statSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
// The engines from npm (package-lock.json pins them): three.js's build and addons, Babylon.js's
// ES modules and glTF loader, and ktx-parse for the integrations' shared loader.
export const kWebRoots = {
  three: join(here, "node_modules", "three", "build"),
  "three-addons": join(here, "node_modules", "three", "examples", "jsm"),
  babylon: join(here, "node_modules", "@babylonjs", "core"),
  "babylon-loaders": join(here, "node_modules", "@babylonjs", "loaders"),
  "ktx-parse": join(here, "node_modules", "ktx-parse", "dist"),
  checks: here,  // the in-page helpers of these checks (page-bad-inputs.mjs)
};
export const kWebImportMap = JSON.stringify({
  imports: { three: "/three/three.module.js", "three/webgpu": "/three/three.webgpu.js",
             "three/tsl": "/three/three.tsl.js", "three/addons/": "/three-addons/",
             "@babylonjs/core/": "/babylon/", "@babylonjs/loaders/": "/babylon-loaders/", "ktx-parse": "/ktx-parse/index.mjs" } });
export const threeVersion = () =>
  JSON.parse(readFileSync(join(here, "node_modules", "three", "package.json"), "utf8")).version;

// A page that runs one ES module: `head` (imports, top-level helpers), then `body` with `config`
// (the JSON given here), `out` ({ errors }, what the page reports) and base64Floats in scope; an
// exception ends up in out.errors, and out is written where runPage reads it.
export function modulePage(config, { head, body }) {
  return `<!doctype html><html><body><pre id="result">not run</pre>
<script type="application/json" id="config">${JSON.stringify(config)}</script>
<script type="importmap">${kWebImportMap}</script>
<script type="module">
${head}
const config = JSON.parse(document.getElementById("config").textContent);
const out = { errors: [] };
// Float arrays travel in \`out\` as base64 of their bytes.
const base64Floats = (floats) => {
  const bytes = new Uint8Array(floats.buffer, floats.byteOffset, floats.byteLength);
  let binary = "";
  for (let i = 0; i < bytes.length; i += 0x8000) binary += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(binary);
};
try {
${body}
} catch (error) {
  out.errors.push(String(error.stack || error));
}
document.getElementById("result").textContent = JSON.stringify(out);
await fetch("/result", { method: "POST", body: JSON.stringify(out) }).catch(() => {});  // runPage's realTime mode
</script></body></html>
`;
}

function chromiumPath() {
  for (const name of ["chromium", "chromium-browser"]) {
    const found = spawnSync("sh", ["-c", `command -v ${name}`], { encoding: "utf8" });
    if (found.status === 0) return found.stdout.trim();
  }
  throw new Error("chromium not found (scripts/install-deps.sh installs Debian's chromium)");
}

const kTypes = { js: "text/javascript", mjs: "text/javascript", json: "application/json", wasm: "application/wasm",
                 html: "text/html", css: "text/css", glsl: "text/plain" };

// By default the page runs under Chromium's virtual time and its DOM is read when it is done.
// realTime: the page runs on the wall clock and posts its result to /result (modulePage does), for
// work virtual time does not settle (WebGPU's adapter and device); browserArgs: more Chromium flags.
// pagePath: where the page's HTML is served (default /page.html; a page that imports modules
// relative to its own folder is served from there); fragment: the URL's #... part; screenshot: a
// PNG path to write the window into when virtual time runs out, instead of reading the DOM (returns
// null).
export async function runPage({ html, roots, dir, budgetMs = 120000, realTime = false, browserArgs = [],
                                pagePath = "/page.html", fragment = "", screenshot = null }) {
  let posted = null;
  let finished = () => {};
  const server = createServer((request, response) => {
    const path = decodeURIComponent(new URL(request.url, "http://localhost").pathname);
    const [, root, ...rest] = path.split("/");
    if (request.method === "POST" && path === "/result") {
      let body = "";
      request.on("data", (chunk) => { body += chunk; });
      request.on("end", () => {
        posted = body;
        response.writeHead(200).end();
        finished();
      });
      return;
    }
    try {
      if (path === pagePath) {
        response.writeHead(200, { "content-type": "text/html" }).end(html);
        return;
      }
      const base = roots[root];
      const file = base && !rest.includes("..") ? join(base, ...rest) : null;
      if (file && statSync(file).isFile()) {
        const type = kTypes[file.split(".").pop()] ?? "application/octet-stream";
        response.writeHead(200, { "content-type": type }).end(readFileSync(file));
        return;
      }
    } catch {
      // a missing file: 404 below
    }
    response.writeHead(404).end();
  });
  try {
    await new Promise((resolve) => server.listen(0, "127.0.0.1", resolve));
    const url = `http://127.0.0.1:${server.address().port}${pagePath}${fragment}`;
    const dom = await new Promise((resolve, reject) => {
      const browser = spawn(chromiumPath(), [
        "--headless", "--no-sandbox", "--disable-dev-shm-usage", "--use-angle=swiftshader",
        "--enable-unsafe-swiftshader", ...(realTime ? [] : [`--virtual-time-budget=${budgetMs}`, screenshot ? `--screenshot=${screenshot}` : "--dump-dom"]),
        // MATC_BROWSER_LOG=1 shows the page's console (and Chromium's own messages) on stderr.
        ...(process.env.MATC_BROWSER_LOG ? ["--enable-logging=stderr", "--v=0"] : []),
        ...browserArgs, `--user-data-dir=${join(dir, "profile")}`, url]);
      let text = "";
      browser.stdout.on("data", (chunk) => { text += chunk; });
      if (process.env.MATC_BROWSER_LOG) browser.stderr.on("data", (chunk) => process.stderr.write(chunk));
      browser.on("error", reject);
      browser.on("close", () => resolve(text));
      if (realTime) {
        const timer = setTimeout(() => browser.kill(), budgetMs);
        finished = () => { clearTimeout(timer); browser.kill(); };
      }
    });
    if (screenshot) return null;
    let text;
    if (realTime) {
      if (posted === null) throw new Error(`the page posted no result within ${budgetMs / 1000} s`);
      text = posted;
    } else {
      const match = dom.match(/<pre id="result"[^>]*>([^<]*)<\/pre>/);
      if (match === null) throw new Error("the page wrote no result");
      text = match[1].replaceAll("&quot;", "\"").replaceAll("&lt;", "<").replaceAll("&gt;", ">")
                     .replaceAll("&amp;", "&");
    }
    try {
      return JSON.parse(text);
    } catch {
      throw new Error(`the page's result is not JSON: ${text.slice(0, 400)}`);
    }
  } finally {
    server.close();
  }
}
