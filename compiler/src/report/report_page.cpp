#include "report/report_page.h"

#include <fmt/format.h>

#include "matc/version.h"
#include "report/fresnel_plot.h"

namespace matc {
namespace {

std::string error_table(const FitAccuracy& accuracy) {
  std::string out =
      "<table>\n<tr><th>model</th><th>max R</th><th>max G</th><th>max B</th><th>RMS R</th>"
      "<th>RMS G</th><th>RMS B</th></tr>\n";
  const std::pair<const char*, const ErrorStats*> rows[] = {{"ours", &accuracy.decomposition},
                                                            {"Schlick", &accuracy.schlick},
                                                            {"F82-tint", &accuracy.f82_tint}};
  for (const auto& [label, stats] : rows) {
    out.append(fmt::format("<tr><td>{}</td>", label));
    for (const double value : stats->max_abs)
      out.append(fmt::format("<td>{:.4f}</td>", value));
    for (const double value : stats->rms)
      out.append(fmt::format("<td>{:.4f}</td>", value));
    out.append("</tr>\n");
  }
  out.append("</table>\n");
  return out;
}

}  // namespace

std::string report_index_html(std::span<const ReportEntry> entries, std::string_view basis_name) {
  std::string out = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>matc accuracy report</title>\n"
      "<style>\n"
      "body {{ font-family: sans-serif; margin: 2em; color: #222; }}\n"
      "table {{ border-collapse: collapse; margin: 0.5em 0 1.5em; }}\n"
      "th, td {{ border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: right; }}\n"
      "th:first-child, td:first-child {{ text-align: left; }}\n"
      "img {{ max-width: 100%; height: auto; border: 1px solid #eee; }}\n"
      "</style>\n</head>\n<body>\n"
      "<h1>matc accuracy report</h1>\n"
      "<p>matc {}, basis <code>{}</code>. Absolute reflectance error per linear-sRGB channel "
      "against the exact Fresnel curve, at {} cosines uniform in [0, 1]; ours is evaluated as the "
      "shaders evaluate it. Schlick and F82-tint are given the exact F0 (and F82).</p>\n"
      "<table>\n<tr><th>material</th><th>source</th><th>F0 (linear sRGB)</th>"
      "<th>ours, worst channel</th><th>Schlick</th><th>F82-tint</th><th>files</th></tr>\n",
      kVersion, escape_xml(basis_name), kAccuracySamples);
  for (const ReportEntry& entry : entries) {
    const std::string name = escape_xml(entry.name);
    out.append(fmt::format(
        "<tr><td><a href=\"#{0}\">{0}</a></td><td>{1}</td><td>{2:.3f}, {3:.3f}, {4:.3f}</td>"
        "<td>{5:.4f}</td><td>{6:.4f}</td><td>{7:.4f}</td>"
        "<td><a href=\"{0}.svg\">svg</a> <a href=\"{0}.csv\">csv</a></td></tr>\n",
        name, escape_xml(entry.source), entry.f0[0], entry.f0[1], entry.f0[2],
        worst_channel(entry.accuracy.decomposition.max_abs),
        worst_channel(entry.accuracy.schlick.max_abs),
        worst_channel(entry.accuracy.f82_tint.max_abs)));
  }
  out.append("</table>\n");
  for (const ReportEntry& entry : entries) {
    const std::string name = escape_xml(entry.name);
    out.append(fmt::format(
        "<section id=\"{0}\">\n<h2>{0}</h2>\n"
        "<img class=\"plot\" src=\"{0}.svg\" width=\"{1}\" height=\"{2}\" "
        "alt=\"Fresnel curves of {0}: exact, ours, Schlick and F82-tint per channel\">\n",
        name, kPlotWidth, kPlotHeight));
    out.append(error_table(entry.accuracy));
    out.append("</section>\n");
  }
  out.append(
      "<script>\n"
      "window.addEventListener('load', () => {\n"
      "  const plots = [...document.querySelectorAll('img.plot')];\n"
      "  document.body.dataset.plotsLoaded =\n"
      "      plots.filter((img) => img.complete && img.naturalWidth > 0).length;\n"
      "});\n"
      "</script>\n</body>\n</html>\n");
  return out;
}

}  // namespace matc
