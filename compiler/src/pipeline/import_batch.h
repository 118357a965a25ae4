// The batch import: what `matc import -o DIR DOCUMENTS...` does. Every document is imported and
// every name checked before anything is written, so that a failing batch (without keep_going)
// writes nothing and a failing document never does; each metallic material becomes <name>.json.
#pragma once

#include <span>

#include "pipeline/batch.h"
#include "pipeline/compile_batch.h"
#include "pipeline/output_sink.h"

namespace matc {

struct ImportBatchOptions {
  bool keep_going = false;  // write the other documents' materials when one fails
};

// Counts: failures count documents, the rest materials.
BatchCounts import_batch(std::span<const MaterialSource> documents, OutputSink& output,
                         const ImportBatchOptions& options = {}, const BatchEvents& events = {});

}  // namespace matc
