// The look-development page's render: a sphere and a torus (curved both ways: its inner ring is a
// saddle) under a room environment and a rect light, drawn by three.js's WebGLRenderer with matc's
// Fresnel in every light path (the package's matc/three integration), beside the same objects in
// three.js's own metal (Schlick's curve from F0; for a coated metal F0 seen from inside the coat,
// as Filament converts it, under three's clearcoat). Or, for an opened glTF asset, the asset itself
// as matc's GLTFLoader plugin loads it beside three.js's own loading (lookdev-asset.mjs). Split
// view, one side only, or flipped; orbit controls; frames drawn on demand.
import * as THREE from "three";
import { OrbitControls } from "three/addons/controls/OrbitControls.js";
import { RoomEnvironment } from "three/addons/environments/RoomEnvironment.js";
import { RectAreaLightHelper } from "three/addons/helpers/RectAreaLightHelper.js";
import { RectAreaLightUniformsLib } from "three/addons/lights/RectAreaLightUniformsLib.js";
import { useMatcFresnel } from "../three/matc-three.mjs";

// F0 as seen from inside a coat of index `ior` (the metal taken for a dielectric of the same F0):
// the engines' stand-in for the metal under a coat (compiler/src/optics/coat.cpp's f0_seen_from_coat).
export function f0SeenFromCoat(f0, ior) {
  const s = Math.sqrt(Math.min(Math.max(f0, 0), 0.999));
  const n = (1 + s) / (1 - s);
  return ((n - ior) / (n + ior)) ** 2;
}

// three.js's own metal for a compiled material: colour F0 (clamped to [0, 1]), metalness 1; coated:
// the base colour mix(F0, F0 seen from the coat x coat colour, weight) under three's clearcoat;
// filmed (`film`: lookdev-state.mjs's filmOf), three's iridescence of the same film over the bare
// metal's F0 (as glTF's KHR_materials_iridescence draws it: a dielectric base of that F0).
export function engineMetalParameters(compiled, roughness, film = null) {
  const f0 = Array.from(compiled.f0, (v) => Math.min(Math.max(v, 0), 1));
  const iridescence = film
    ? { iridescence: film.weight, iridescenceIOR: film.ior, iridescenceThicknessMinimum: film.thickness,
        iridescenceThicknessMaximum: film.thickness }
    : { iridescence: 0, iridescenceIOR: 1.3, iridescenceThicknessMinimum: 100, iridescenceThicknessMaximum: 400 };
  const coat = compiled.coat;
  if (!coat) return { color: f0, roughness, clearcoat: 0, clearcoatRoughness: 0, ...iridescence };
  const color = f0.map((v, c) => (1 - coat.weight) * v + coat.weight * f0SeenFromCoat(v, coat.ior) * coat.color[c]);
  return { color, roughness, clearcoat: coat.weight, clearcoatRoughness: coat.roughness, ...iridescence };
}

