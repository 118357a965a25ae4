// What `matc bake` does (docs/baking.md): reflectivity and edge-tint maps (or n and k maps) into
// coefficient textures with mip chains computed in coefficient space, KTX2 or DDS, per asset:
// asset files, or assets described in memory (a tool's, or the command line's). Native builds.
#pragma once

#include <optional>
#include <span>
#include <stop_token>
#include <string>
#include <vector>

#include "matc/api/batch.h"

namespace matc::api {

// One map of an asset described in memory: an image file (PNG, JPEG, OpenEXR) or constant values
// ("R,G,B" or one grey value). `label` is what its diagnostics call it ("--reflectivity").
struct BakeMap {
  std::string label;
  std::string value;  // empty: not given
};

// An asset described in memory: one pair of maps, reflectivity and edge tint or n and k.
struct BakeDescription {
  std::string origin;  // where it was described: its diagnostics' place ("matc bake")
  BakeMap reflectivity{"reflectivity", {}};
  BakeMap edge_tint{"edge_tint", {}};
  BakeMap n{"n", {}};
  BakeMap k{"k", {}};
  // The stem of its files; empty: the first map file's stem. `name_label` names it in
  // diagnostics.
  std::string name;
  std::string name_label = "name";
  bool linear = false;  // its 8- and 16-bit map files hold linear values, not sRGB
};

struct BakeSource {
  std::string path;  // the asset file; for a description, what name-clash errors call it
  std::optional<BakeDescription> described;
  static BakeSource file(std::string path) { return {std::move(path), std::nullopt}; }
  static BakeSource in_memory(BakeDescription description, std::string label) {
    return {std::move(label), std::move(description)};
  }
};

struct BakeOptions {
  std::string output_directory;
  std::string basis;        // by --basis's names; empty: the default
  std::string format;       // "ktx2" (default) or "dds"
  std::string precision;    // "f16" (default) or "f32"
  bool f0 = false;          // also NAME_f0: linear F0 with coefficient-space mips
  bool error_map = false;   // also NAME_error.png: level 0's largest |F - exact| per texel
  unsigned jobs = 0;        // threads; 0: one per hardware thread (the result is the same)
  bool keep_going = false;  // bake the others after one fails
  std::string depfile;      // Make-syntax dependencies of every output; empty: none
  std::vector<std::string> extra_dependencies;  // listed after the assets and maps
};

// `compiled` counts the assets baked. Throws std::invalid_argument for an option outside its
// names or no output directory.
BatchResult bake_batch(std::span<const BakeSource> sources, const BakeOptions& options,
                       const BatchEvents& events = {}, std::stop_token cancel = {});

}  // namespace matc::api
