// matc's look-development page (index.html; docs/lookdev.md): the controls edit a material file's
// JSON, which the package's WebAssembly compiler compiles in the page; the render, the curves and
// the exports follow. A value the compiler refuses shows its message beside its control and the
// last good material stays on screen. window.matcLookdev is the page's scripting handle (tests,
// benchmarks, the console): ready, idle(), the view, the compiled material, the plotted curves,
// the exports.
import { createMatc } from "../index.mjs";
import { compiledMatcBuildFiles } from "../matc-build.mjs";
import { loadMatcBuild } from "../three/matc-three.mjs";
import { disposeAsset, escapedText, loadAssetPair } from "./lookdev-asset.mjs";
import { curveSeries, drawCurves } from "./lookdev-plot.mjs";
import { defaultState, filmOf, hexToLinear, kModels, kNewFilm, linearToHex, materialText, modelDefaults, modelOf,
         rgbOf, stateFromHash, stateToHash } from "./lookdev-state.mjs";
import { LookdevView } from "./lookdev-view.mjs";

const $ = (selector) => document.querySelector(selector);
const $$ = (selector) => [...document.querySelectorAll(selector)];

// ---- Controls <-> the material's JSON. ----

// Rounds what a control holds to the digits a person reads (range steps of 0.01 make 0.30000000000000004).
const rounded = (value) => Math.round(value * 1e6) / 1e6;

function showModel(model) {
  $("#model").value = model;
  for (const element of $$(".model")) element.classList.toggle("active", element.dataset.model === model);
}

function showRangeValues() {
  for (const span of $$("[data-value-of]")) span.textContent = Number($(`#${span.dataset.valueOf}`).value).toFixed(2);
}

// Sets every control from `material` (a material file's JSON object).
function toControls(material, colorSpace) {
  const model = modelOf(material);
  showModel(model);
  $("#name").value = material.name ?? "";
  const body = material[model] ?? {};
  if (model === "spectral") $("#preset").value = body.preset ?? "";
  if (model === "artistic") {
    $("#reflectivity").value = linearToHex(body.reflectivity ?? 0);
    $("#edge-tint").value = linearToHex(body.edge_tint ?? 0);
  }
  if (model === "ior") {
    for (const input of $$("[data-field^='ior.']")) {
      input.value = rgbOf(body[input.dataset.field.slice(4)] ?? 0)[Number(input.dataset.channel)];
    }
  }
  if (model === "f82_tint") {
    $("#f82-f0").value = linearToHex(body.f0 ?? 0);
    $("#f82-tint").value = linearToHex(body.tint ?? 1);
  }
  $("#roughness").value = material.roughness ?? 0;
  const coat = material.coat;
  $("#coated").checked = Boolean(coat);
  $("#coat-weight").value = coat?.weight ?? 1;
  $("#coat-ior").value = coat?.ior ?? 1.6;
  $("#coat-roughness").value = coat?.roughness ?? 0;
  $("#coat-color").value = linearToHex(coat?.color ?? 1);
  for (const input of $$("fieldset:nth-of-type(2) input:not(#coated)")) input.disabled = !coat;
  const film = filmOf(material);
  $("#filmed").checked = Boolean(film);
  $("#film-weight").value = film?.weight ?? 1;
  $("#film-ior").value = film?.ior ?? kNewFilm.ior;
  $("#film-thickness").value = film?.thickness ?? kNewFilm.thickness;
  for (const input of $$("#film-controls input:not(#filmed)")) input.disabled = !film;
  $("#color-space").value = colorSpace;
  showRangeValues();
}

