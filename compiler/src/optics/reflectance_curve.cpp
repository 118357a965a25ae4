#include "matc/optics/reflectance_curve.h"

namespace matc {

Rgb IorCurve::at(double mu) const {
  return {fresnel_exact(mu, ior_[0]), fresnel_exact(mu, ior_[1]), fresnel_exact(mu, ior_[2])};
}

}  // namespace matc
