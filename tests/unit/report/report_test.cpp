// matc report's pieces: sampled curves, their CSV, the SVG plot and the HTML index.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "compile/compile.h"
#include "material/parse.h"
#include "report/fresnel_plot.h"
#include "report/material_curves.h"
#include "report/report_page.h"

namespace matc {
namespace {

CompiledMaterial compiled(const std::string& json) {
  const ParseResult parsed = parse_material(json, "memory/test.json");
  EXPECT_TRUE(parsed.material);
  return compile_material(*parsed.material, runtime::shipped_basis());
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
    ++n;
  return n;
}

const char* const kChromium = R"({"name": "cr", "spectral": {"preset": "Cr"}})";

TEST(MaterialCurves, RunFromNormalIncidenceToGrazing) {
  const CompiledMaterial material = compiled(kChromium);
  const MaterialCurves curves = sample_material_curves(material, runtime::shipped_shader_basis());
  ASSERT_EQ(curves.theta_degrees.size(), kReportAngles);
  EXPECT_EQ(curves.theta_degrees.front(), 0.0);
  EXPECT_EQ(curves.theta_degrees.back(), 90.0);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_NEAR(curves.exact.front()[c], material.f0[c], 1e-12);
    EXPECT_NEAR(curves.schlick.front()[c], material.f0[c], 1e-12);
    EXPECT_NEAR(curves.exact.back()[c], 1.0, 1e-12);
    EXPECT_NEAR(curves.ours.back()[c], 1.0, 1e-4);
  }
  // The plotted error is the accuracy the compiler reports (on a coarser set of angles).
  double worst = 0.0;
  for (std::size_t i = 0; i < kReportAngles; ++i)
    for (std::size_t c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(curves.ours[i][c] - curves.exact[i][c]));
  const auto& reported = material.accuracy.decomposition.max_abs;
  EXPECT_LE(worst, *std::max_element(reported.begin(), reported.end()) + 1e-9);
}

TEST(MaterialCurves, CsvHasAHeaderAndOneRowPerAngle) {
  const MaterialCurves curves =
      sample_material_curves(compiled(kChromium), runtime::shipped_shader_basis());
  const std::string csv = material_curves_csv(curves);
  EXPECT_EQ(count(csv, "\n"), kReportAngles + 1);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "theta_deg,exact_r,exact_g,exact_b,ours_r,ours_g,ours_b,schlick_r,schlick_g,schlick_b,"
            "f82_tint_r,f82_tint_g,f82_tint_b");
  EXPECT_NE(csv.find("\n90.0,1.000000,1.000000,1.000000,"), std::string::npos);
}

TEST(FresnelPlot, HasAPanelPairPerChannelAndEveryCurve) {
  const MaterialCurves curves =
      sample_material_curves(compiled(kChromium), runtime::shipped_shader_basis());
  const std::string svg = fresnel_plot_svg(curves, "cr <&>", "subtitle");
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  EXPECT_EQ(count(svg, "<clipPath"), 6u);
  // Top panels: exact, Schlick, F82-tint, ours; error panels: the three approximations.
  EXPECT_EQ(count(svg, "<polyline"), 3u * 4u + 3u * 3u);
  EXPECT_EQ(count(svg, std::string("stroke=\"") + std::string(kOursColour)), 3u * 2u + 1u);
  EXPECT_NE(svg.find("cr &lt;&amp;&gt;"), std::string::npos);
  // Chromium: Schlick is off by 0.2, far outside the error axes ours and F82-tint need.
  EXPECT_EQ(error_axis_range(curves), 0.05);
  EXPECT_NE(svg.find("Schlick's error reaches"), std::string::npos);
}

TEST(FresnelPlot, SameCurvesSameBytes) {
  const MaterialCurves curves =
      sample_material_curves(compiled(kChromium), runtime::shipped_shader_basis());
  EXPECT_EQ(fresnel_plot_svg(curves, "a", "b"), fresnel_plot_svg(curves, "a", "b"));
}

TEST(FresnelPlot, EscapesEveryXmlSpecialCharacter) {
  EXPECT_EQ(escape_xml(R"(a&b<c>d"e'f)"), "a&amp;b&lt;c&gt;d&quot;e&#39;f");
}

TEST(ReportPage, ListsEveryMaterialAndShowsItsPlot) {
  const CompiledMaterial material = compiled(kChromium);
  const std::vector<ReportEntry> entries = {{"cr", "cr.json", material.f0, material.accuracy},
                                            {"gold", "gold.json", material.f0, material.accuracy}};
  const std::string html = report_index_html(entries, "extended");
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_EQ(count(html, "<img class=\"plot\""), 2u);
  EXPECT_NE(html.find("src=\"cr.svg\""), std::string::npos);
  EXPECT_NE(html.find("src=\"gold.svg\""), std::string::npos);
  EXPECT_NE(html.find("href=\"gold.csv\""), std::string::npos);
  EXPECT_NE(html.find("basis <code>extended</code>"), std::string::npos);
  EXPECT_NE(html.find("dataset.plotsLoaded"), std::string::npos);
}

}  // namespace
}  // namespace matc