// The material the controls describe, starting from `previous` (its description and other keys
// are kept; a control the person did not touch keeps its exact value).
function fromControls(previous, changed) {
  const model = $("#model").value;
  const material = { ...previous, name: $("#name").value };
  for (const other of kModels) if (other !== model) delete material[other];
  if (changed === $("#model")) {
    material[model] = modelDefaults(model, app.compiled ? Array.from(app.compiled.f0) : [0.9, 0.6, 0.5]);
  } else if (model === "spectral") {
    material.spectral = { preset: $("#preset").value };
    // A preset names the metal, unless the person named it otherwise.
    if (changed === $("#preset") && (previous.name === previous.spectral?.preset || previous.name === "")) {
      material.name = $("#preset").value;
    }
  } else if (model === "artistic") {
    material.artistic = { ...previous.artistic };
    if (changed === $("#reflectivity")) material.artistic.reflectivity = hexToLinear($("#reflectivity").value);
    if (changed === $("#edge-tint")) material.artistic.edge_tint = hexToLinear($("#edge-tint").value);
  } else if (model === "ior") {
    const number = (input) => (input.value.trim() === "" ? Number.NaN : Number(input.value));
    material.ior = {
      n: $$("[data-field='ior.n']").map(number),
      k: $$("[data-field='ior.k']").map(number),
    };
  } else if (model === "f82_tint") {
    material.f82_tint = { ...previous.f82_tint };
    if (changed === $("#f82-f0")) material.f82_tint.f0 = hexToLinear($("#f82-f0").value);
    if (changed === $("#f82-tint")) material.f82_tint.tint = hexToLinear($("#f82-tint").value);
  }
  if (changed === $("#roughness")) material.roughness = rounded(Number($("#roughness").value));
  if (!$("#coated").checked) {
    delete material.coat;
  } else {
    const coat = { ...(previous.coat ?? {}) };
    if (!previous.coat) Object.assign(coat, { ior: 1.5, roughness: 0.1 });
    if (changed === $("#coat-weight")) coat.weight = rounded(Number($("#coat-weight").value));
    if (changed === $("#coat-ior")) coat.ior = $("#coat-ior").value.trim() === "" ? Number.NaN : Number($("#coat-ior").value);
    if (changed === $("#coat-roughness")) coat.roughness = rounded(Number($("#coat-roughness").value));
    if (changed === $("#coat-color")) coat.color = hexToLinear($("#coat-color").value);
    material.coat = coat;
  }
  if (!$("#filmed").checked) {
    delete material.film;
  } else {
    const film = { ...(previous.film ?? kNewFilm) };
    const typed = (input) => (input.value.trim() === "" ? Number.NaN : Number(input.value));
    if (changed === $("#film-weight")) film.weight = rounded(Number($("#film-weight").value));
    if (changed === $("#film-ior")) film.ior = typed($("#film-ior"));
    if (changed === $("#film-thickness")) film.thickness = typed($("#film-thickness"));
    material.film = film;
  }
  return material;
}

// ---- Messages beside the controls. ----

function clearMessages() {
  for (const output of $$(".message")) output.textContent = "";
  for (const element of $$(".refused")) element.classList.remove("refused");
  $("#status").classList.remove("refused");
}

// The output beside the control a diagnostic's field belongs to (the longest data-for prefix of
// the field, indices dropped), or the document's.
function messageFor(field) {
  const bare = String(field ?? "").replace(/\[\d+\]/g, "");
  let best = null;
  for (const output of $$(".message[data-for]")) {
    const key = output.dataset.for;
    if ((bare === key || bare.startsWith(`${key}.`)) && (!best || key.length > best.dataset.for.length)) best = output;
  }
  return best ?? $(".message[data-for='document']");
}

// Shows a refusal: each diagnostic's line (the CLI's text) beside its control, the status says
// the last good material stays.
function showRefusal(error) {
  const diagnostics = error.diagnostics?.length ? error.diagnostics : [{ field: "", text: error.message }];
  for (const diagnostic of diagnostics) {
    const output = messageFor(diagnostic.field);
    output.textContent += `${output.textContent ? "\n" : ""}${diagnostic.text}`;
    // The control of the field (of its channel, for a per-channel field such as ior.n[1]).
    const [, field, channel] = /^([\w.]+?)(?:\[(\d+)\])?$/.exec(diagnostic.field ?? "") ?? [];
    const control = field && (document.querySelector(`[data-field='${field}'][data-channel='${channel}']`) ??
                              document.querySelector(`[data-field='${field}']`));
    control?.classList.add("refused");
  }
  $("#status").textContent = `refused; showing the last good material${app.compiled ? ` (${app.compiled.name})` : ""}`;
  $("#status").classList.add("refused");
}

// ---- Compile, render, plot, export. ----

const app = {
  state: defaultState(),
  matc: null,
  build: null,
  view: null,
  compiled: null,        // in the working space (curves, exports)
  renderCompiled: null,  // in linear Rec.709, three.js's working space (the render)
  series: null,
  lastUpdate: null,
  exportKind: "material",
  textOutputs: new Map(),
};

function textOutputsFor(colorSpace) {
  if (!app.textOutputs.has(colorSpace)) app.textOutputs.set(colorSpace, app.matc.textOutputs({ colorSpace }));
  return app.textOutputs.get(colorSpace);
}

