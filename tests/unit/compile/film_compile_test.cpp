// Materials with a film compiled (compile/compile.h, docs/material-format.md "film"): the curve the
// compile fits is the film's, a film of 0 nm, of no coverage or of index 1 is the bare metal bit
// for bit, and the fit's accuracy is reported against the film's curve.
#include <gtest/gtest.h>

#include <algorithm>

#include "compile/compile.h"
#include "matc/runtime/shipped_bases.h"
#include "optics/presets.h"
#include "optics/thin_film.h"
#include "preset_material.h"

namespace matc {
namespace {

Material titanium(std::optional<FilmInput> film) {
  Material material = test::preset_material(*find_metal_preset("Ti"), "titanium");
  material.film = film;
  return material;
}

TEST(FilmCompile, NoThicknessNoCoverageOrIndexOneIsTheBareMetalBitForBit) {
  const auto& basis = runtime::shipped_basis();
  const CompiledMaterial bare = compile_material(titanium(std::nullopt), basis);
  // A film of index 1 is air (Khronos's IridescenceMetallicSpheres has 49 such metals).
  for (const FilmInput film :
       {FilmInput{1.0, 2.3, 0.0}, FilmInput{0.0, 2.3, 300.0}, FilmInput{1.0, 1.0, 300.0}}) {
    const CompiledMaterial same = compile_material(titanium(film), basis);
    EXPECT_EQ(same.coefficients, bare.coefficients);
    EXPECT_EQ(same.f0, bare.f0);
    EXPECT_FALSE(same.film_table);  // the bare metal's shaders, not a table
  }
}

// A film the basis cannot hold (300 nm oscillates with the angle) compiles to its own table, which
// the shaders read: the table's error is what the outputs report, and it is no poor fit.
TEST(FilmCompile, CarriesItsOwnTableWhichHoldsTheFilm) {
  const auto& basis = runtime::shipped_basis();
  const CompiledMaterial compiled = compile_material(titanium(FilmInput{1.0, 2.3, 300.0}), basis);
  ASSERT_TRUE(compiled.film_table);
  const double fit = worst_channel(compiled.accuracy.decomposition.max_abs);
  const double table = worst_channel(compiled.film_table_error.max_abs);
  EXPECT_GT(fit, 0.05);     // the 4-term fit misses it
  EXPECT_LT(table, 0.004);  // the table does not (the target is 0.01)
  EXPECT_EQ(&shader_fresnel_error(compiled), &compiled.film_table_error);
  Diagnostics diagnostics;
  warn_if_poor_fit(compiled, diagnostics);
  EXPECT_TRUE(diagnostics.items().empty());
}

TEST(FilmCompile, FitsTheFilmsCurveAndReportsHowClosely) {
  const auto& basis = runtime::shipped_basis();
  const FilmInput film{1.0, 2.3, 40.0};
  const CompiledMaterial compiled = compile_material(titanium(film), basis);
  const ThinFilmCurve exact(preset_spectrum(*find_metal_preset("Ti")), {2.3, 40.0});
  const Rgb f0 = exact.at(1.0);
  for (std::size_t c = 0; c < 3; ++c)
    EXPECT_DOUBLE_EQ(compiled.f0[c], f0[c]);
  // A 40 nm film of titania turns titanium dark gold: far from its bare grey F0 of about 0.58.
  EXPECT_LT(compiled.f0[1], 0.2);
  // The fit reported is the film curve's (0.0197 worst; docs/accuracy.md "Thin films").
  const double worst = *std::max_element(compiled.accuracy.decomposition.max_abs.begin(),
                                         compiled.accuracy.decomposition.max_abs.end());
  EXPECT_GT(worst, 0.01);
  EXPECT_LT(worst, 0.025);
  // A film is not a conductor: no per-channel index describes the curve.
  EXPECT_FALSE(compiled.ior);
}

}  // namespace
}  // namespace matc
