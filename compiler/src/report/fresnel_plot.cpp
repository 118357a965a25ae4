#include "report/fresnel_plot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <fmt/format.h>

namespace matc {
namespace {

constexpr double kLeft = 60.0;
constexpr double kPanelWidth = 260.0;
constexpr double kPanelGap = 50.0;
constexpr double kPanelHeight = 200.0;
constexpr std::array<double, 2> kRowTop = {96.0, 350.0};
constexpr std::array<const char*, 3> kChannelNames = {"R", "G", "B"};

struct Panel {
  double x = 0.0;  // left edge
  double y = 0.0;  // top edge
  double value_min = 0.0;
  double value_max = 1.0;
  double px(double theta_degrees) const { return x + kPanelWidth * theta_degrees / 90.0; }
  double py(double value) const {
    return y + kPanelHeight * (value_max - value) / (value_max - value_min);
  }
};

struct Model {
  const std::vector<Rgb>* values;
  std::string_view colour;
  const char* dash;  // SVG stroke-dasharray, empty for solid
  const char* label;
};

std::array<Model, 4> models(const MaterialCurves& curves) {
  return {{{&curves.exact, kExactColour, "", "exact"},
           {&curves.schlick, kSchlickColour, "6 3", "Schlick"},
           {&curves.f82_tint, kF82TintColour, "2 2", "F82-tint"},
           {&curves.ours, kOursColour, "", "ours"}}};
}

void append_polyline(std::string& out, const Panel& panel, const std::vector<double>& theta,
                     const std::vector<double>& values, const Model& model, double width,
                     const std::string& clip_id) {
  out.append(fmt::format(
      R"svg(<polyline clip-path="url(#{})" fill="none" stroke="{}" stroke-width="{}")svg", clip_id,
      model.colour, width));
  if (*model.dash) out.append(fmt::format(R"( stroke-dasharray="{}")", model.dash));
  out.append(R"( points=")");
  for (std::size_t i = 0; i < theta.size(); ++i) {
    out.append(
        fmt::format("{}{:.1f},{:.1f}", i == 0 ? "" : " ", panel.px(theta[i]), panel.py(values[i])));
  }
  out.append("\"/>\n");
}

void append_frame(std::string& out, const Panel& panel, const std::vector<double>& y_ticks,
                  const std::string& title, const std::string& clip_id) {
  out.append(fmt::format(
      R"(<clipPath id="{}"><rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}"/></clipPath>)"
      "\n",
      clip_id, panel.x, panel.y, kPanelWidth, kPanelHeight));
  for (int degrees = 0; degrees <= 90; degrees += 15) {
    const double x = panel.px(degrees);
    out.append(fmt::format(
        R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" stroke="#dddddd"/>)"
        "\n",
        x, panel.y, panel.y + kPanelHeight));
    out.append(
        fmt::format(R"(<text x="{:.1f}" y="{:.1f}" font-size="11" text-anchor="middle">{}</text>)"
                    "\n",
                    x, panel.y + kPanelHeight + 14, degrees));
  }
  for (const double tick : y_ticks) {
    const double y = panel.py(tick);
    out.append(fmt::format(R"(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="{}"/>)"
                           "\n",
                           panel.x, y, panel.x + kPanelWidth, y,
                           tick == 0.0 ? "#999999" : "#dddddd"));
    out.append(
        fmt::format(R"(<text x="{:.1f}" y="{:.1f}" font-size="11" text-anchor="end">{:g}</text>)"
                    "\n",
                    panel.x - 4, y + 4, tick));
  }
  out.append(fmt::format(
      R"(<rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}" fill="none" stroke="#666666"/>)"
      "\n",
      panel.x, panel.y, kPanelWidth, kPanelHeight));
  out.append(
      fmt::format(R"(<text x="{:.1f}" y="{:.1f}" font-size="13" text-anchor="middle">{}</text>)"
                  "\n",
                  panel.x + kPanelWidth / 2, panel.y - 6, escape_xml(title)));
}

std::vector<double> channel(const std::vector<Rgb>& values, std::size_t c) {
  std::vector<double> out;
  for (const Rgb& value : values)
    out.push_back(value[c]);
  return out;
}

std::vector<double> difference(const std::vector<Rgb>& values, const std::vector<Rgb>& exact,
                               std::size_t c) {
  std::vector<double> out;
  for (std::size_t i = 0; i < values.size(); ++i)
    out.push_back(values[i][c] - exact[i][c]);
  return out;
}

double max_abs_error(const std::vector<Rgb>& values, const std::vector<Rgb>& exact) {
  double worst = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i)
    for (std::size_t c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(values[i][c] - exact[i][c]));
  return worst;
}

}  // namespace

