# The CPU runtime's sources (paths relative to runtime/), for the native library and the
# WebAssembly one (js/).
# What a generator (`matc basis ...`, docs/maintainers.md) writes lives in src/generated/; the rest
# is written by hand.
set(matc_runtime_generated
  src/generated/powers_coefficient_table.cpp
  src/generated/powers_analytic_lut_table.cpp
  src/generated/extended_basis_table.cpp
  src/generated/extended_coefficient_table.cpp
  src/generated/extended_analytic_lut_table.cpp
  src/generated/paper_basis_table.cpp
  src/generated/paper_coefficient_table.cpp
  src/generated/paper_analytic_lut_table.cpp
  src/generated/f82_coefficient_table.cpp
  src/generated/f82_analytic_lut_table.cpp
  src/generated/ltc_table.cpp)
set(MATC_RUNTIME_SOURCES
  ${matc_runtime_generated}
  src/basis.cpp
  src/shipped_bases.cpp
  src/basis_polynomial.cpp
  src/powers_basis.cpp
  src/shader_basis.cpp
  src/fresnel.cpp
  src/coat.cpp
  src/lut.cpp
  src/ltc.cpp
  src/ltc_following.cpp
  src/baked_coefficients.cpp
  src/f0_table.cpp
  src/film_table.cpp
  src/coefficient_table.cpp
  src/analytic_lut.cpp)
