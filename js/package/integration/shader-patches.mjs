// Patching an engine's shader text at anchors that must be found exactly once (the three.js and
// Babylon.js integrations): an engine whose shaders changed makes the patch throw, never render
// wrongly.
import { MatcWebError } from "./errors.mjs";

// A pattern for `anchor` that ignores how whitespace is laid out (engines' builds collapse blank
// lines and indentation) but nothing else.
export function anchorPattern(anchor) {
  const words = anchor.trim().split(/\s+/).map((word) => word.replace(/[.*+?^${}()|[\]\\]/g, "\\$&"));
  return new RegExp(words.join("\\s*"), "g");
}

// How many times `anchor` occurs in `source`.
export function countAnchor(source, anchor) {
  return (source.match(anchorPattern(anchor)) ?? []).length;
}

// Checks each patch's anchor against the engine's shader sources (name -> text): found exactly
// `patch.count ?? 1` times, or the engine changed and the material must not be used.
export function checkAnchors(engine, sources, patches, tested) {
  for (const patch of patches) {
    const source = sources[patch.source];
    if (typeof source !== "string") {
      throw new MatcWebError(`${engine} has no shader source ${patch.source}; the integration was tested with ${tested}`);
    }
    const count = countAnchor(source, patch.anchor);
    if (count !== (patch.count ?? 1)) {
      throw new MatcWebError(
          `${engine}: the shader source ${patch.source} changed (${count} matches for the text the patch ` +
          `"${patch.what}" replaces, expected ${patch.count ?? 1}); the integration was tested with ` +
          `${tested}: pin that version or update the patch`);
    }
  }
}
