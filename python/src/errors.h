// matc's diagnostics as Python values, and the library's MaterialError raised as
// matc.MaterialError (or a batch's failure as matc.BatchError) with the located diagnostics
// attached (matc/errors.py defines both).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <pybind11/pybind11.h>

#include "matc/matc.h"

namespace matc::python {

// Text from matc as a Python str. Diagnostics are escaped (valid UTF-8), but a path or a name
// read from a file need not be: bytes that are not UTF-8 decode as surrogate escapes (as
// os.fsdecode does), so no text is lost and printing it gives back what the CLI prints.
pybind11::str python_text(std::string_view text);

// The diagnostics' lines as the CLI prints them, one per line.
std::string formatted_lines(const std::vector<api::Diagnostic>& diagnostics);

// A list of matc.Diagnostic values.
pybind11::list diagnostic_list(const std::vector<api::Diagnostic>& diagnostics);

// Raises matc.BatchError(message, diagnostics, result) and throws error_already_set: a batch that
// failed still says what it wrote.
[[noreturn]] void raise_batch_error(const std::vector<api::Diagnostic>& diagnostics,
                                    pybind11::object result);

}  // namespace matc::python