std::string escape_xml(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

double error_axis_range(const MaterialCurves& curves) {
  const double needed = std::max(max_abs_error(curves.ours, curves.exact),
                                 max_abs_error(curves.f82_tint, curves.exact));
  for (const double range : {0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5})
    if (needed <= range) return range;
  return 1.0;
}

std::string fresnel_plot_svg(const MaterialCurves& curves, std::string_view title,
                             std::string_view subtitle) {
  std::string out = fmt::format(
      R"(<svg xmlns="http://www.w3.org/2000/svg" width="{0}" height="{1}" viewBox="0 0 {0} {1}" font-family="sans-serif">)"
      "\n"
      R"(<rect width="{0}" height="{1}" fill="#ffffff"/>)"
      "\n"
      R"(<text x="{2}" y="24" font-size="17" font-weight="bold">{3}</text>)"
      "\n"
      R"(<text x="{2}" y="44" font-size="12">{4}</text>)"
      "\n",
      kPlotWidth, kPlotHeight, kLeft, escape_xml(title), escape_xml(subtitle));

  // Legend.
  double legend_x = kLeft;
  for (const Model& model : models(curves)) {
    out.append(fmt::format(
        R"(<line x1="{:.1f}" y1="64" x2="{:.1f}" y2="64" stroke="{}" stroke-width="2.5"{}/>)"
        "\n"
        R"(<text x="{:.1f}" y="68" font-size="12">{}</text>)"
        "\n",
        legend_x, legend_x + 28, model.colour,
        *model.dash ? fmt::format(R"( stroke-dasharray="{}")", model.dash) : std::string(),
        legend_x + 34, model.label));
    legend_x += 120;
  }

  const double range = error_axis_range(curves);
  const double schlick_error = max_abs_error(curves.schlick, curves.exact);
  for (std::size_t c = 0; c < 3; ++c) {
    const double x = kLeft + static_cast<double>(c) * (kPanelWidth + kPanelGap);
    const Panel top{x, kRowTop[0], 0.0, 1.0};
    const std::string top_clip = fmt::format("f{}", c);
    append_frame(out, top, {0.0, 0.25, 0.5, 0.75, 1.0},
                 fmt::format("{}: reflectance F", kChannelNames[c]), top_clip);
    for (const Model& model : models(curves)) {
      append_polyline(out, top, curves.theta_degrees, channel(*model.values, c), model,
                      model.values == &curves.exact ? 3.0 : 1.8, top_clip);
    }

    const Panel bottom{x, kRowTop[1], -range, range};
    const std::string bottom_clip = fmt::format("e{}", c);
    append_frame(out, bottom, {-range, -range / 2, 0.0, range / 2, range},
                 fmt::format("{}: F - exact", kChannelNames[c]), bottom_clip);
    for (const Model& model : models(curves)) {
      if (model.values == &curves.exact) continue;
      append_polyline(out, bottom, curves.theta_degrees, difference(*model.values, curves.exact, c),
                      model, 1.8, bottom_clip);
    }
  }
  out.append(fmt::format(
      R"(<text x="{:.1f}" y="{:.1f}" font-size="12" text-anchor="middle">angle of incidence (degrees)</text>)"
      "\n",
      kLeft + 1.5 * kPanelWidth + kPanelGap, kRowTop[1] + kPanelHeight + 32));
  if (schlick_error > range) {
    out.append(fmt::format(
        R"(<text x="{:.1f}" y="{:.1f}" font-size="11" fill="{}">Schlick's error reaches {:.3f} and leaves the error axes (+/-{:g}).</text>)"
        "\n",
        kLeft, kRowTop[1] + kPanelHeight + 50, kSchlickColour, schlick_error, range));
  }
  out.append("</svg>\n");
  return out;
}

}  // namespace matc
