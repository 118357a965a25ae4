// In-page side of the look-development page's checks (check-lookdev.mjs, bench/lookdev-latency):
// added to the page's own HTML after its module, it drives the page through its controls as a
// person does (values set, input/change events, a pasted document), waits for the page to settle,
// and reports what the page shows: its exports, its plotted curves, probe renders of its matc
// material under the engine checks' lights (engine-probes.mjs), the messages of refused values.
// The config (<script id="lookdev-check-config">) lists the cases; the result goes into
// <pre id="result"> and is posted to /result (runPage's realTime mode).
import * as THREE from "three";
import { probeScene, probeSetup, renderProbePixels } from "/checks/three-scene-page.mjs";

const config = JSON.parse(document.getElementById("lookdev-check-config").textContent);
const out = { errors: [], cases: {}, refusals: {}, timings: {} };
const $ = (selector) => {
  const element = document.querySelector(selector);
  if (!element) throw new Error(`the page has no ${selector}`);
  return element;
};

// One step through the controls: { selector, value } (input event; event: "change" for selects),
// { selector, checked } (a checkbox, change event), { paste } (the text into the paste box, Load)
// or { drop: [{ name, text }] } (files dropped on the page together).
function apply(step) {
  if (step.drop !== undefined) {
    const transfer = new DataTransfer();
    const bytes = (file) => (file.base64 !== undefined
      ? Uint8Array.from(atob(file.base64), (character) => character.charCodeAt(0)) : file.text);
    for (const file of step.drop) transfer.items.add(new File([bytes(file)], file.name));
    document.dispatchEvent(new DragEvent("drop", { dataTransfer: transfer, bubbles: true, cancelable: true }));
    return;
  }
  if (step.paste !== undefined) {
    $("#paste").value = step.paste;
    $("#load-pasted").click();
    return;
  }
  const element = $(step.selector);
  if (step.checked !== undefined) {
    element.checked = step.checked;
    element.dispatchEvent(new Event("change"));
    return;
  }
  element.value = step.value;
  element.dispatchEvent(new Event(step.event ?? "input"));
}

// Waits for the page's updates and draws their frame (idle() does not wait for an animation frame,
// which headless Chromium's virtual time does not run).
async function settle(lookdev) {
  await lookdev.idle();
}

// The page's matc material (or `material`) on the probe plane under each light, read at the probe pixels.
function probeRenders(view, lights, material = view.matcMaterial) {
  const renderer = view.renderer;
  const { target, camera, pmrem, environment } = probeSetup(THREE, renderer, config.probeSize);
  const renders = {};
  for (const light of lights) {
    renders[light] = renderProbePixels(renderer, probeScene(THREE, material, light, config, environment),
                                       camera, target, config.pixels);
  }
  renderer.setRenderTarget(null);
  target.dispose();
  environment.dispose();
  pmrem.dispose();
  return renders;
}

const coefficientsOf = (view) => {
  const { matc_red: red, matc_green: green, matc_blue: blue } = view.matcMaterial.userData.matc.uniforms;
  return [red, green, blue].map((uniform) => uniform.value.toArray());
};

// Times from a control's event to the frame drawn and finished (a pixel read waits for the GPU).
async function timeChange(lookdev, step) {
  const gl = lookdev.app.view.renderer.getContext();
  const started = performance.now();
  apply(step);
  await lookdev.idle();  // draws the frame the change asked for
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
  return { totalMs: performance.now() - started, ...lookdev.app.lastUpdate };
}