// The exports, as matc writes them for the same material: the material file, <name>.glsl/.wgsl/
// .hlsl and <name>.json.
function exportText(kind) {
  if (kind === "material") return materialText(app.state.material);
  const texts = textOutputsFor(app.state.colorSpace);
  return kind === "json" ? texts.materialJson(app.compiled) : texts.materialSource(kind, app.compiled);
}
// The material file's name: <name>.json for a name matc accepts (so that the snippets' headers,
// which name the file, match `matc <name>.json`'s), else material.json.
const materialFileName = (material) =>
  (typeof material.name === "string" && /^[A-Za-z](_?[A-Za-z0-9])*_?$/.test(material.name) &&
   material.name.length <= 64 ? `${material.name}.json` : "material.json");
// Downloads: the material file, <name>.glsl/.wgsl/.hlsl, and the compiled <name>.json (matc's
// output folder's name for it) as <name>.coefficients.json beside the material file.
const exportFileName = (kind) => {
  if (kind === "material") return materialFileName(app.state.material);
  return kind === "json" ? `${app.compiled.name}.coefficients.json` : `${app.compiled.name}.${kind}`;
};

function showExport() {
  for (const button of $$("[data-export]")) button.classList.toggle("active", button.dataset.export === app.exportKind);
  $("#export-text").textContent = app.compiled ? exportText(app.exportKind) : "";
}

const format = (values, digits = 4) => Array.from(values, (v) => v.toFixed(digits)).join(" ");

function showAccuracy(compiled) {
  const a = compiled.accuracy;
  const lines = [
    `${compiled.name}: ${compiled.material.model}${compiled.coat ? ", coated" : ""}` +
      `${compiled.filmTable ? ", filmed (its own table; the 4-term fit below gives F0)" : ""}, basis ${compiled.basis}, ` +
      `${app.state.colorSpace}`,
    `F0            ${format(compiled.f0)}`,
    `F82           ${format(compiled.f82)}`,
    `max |F − exact| over ${a.samples} angles (R G B):`,
    `  matc        ${format(a.maxError)}`,
    `  Schlick     ${format(a.schlickMaxError)}`,
    `  F82-tint    ${format(a.f82TintMaxError)}`,
  ];
  if (compiled.coat) lines.push(`  matc coated ${format(compiled.coat.layeredMaxError)}  (both lobes, layered)`);
  for (const diagnostic of [...compiled.material.diagnostics, ...compiled.diagnostics]) lines.push(diagnostic.text);
  $("#accuracy").textContent = lines.join("\n");
}

// Compiles the state's material; on success shows it everywhere and returns true; on a refusal
// shows the messages and keeps what is on screen.
async function update() {
  const started = performance.now();
  clearMessages();
  const { material, colorSpace } = app.state;
  let compiled, renderCompiled, parsed;
  try {
    parsed = app.matc.parseMaterial(materialText(material), { path: materialFileName(material) });
    compiled = app.matc.compile(parsed, { colorSpace });
    renderCompiled = colorSpace === "lin_rec709" ? compiled : app.matc.compile(parsed, {});
  } catch (error) {
    parsed?.dispose();
    compiled?.dispose();
    showRefusal(error);
    return false;
  }
  const compiledAt = performance.now();
  const loaded = await app.build.loadMaterial(renderCompiled);
  app.view.setMaterial(loaded, renderCompiled, material.roughness ?? 0, filmOf(material));
  const uploadedAt = performance.now();
  for (const old of new Set([app.compiled, app.renderCompiled])) {
    if (old && old !== compiled && old !== renderCompiled) old.dispose();
  }
  app.compiled = compiled;
  app.renderCompiled = renderCompiled;
  app.series = curveSeries(compiled);
  drawCurves($("#plot"), app.series);
  showAccuracy(compiled);
  showExport();
  history.replaceState(null, "", stateToHash(app.state));
  const plottedAt = performance.now();
  app.lastUpdate = { compileMs: compiledAt - started, uploadMs: uploadedAt - compiledAt, plotMs: plottedAt - uploadedAt };
  $("#status").textContent = `${compiled.name}: compiled in ${app.lastUpdate.compileMs.toFixed(1)} ms`;
  return true;
}

// Updates run one at a time; a change during one runs after it (the newest state).
let running = null;
let again = false;
function scheduleUpdate() {
  if (running) {
    again = true;
    return running;
  }
  running = (async () => {
    do {
      again = false;
      await update();
    } while (again);
    running = null;
  })();
  return running;
}

// Resolves when no dropped file is being read, no update is running and the frame they asked for
// is drawn.
async function idle() {
  while (reading) await reading;
  while (assetLoading) await assetLoading;
  while (running) await running;
  app.view.flush();
}

