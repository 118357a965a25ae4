// The look-development page's curves: F against the angle of incidence per channel, exact,
// matc's (ours), Schlick's and F82-tint's, each the package's evaluation of the compiled material
// (CompiledMaterial.exact/fresnel/schlick/f82Tint, the functions `matc report` plots natively),
// with the error against the exact curve below. A coated metal's curves are its layered ones
// (both lobes; exact: the layered reflectance).

// The angles plotted, 0 to 90 degrees every half degree, and their cosines (exactly 0 at 90).
export function plotCosines(count = 181) {
  const angles = Array.from({ length: count }, (_, i) => (90 * i) / (count - 1));
  const mu = angles.map((degrees) => (degrees === 90 ? 0 : Math.cos((degrees * Math.PI) / 180)));
  return { angles, mu };
}

// Everything the plot draws, 3 values (R, G, B) per cosine in each curve.
export function curveSeries(compiled) {
  const { angles, mu } = plotCosines();
  return { angles, mu, exact: compiled.exact(mu), ours: compiled.fresnel(mu), schlick: compiled.schlick(mu),
           f82Tint: compiled.f82Tint(mu) };
}

const kChannels = ["#ef6a5e", "#5cc46a", "#5f8ff0"];
const kCurves = [
  { key: "exact", label: "exact", width: 3, dash: [], alpha: 0.35 },
  { key: "ours", label: "matc", width: 1.5, dash: [], alpha: 1 },
  { key: "schlick", label: "Schlick", width: 1.2, dash: [6, 4], alpha: 0.9 },
  { key: "f82Tint", label: "F82-tint", width: 1.2, dash: [2, 3], alpha: 0.9 },
];

function panel(context, { x, y, width, height }, range, title) {
  context.strokeStyle = "#34373d";
  context.fillStyle = "#8b9099";
  context.lineWidth = 1;
  context.setLineDash([]);
  context.strokeRect(x, y, width, height);
  context.fillText(title, x + 4, y + 12);
  for (const degrees of [0, 30, 60, 75, 90]) {
    const px = x + (degrees / 90) * width;
    context.beginPath();
    context.moveTo(px, y);
    context.lineTo(px, y + height);
    context.stroke();
  }
  context.fillText(range[1].toPrecision(2), x - 34, y + 10);
  context.fillText(range[0].toPrecision(2), x - 34, y + height);
}

function line(context, area, range, angles, values, channel) {
  context.beginPath();
  angles.forEach((degrees, i) => {
    const px = area.x + (degrees / 90) * area.width;
    const t = (values[3 * i + channel] - range[0]) / (range[1] - range[0]);
    const py = area.y + area.height * (1 - Math.min(Math.max(t, -0.02), 1.02));
    if (i === 0) context.moveTo(px, py);
    else context.lineTo(px, py);
  });
  context.stroke();
}

// Draws `series` (curveSeries) into the canvas: F above, F - exact below.
export function drawCurves(canvas, series) {
  const context = canvas.getContext("2d");
  const { width, height } = canvas;
  context.clearRect(0, 0, width, height);
  context.font = "11px system-ui, sans-serif";
  const left = 40, right = 8;
  const top = { x: left, y: 6, width: width - left - right, height: height * 0.58 };
  const bottom = { x: left, y: top.y + top.height + 24, width: top.width, height: height - top.height - 48 };
  const curves = kCurves.filter((curve) => series[curve.key]);
  const low = Math.min(...curves.flatMap((curve) => Array.from(series[curve.key])));
  const fRange = [Math.max(0, Math.floor(low * 10) / 10), 1];
  const errors = Object.fromEntries(curves.filter((curve) => curve.key !== "exact")
    .map((curve) => [curve.key, series[curve.key].map((value, i) => value - series.exact[i])]));
  const largest = Math.max(1e-4, ...Object.values(errors).flatMap((values) => Array.from(values, Math.abs)));
  const errorRange = [-largest, largest];
  panel(context, top, fRange, "F");
  panel(context, bottom, errorRange, "F − exact");
  for (const curve of curves) {
    context.lineWidth = curve.width;
    context.setLineDash(curve.dash);
    context.globalAlpha = curve.alpha;
    for (let channel = 0; channel < 3; ++channel) {
      context.strokeStyle = kChannels[channel];
      line(context, top, fRange, series.angles, series[curve.key], channel);
      if (errors[curve.key]) line(context, bottom, errorRange, series.angles, errors[curve.key], channel);
    }
  }
  context.globalAlpha = 1;
  context.setLineDash([]);
  context.fillStyle = "#8b9099";
  const axis = bottom.y + bottom.height + 14;
  for (const degrees of [0, 30, 60, 75, 90]) context.fillText(`${degrees}°`, left + (degrees / 90) * top.width - 6, axis);
  // Legend: each curve's stroke.
  let x = left + 40;
  for (const curve of curves) {
    context.strokeStyle = "#d8dadf";
    context.lineWidth = curve.width;
    context.setLineDash(curve.dash);
    context.beginPath();
    context.moveTo(x, top.y + top.height - 10);
    context.lineTo(x + 22, top.y + top.height - 10);
    context.stroke();
    context.fillText(curve.label, x + 26, top.y + top.height - 6);
    x += 40 + context.measureText(curve.label).width;
  }
  context.setLineDash([]);
}
