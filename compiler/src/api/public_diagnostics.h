// The library's diagnostics as the public face's (plain values, the CLI's text beside them).
#pragma once

#include <vector>

#include "base/diagnostics.h"
#include "matc/api/diagnostics.h"

namespace matc::api {

std::vector<Diagnostic> public_diagnostics(const Diagnostics& diagnostics);

// Throws MaterialError with `diagnostics` when they hold an error.
void throw_if_errors(const Diagnostics& diagnostics);

}  // namespace matc::api
