// Between a public batch and the library's (batch.cpp, bake.cpp): the events as the library's
// batches report them (diagnostics made public, the batch's own errors escaped), and their counts.
#pragma once

#include "matc/api/batch.h"
#include "pipeline/batch.h"

namespace matc::api {

// Refers to `events`, which must outlive the batch.
matc::BatchEvents library_events(const BatchEvents& events);

// A library batch's counts as the public result.
BatchResult public_result(const BatchCounts& counts, bool cancelled = false);

}  // namespace matc::api