try {
  const lookdev = window.matcLookdev;
  await lookdev.ready;
  await settle(lookdev);
  // The layout settles after the first frame (the curves and exports fill their column); a page
  // redraws on resize at an animation frame, which virtual time does not run: draw now.
  await new Promise((resolve) => setTimeout(resolve, 100));
  lookdev.app.view.render();
  out.start = { status: $("#status").textContent, frames: lookdev.app.view.frames, name: lookdev.app.compiled?.name,
                exports: Object.fromEntries(["material", "glsl"].map((kind) => [kind, lookdev.exportText(kind)])),
                documentMessage: $(".message[data-for='document']").textContent };
  for (const testCase of config.cases ?? []) {
    for (const step of testCase.steps) {
      apply(step);
      await settle(lookdev);
    }
    const { app } = lookdev;
    out.cases[testCase.key] = {
      status: $("#status").textContent,
      refused: $("#status").classList.contains("refused"),
      messages: [...document.querySelectorAll(".message")].map((output) => output.textContent).filter(Boolean),
      choices: [...$("#choice").options].map((option) => option.textContent),
      colorSpace: app.state.colorSpace,
      exports: Object.fromEntries(["material", "glsl", "wgsl", "hlsl", "json"].map((kind) => [kind, lookdev.exportText(kind)])),
      hash: location.hash,
      series: Object.fromEntries(Object.entries(app.series).map(([key, values]) => [key, Array.from(values)])),
      renders: probeRenders(app.view, testCase.lights ?? []),
      labels: [$("#label-left").textContent, $("#label-right").textContent],
    };
    // An opened asset's view: what the page says of it, and each named glTF material of either load
    // (matc's loader, three.js's own) on the probe plane.
    if (testCase.assetMaterials) {
      const asset = app.view.asset;
      const byName = (root) => {
        const found = {};
        root?.traverse((object) => { if (object.isMesh) found[object.material.name] = object.material; });
        return found;
      };
      const loads = { matc: byName(asset?.matc), engine: byName(asset?.engine) };
      out.cases[testCase.key].asset = {
        summary: $("#asset-notes").textContent, scene: $("#scene").value, metals: asset?.metals ?? [],
        renders: Object.fromEntries(Object.entries(loads).flatMap(([load, materials]) => testCase.assetMaterials
          .filter((name) => materials[name]).map((name) => [`${load} ${name}`, probeRenders(app.view, testCase.lights, materials[name])]))),
      };
    }
    // Each refusal: the message beside its control, the last good material kept.
    for (const refusal of testCase.refusals ?? []) {
      const before = { compiled: app.compiled, coefficients: coefficientsOf(app.view), hash: location.hash };
      for (const step of refusal.steps) {
        apply(step);
        await settle(lookdev);
      }
      out.refusals[refusal.key] = {
        message: $(refusal.messageSelector).textContent,
        refused: $("#status").classList.contains("refused"),
        kept: app.compiled === before.compiled && location.hash === before.hash &&
              JSON.stringify(coefficientsOf(app.view)) === JSON.stringify(before.coefficients),
        controlMarked: refusal.control ? $(refusal.control).classList.contains("refused") : null,
      };
      for (const step of refusal.restore ?? []) {
        apply(step);
        await settle(lookdev);
      }
    }
  }
  for (const timing of config.timings ?? []) {
    for (const step of timing.setup ?? []) {
      apply(step);
      await settle(lookdev);
    }
    const samples = [];
    for (let i = 0; i < timing.repeat; ++i) samples.push(await timeChange(lookdev, timing.steps[i % timing.steps.length]));
    out.timings[timing.key] = samples;
  }
  if (config.frameTimes) {
    const { view } = lookdev.app;
    const gl = view.renderer.getContext();
    const samples = [];
    for (let i = 0; i < config.frameTimes; ++i) {
      const started = performance.now();
      view.render();
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
      samples.push(performance.now() - started);
    }
    out.frameTimes = samples;
    out.canvas = [view.canvas.width, view.canvas.height];
  }
} catch (error) {
  out.errors.push(String(error.stack || error));
}
out.console = window.lookdevConsole ?? [];
const result = document.createElement("pre");
result.id = "result";
result.hidden = true;
result.textContent = JSON.stringify(out);
document.body.append(result);
await fetch("/result", { method: "POST", body: JSON.stringify(out) }).catch(() => {});
