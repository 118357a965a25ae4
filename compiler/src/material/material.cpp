#include "material/material.h"

namespace matc {

std::string_view model_key(const MaterialModel& model) {
  struct Visitor {
    std::string_view operator()(const ArtisticInput&) const { return "artistic"; }
    std::string_view operator()(const IorInput&) const { return "ior"; }
    std::string_view operator()(const SpectralInput&) const { return "spectral"; }
    std::string_view operator()(const F82TintInput&) const { return "f82_tint"; }
  };
  return std::visit(Visitor{}, model);
}

}  // namespace matc
