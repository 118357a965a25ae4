// libmatc's public API: read materials, compile them, evaluate their curves and write their
// texts. The CLI, the Python module and the WebAssembly binding are faces over it (docs/api.md).
// Native builds add "matc/api/tables.h" (the tables a renderer samples), "matc/api/basis.h" (a
// shipped basis described), "matc/api/build.h" (every
// file `matc` writes, in memory), "matc/api/batch.h" (a batch into an output directory, as
// `matc -o` runs it), "matc/api/evaluation.h" (what `matc eval` prints), "matc/api/report.h"
// (what `matc report` writes) and "matc/api/files.h" (writing a file as matc writes its outputs).
#pragma once

#include "matc/api/compiled_material.h"
#include "matc/api/diagnostics.h"
#include "matc/api/gltf.h"
#include "matc/api/layout.h"
#include "matc/api/material.h"
#include "matc/api/options.h"
#include "matc/api/text_outputs.h"
