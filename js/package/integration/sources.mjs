// The options and coefficient sources the integrations' useMatcFresnel takes, checked against the
// build: areaLights, colour options, and the source's kind.
import { buildBases, holdsBasis } from "./basis-layers.mjs";
import { checkedZeroF0Rows } from "./coefficient-rows.mjs";
import { MatcWebError, quoted } from "./errors.mjs";
import { checkedF0Table } from "./f0-table.mjs";

// Checks the areaLights option against what a coated material (`allowed`) or a filmed one takes in
// an integration: the quality level's area lights take bare metals (they follow the 4-term basis
// across the lobe, which a film's table is not).
export function checkLayeredAreaLights(material, areaLights, allowed = ["matc", "engine"]) {
  if (!material?.coat && !material?.film) return;
  const permitted = material.coat ? allowed : ["matc", "engine"];
  if (permitted.includes(areaLights)) return;
  const why = areaLights === "quality" ? "the quality-level area lights take bare metals"
                                       : `its coat lobe needs matc's LTC on rect lights (areaLights ${quoted(areaLights)})`;
  throw new MatcWebError(`${quoted(material.name)} is ${material.coat ? "coated" : "filmed"}: ${why}; use areaLights ` +
                         permitted.map((value) => `"${value}"`).join(" or "));
}

// The engine's own iridescence (glTF's KHR_materials_iridescence: the film over a dielectric base)
// replaces the base Fresnel: a filmed matc metal takes its place, and so does a bare one compiled
// from a film that shows nothing (`bareFilm`: index 1, 0 nm or no coverage, which matc compiles as
// the bare metal); any other bare one cannot be combined with it. Returns whether the integration
// switches the engine's iridescence off.
export function checkIridescence(engineIridescence, film, bareFilm = false) {
  if (typeof bareFilm !== "boolean") {
    throw new MatcWebError(`bareFilm must be true or false, not a ${typeof bareFilm}`);
  }
  if (engineIridescence && !film && !bareFilm) {
    throw new MatcWebError("iridescence replaces the base Fresnel; it cannot be combined with matc's " +
                           "(a matc material with a film takes its place)");
  }
  return Boolean(film || bareFilm);
}

// A colour option of a source (reflectivity, edgeTint): [r, g, b], one grey value, or 1 when absent.
export function rgbOf(value) {
  return Array.isArray(value) ? value : [value ?? 1, value ?? 1, value ?? 1];
}

// Checks the areaLights option against the values an integration supports.
export function checkAreaLights(areaLights, allowed = ["matc", "quality", "engine"]) {
  if (!allowed.includes(areaLights)) {
    throw new MatcWebError(`areaLights: ${quoted(areaLights)}; allowed: ${allowed.map((value) => `"${value}"`).join(", ")}`);
  }
}

// Checks that a source of coefficients (see the integrations' useMatcFresnel) fits the build;
// returns its kind: "schlick", "material", "table" or "baked".
export function sourceKind(build, source) {
  if (source?.schlick) {
    const { basis, zeroF0Coefficients } = source.schlick;
    if (!holdsBasis(build, basis)) {
      throw new MatcWebError(`schlick: coefficients of basis ${quoted(basis)}, the build's tables are ${buildBases(build).join(", ")}`);
    }
    checkedZeroF0Rows(zeroF0Coefficients, "schlick");
    return "schlick";
  }
  if (source?.f0Table) {
    if (!source.material) throw new MatcWebError("an F0 table (f0Table) comes with its { material }");
    if (source.material.film) {
      throw new MatcWebError(`${quoted(source.material.name)} is filmed: its own table holds the film over one metal, ` +
                             "so its F0 is not followed per pixel (f0Table)");
    }
    checkedF0Table(source.f0Table, Boolean(source.material.coat), "f0Table");
  }
  if (source?.material) {
    if (!holdsBasis(build, source.material.basis)) {
      throw new MatcWebError(`${quoted(source.material.name)}: coefficients of basis ${quoted(source.material.basis)}, ` +
                             `the build's tables are ${buildBases(build).join(", ")}`);
    }
    return source.f0Table ? "f0Table" : "material";
  }
  if (source?.reflectivityMap || source?.edgeTintMap) {
    if (!source.reflectivityMap || !source.edgeTintMap) {
      throw new MatcWebError("a textured metal needs both reflectivityMap and edgeTintMap");
    }
    if (!build.coefficientTable) {
      throw new MatcWebError(`${build.url}: textured metals need the coefficient table; compile with ` +
                             "--emit coefficient-table among the outputs");
    }
    return "table";
  }
  if (source?.baked) {
    if (!source.baked.c2Map || !source.baked.c3Map) {
      throw new MatcWebError("baked coefficients need c2Map and c3Map (matc bake)");
    }
    if (source.baked.basis && source.baked.basis !== buildBases(build)[0]) {
      throw new MatcWebError(`baked coefficients of basis ${quoted(source.baked.basis)}, the build's tables are ${buildBases(build)[0]}`);
    }
    return "baked";
  }
  throw new MatcWebError("useMatcFresnel needs { material }, { material, f0Table }, { schlick }, " +
                         "{ reflectivityMap, edgeTintMap } or { baked }");
}

// The basis a source's coefficients are in (its material's, its Schlick rows'; the coefficient
// table's and bakes' are the build's first).
export function sourceBasis(build, source) {
  return source?.schlick?.basis ?? source?.material?.basis ?? buildBases(build)[0];
}