export class LookdevView {
  // canvas: the page's; build: loadMatcBuild's (matc/three) of the page's compiled build.
  constructor(canvas, build) {
    this.canvas = canvas;
    this.build = build;
    this.mode = "split";
    this.flipped = false;
    this.frames = 0;
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: true });
    this.renderer.toneMapping = THREE.NeutralToneMapping;
    RectAreaLightUniformsLib.init();
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0.05, 0.05, 0.055);
    const pmrem = new THREE.PMREMGenerator(this.renderer);
    this.scene.environment = pmrem.fromScene(new RoomEnvironment(), 0.04).texture;
    pmrem.dispose();
    const rect = new THREE.RectAreaLight(0xffffff, 6, 1.6, 0.5);
    rect.position.set(-1.2, 1.6, 1.4);
    rect.lookAt(0, 0, 0);
    rect.add(new RectAreaLightHelper(rect));
    this.scene.add(rect);
    this.matcMaterial = null;
    this.engineMaterial = new THREE.MeshPhysicalMaterial({ metalness: 1 });
    this.meshes = [
      new THREE.Mesh(new THREE.SphereGeometry(0.5, 96, 48)),
      new THREE.Mesh(new THREE.TorusGeometry(0.42, 0.17, 64, 128)),
    ];
    this.meshes[0].position.set(0, 0.58, 0);
    this.meshes[1].position.set(0, -0.52, 0);
    this.meshes[1].rotation.set(-0.9, 0.35, 0);
    for (const mesh of this.meshes) this.scene.add(mesh);
    this.camera = new THREE.PerspectiveCamera(32, 1, 0.1, 50);
    this.camera.position.set(0, 0.2, 7.2);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.target.set(0, 0.03, 0);
    this.controls.update();
    this.controls.saveState();
    this.controls.addEventListener("change", () => this.requestFrame());
    new ResizeObserver(() => this.requestFrame()).observe(canvas);
    this.pending = 0;  // the requested animation frame's id, 0 when none
    this.asset = null;       // loadAssetPair's, while an asset is open
    this.showAsset = false;  // the asset drawn instead of the sphere and torus
  }

  // Puts an opened asset (loadAssetPair's, or null) in the scene, framed by the camera; returns the
  // one it replaces (for the caller to dispose).
  setAsset(asset) {
    const previous = this.asset;
    if (previous) this.scene.remove(previous.matc, previous.engine);
    this.asset = asset;
    if (asset) {
      this.scene.add(asset.matc, asset.engine);
      const sphere = new THREE.Box3().setFromObject(asset.engine).getBoundingSphere(new THREE.Sphere());
      this.assetFrame = { centre: sphere.center.clone(), radius: Math.max(sphere.radius, 1e-3) };
    }
    this.frameCamera();
    this.requestFrame();
    return previous;
  }

  // Draws the asset (true) or the sphere and torus (false).
  setShowAsset(show) {
    this.showAsset = Boolean(show) && Boolean(this.asset);
    this.frameCamera();
    this.requestFrame();
  }

  // The camera at its start for what is shown: the sphere and torus, or the asset's bounds seen
  // from its +z side.
  frameCamera() {
    if (this.showAsset && this.asset) {
      // The bounds fit the narrower of the two fields of view of one side of the view.
      const { centre, radius } = this.assetFrame;
      const sideAspect = Math.max(1, this.canvas.clientWidth) / this.sides().length / Math.max(1, this.canvas.clientHeight);
      const halfVertical = THREE.MathUtils.degToRad(this.camera.fov / 2);
      const halfHorizontal = Math.atan(Math.tan(halfVertical) * sideAspect);
      const distance = 1.1 * radius / Math.sin(Math.min(halfVertical, halfHorizontal));
      this.camera.position.copy(centre).add(new THREE.Vector3(0, 0.03 * distance, distance));
      this.camera.near = distance / 100;
      this.camera.far = distance * 10;
      this.controls.target.copy(centre);
    } else {
      this.camera.position.set(0, 0.2, 7.2);
      this.camera.near = 0.1;
      this.camera.far = 50;
      this.controls.target.set(0, 0.03, 0);
    }
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.controls.saveState();
  }

  // Shows a compiled material: `loaded` (build.loadMaterial(compiled) of the build's language),
  // `compiled` (its CompiledMaterial, for three.js's own metal) and the roughness. A bare metal
  // after a bare metal of the same basis changes uniforms only; a coated one, or one of another
  // basis (its functions and its layer of the table), gets a program of its own.
  setMaterial(loaded, compiled, roughness, film = null) {
    const current = this.matcMaterial;
    const shown = current?.userData.matc.source.material;
    if (current && !loaded.coat && !shown.coat && !loaded.film && !shown.film && shown.basis === loaded.basis) {
      const { matc_red: red, matc_green: green, matc_blue: blue } = current.userData.matc.uniforms;
      [red, green, blue].forEach((uniform, c) => uniform.value.set(...loaded.coefficients[c]));
      current.userData.matc.source = { material: loaded };
      current.roughness = roughness;
    } else {
      this.matcMaterial = useMatcFresnel(new THREE.MeshPhysicalMaterial({ roughness }), this.build, { material: loaded });
      current?.dispose();
    }
    const { color, ...engine } = engineMetalParameters(compiled, roughness, film);
    this.engineMaterial.color.setRGB(...color, THREE.LinearSRGBColorSpace);
    Object.assign(this.engineMaterial, engine);
    this.requestFrame();
  }

  setMode(mode) {
    this.mode = mode;
    if (this.showAsset) this.frameCamera();
    this.requestFrame();
  }

  // Space: flips matc and three.js (the split's sides, or the side shown).
  flip() {
    this.flipped = !this.flipped;
    this.requestFrame();
  }

  resetCamera() {
    this.controls.reset();
  }

  // The sides drawn, left to right: "matc" and "engine" in split view, or the one shown.
  sides() {
    const sides = this.mode === "split" ? ["matc", "engine"] : [this.mode];
    if (!this.flipped) return sides;
    return sides.length === 2 ? sides.reverse() : [sides[0] === "matc" ? "engine" : "matc"];
  }

  requestFrame() {
    if (this.pending) return;
    this.pending = requestAnimationFrame(() => {
      this.pending = 0;
      this.render();
    });
  }

  // Draws the requested frame now rather than at the next animation frame.
  flush() {
    if (!this.pending) return;
    cancelAnimationFrame(this.pending);
    this.pending = 0;
    this.render();
  }

  // Draws a frame now (each side into its part of the canvas).
  render() {
    if (!this.matcMaterial) return;
    const width = Math.max(1, this.canvas.clientWidth), height = Math.max(1, this.canvas.clientHeight);
    this.renderer.setPixelRatio(window.devicePixelRatio);
    this.renderer.setSize(width, height, false);
    const sides = this.sides();
    const part = width / sides.length;
    this.camera.aspect = part / height;
    this.camera.updateProjectionMatrix();
    this.renderer.setScissorTest(true);
    const asset = this.showAsset ? this.asset : null;
    sides.forEach((side, i) => {
      const material = side === "matc" ? this.matcMaterial : this.engineMaterial;
      for (const mesh of this.meshes) {
        mesh.material = material;
        mesh.visible = !asset;
      }
      if (this.asset) {
        this.asset.matc.visible = Boolean(asset) && side === "matc";
        this.asset.engine.visible = Boolean(asset) && side === "engine";
      }
      this.renderer.setViewport(i * part, 0, part, height);
      this.renderer.setScissor(i * part, 0, part, height);
      this.renderer.render(this.scene, this.camera);
    });
    this.renderer.setScissorTest(false);
    this.frames += 1;
    this.onFrame?.(sides);
  }
}