// ---- Opening a document: pasted text or a dropped file. ----

let documentMaterials = [];
let reading = null;  // dropped files being read
let assetLoading = null;  // an opened glTF asset being loaded for the asset view
let assetGeneration = 0;  // the newest opened document's number: an older load's result is dropped

// The scene control: the metal (sphere and torus), or the opened glTF asset when it has meshes.
function showSceneChoice() {
  const asset = app.view.asset;
  $("#scene-asset").disabled = !asset || asset.meshes === 0;
  $("#scene").value = app.view.showAsset ? "asset" : "metal";
}

// The asset view's line: what matc's loader made of the asset's materials (names escaped as JSON).
function assetSummary(path, asset) {
  if (asset.meshes === 0) return `${escapedText(path)}: no meshes to show`;
  const mixed = asset.metals.filter((metal) => metal.metalRough);
  const names = (metals) => metals.map((metal) => JSON.stringify(metal.name)).join(", ");
  return `${escapedText(path)}: ${asset.metals.length} metal${asset.metals.length === 1 ? "" : "s"} drawn by matc` +
    (mixed.length ? `, ${mixed.length} mixed per pixel with three.js's dielectric by metalness (${names(mixed)})` : "");
}

// Loads an opened glTF document (bytes) into the asset view, and shows it when it has meshes; any
// other document closes the asset view.
function openAsset(bytes, path, files) {
  const generation = ++assetGeneration;
  const loaded = bytes ? loadAssetPair({ bytes, path, files, matc: app.matc, build: app.build }) : Promise.resolve(null);
  // The newest document's asset (or none) into the view, with its line under it.
  const show = (asset, line, refused) => {
    const previous = app.view.setAsset(asset);
    if (previous) disposeAsset(previous);
    app.view.setShowAsset(Boolean(asset && asset.meshes > 0));
    $("#asset-notes").textContent = line;
    $("#asset-notes").classList.toggle("refused", refused);
  };
  assetLoading = loaded.then((asset) => {
    if (generation !== assetGeneration) {
      if (asset) disposeAsset(asset);
      return;
    }
    show(asset, asset ? assetSummary(path, asset) : "", false);
  }, (error) => {
    if (generation === assetGeneration) show(null, error.message, true);
  }).finally(() => {
    showSceneChoice();
    if (generation === assetGeneration) assetLoading = null;
  });
}

// `files`: the files the document names (a .gltf's buffers, a spectral CSV), by name.
function openDocument(text, path, files = undefined) {
  clearMessages();
  let materials;
  try {
    materials = app.matc.parseMaterials(text, path, { files });
  } catch (error) {
    showRefusal(error);
    return;
  }
  for (const old of documentMaterials) old.dispose();
  documentMaterials = materials;
  const gltf = /\.(gltf|glb)$/i.test(path);
  openAsset(gltf ? (typeof text === "string" ? new TextEncoder().encode(text) : text) : null, path, files ?? {});
  const choice = $("#choice");
  choice.replaceChildren(...materials.map((material, i) => new Option(material.name, String(i))));
  $("#choice-label").hidden = materials.length < 2;
  chooseDocumentMaterial(0);
}

function chooseDocumentMaterial(index) {
  const material = JSON.parse(documentMaterials[index].json);
  app.state.material = material;
  toControls(material, app.state.colorSpace);
  scheduleUpdate();
}

// Dropped files: the document (a .gltf, .glb or .mtlx first, else a .json), the others the files
// it names beside it by their names (a .gltf's .bin, a spectral CSV in the same folder).
async function openDroppedFiles(dropped) {
  const rank = (file) => (/\.(gltf|glb|mtlx)$/i.test(file.name) ? 0 : /\.json$/i.test(file.name) ? 1 : 2);
  const main = [...dropped].sort((a, b) => rank(a) - rank(b))[0];
  if (!main) return;
  const files = {};
  for (const file of dropped) {
    if (file !== main) files[file.name] = new Uint8Array(await file.arrayBuffer());
  }
  openDocument(new Uint8Array(await main.arrayBuffer()), main.name, files);
}

// A pasted text is MaterialX when it starts with "<" (an XML declaration or element), a glTF
// asset when it is JSON with an "asset" object, else a material file.
function pastedPath(text) {
  if (text.trimStart().startsWith("<")) return "pasted.mtlx";
  try {
    const value = JSON.parse(text);
    if (value && typeof value === "object" && value.asset && typeof value.asset === "object") return "pasted.gltf";
  } catch {
    // not JSON: the material parser says where
  }
  return "pasted.json";
}

