// One encoder per container format; lut_files.cpp dispatches between them.
#pragma once

#include <string>

#include "matc/lut/lut_files.h"

namespace matc::lut_writers {

std::string encode_ktx2(const Lut& lut, LutPrecision precision);
std::string encode_dds(const Lut& lut, LutPrecision precision);
std::string encode_header(const BakedLut& baked, LutPrecision precision);

}  // namespace matc::lut_writers
