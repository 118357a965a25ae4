// A public batch's events as the library's batches report them: diagnostics made public, the
// batch's own errors escaped (batch.cpp, bake.cpp).
#pragma once

#include "matc/api/batch.h"
#include "matc/pipeline/batch.h"

namespace matc::api {

// Refers to `events`, which must outlive the batch.
matc::BatchEvents library_events(const BatchEvents& events);

}  // namespace matc::api
