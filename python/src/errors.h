// matc's diagnostics as Python values, and the C++ exception that becomes matc.MaterialError (or
// matc.BatchError) with the located diagnostics attached (matc/errors.py defines both).
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include <pybind11/pybind11.h>

#include "matc/base/diagnostics.h"

namespace matc::python {

// Text from matc as a Python str. Diagnostics quote input bytes, which need not be UTF-8: bytes
// that are not decode as surrogate escapes (as os.fsdecode does), so no message is lost and
// printing it gives back what the CLI prints.
pybind11::str python_text(std::string_view text);

// The diagnostics' lines as the CLI prints them, one per line.
std::string formatted_lines(const Diagnostics& diagnostics);

// A list of matc.Diagnostic values.
pybind11::list diagnostic_list(const Diagnostics& diagnostics);

// Thrown for input that has errors; raised in Python as matc.MaterialError.
class MaterialErrorThrown : public std::runtime_error {
 public:
  explicit MaterialErrorThrown(Diagnostics diagnostics)
      : std::runtime_error(formatted_lines(diagnostics)), diagnostics_(std::move(diagnostics)) {}
  const Diagnostics& diagnostics() const { return diagnostics_; }

 private:
  Diagnostics diagnostics_;
};

// Raises matc.BatchError(message, diagnostics, result) and throws error_already_set: a batch that
// failed still says what it wrote.
[[noreturn]] void raise_batch_error(const Diagnostics& diagnostics, pybind11::object result);

}  // namespace matc::python