// ---- Start. ----

async function start() {
  app.matc = await createMatc();
  $("#version").textContent = app.matc.version;
  $("#preset").replaceChildren(...app.matc.spectralPresets().map((symbol) => new Option(symbol, symbol)));
  app.build = await loadMatcBuild(await compiledMatcBuildFiles(app.matc, { language: "glsl" }));
  app.view = new LookdevView($("#render"), app.build);

  const fromLink = stateFromHash(location.hash);
  if (fromLink && !fromLink.error) app.state = fromLink;
  toControls(app.state.material, app.state.colorSpace);
  app.view.setMode(app.state.view);
  $("#view-mode").value = app.state.view;

  for (const control of $$("#controls input:not(#coated):not(#filmed), #controls select:not(#model):not(#color-space):not(#choice)")) {
    control.addEventListener("input", () => {
      showRangeValues();
      app.state.material = fromControls(app.state.material, control);
      scheduleUpdate();
    });
  }
  $("#model").addEventListener("change", () => {
    showModel($("#model").value);
    app.state.material = fromControls(app.state.material, $("#model"));
    toControls(app.state.material, app.state.colorSpace);
    scheduleUpdate();
  });
  for (const toggle of [$("#coated"), $("#filmed")]) {
    toggle.addEventListener("change", () => {
      app.state.material = fromControls(app.state.material, toggle);
      toControls(app.state.material, app.state.colorSpace);
      scheduleUpdate();
    });
  }
  $("#color-space").addEventListener("change", () => {
    app.state.colorSpace = $("#color-space").value;
    scheduleUpdate();
  });
  $("#view-mode").addEventListener("change", () => {
    app.state.view = $("#view-mode").value;
    app.view.setMode(app.state.view);
    if (app.compiled) history.replaceState(null, "", stateToHash(app.state));
  });
  $("#scene").addEventListener("change", () => {
    app.view.setShowAsset($("#scene").value === "asset");
    showSceneChoice();
  });
  $("#load-pasted").addEventListener("click", () => openDocument($("#paste").value, pastedPath($("#paste").value)));
  $("#choice").addEventListener("change", () => chooseDocumentMaterial(Number($("#choice").value)));
  document.addEventListener("dragover", (event) => event.preventDefault());
  document.addEventListener("drop", (event) => {
    event.preventDefault();
    reading = openDroppedFiles([...(event.dataTransfer?.files ?? [])]).finally(() => { reading = null; });
  });
  for (const button of $$("[data-export]")) {
    button.addEventListener("click", () => {
      app.exportKind = button.dataset.export;
      showExport();
    });
  }
  $("#copy").addEventListener("click", () => navigator.clipboard?.writeText($("#export-text").textContent));
  $("#copy-link").addEventListener("click", () => navigator.clipboard?.writeText(location.href));
  $("#download").addEventListener("click", () => {
    if (!app.compiled) return;
    const link = document.createElement("a");
    link.href = URL.createObjectURL(new Blob([exportText(app.exportKind)], { type: "text/plain" }));
    link.download = exportFileName(app.exportKind);
    link.click();
    URL.revokeObjectURL(link.href);
  });
  document.addEventListener("keydown", (event) => {
    if (event.target.closest?.("input, textarea, select")) return;
    if (event.code === "Space") {
      event.preventDefault();
      app.view.flip();
    } else if (event.key === "r" || event.key === "R") {
      app.view.resetCamera();
    }
  });
  app.view.onFrame = (sides) => {
    const names = app.view.showAsset
      ? { matc: "matc's glTF loader", engine: "three.js's GLTFLoader" }
      : { matc: "matc", engine: `three.js Schlick${app.compiled?.coat ? " (F0 in coat, clearcoat)" : ""}` +
                                `${app.compiled?.filmTable ? " + iridescence" : ""}` };
    $("#label-left").textContent = names[sides[0]];
    $("#label-right").textContent = sides[1] ? names[sides[1]] : "";
  };
  await scheduleUpdate();
  // After the first compile, which clears the messages: why the link's material was not opened.
  if (fromLink?.error) $(".message[data-for='document']").textContent = fromLink.error;
}

window.matcLookdev = {
  app,
  ready: start().catch((error) => {
    $("#status").textContent = `the page could not start: ${error.message}`;
    $("#status").classList.add("refused");
    throw error;
  }),
  idle,
  exportText,
  openDocument,
  openDroppedFiles,
};
