// The native side of the WebAssembly comparison (tests/js/check-wasm-package.mjs): reads material
// requests, one JSON object per line ({"text", "path", "options": {basis, colorSpace,
// gamutMapping}, optionally "mu": the cosines to evaluate}), compiles each through the public API
// (matc/matc.h) and writes one JSON line per material: coefficients, F0, F82, the curves (F, exact,
// Schlick, F82-tint) on the cosines and Fbar on tests' (NdotV, roughness) pairs, and the four
// texts. Also used by check-lookdev.mjs. Numbers are written with 17 significant digits: they read
// back exactly.
#include <iostream>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "matc/matc.h"

namespace {

// The cosines and pairs the comparison evaluates: both ends and 63 points between.
std::vector<double> cosines() {
  std::vector<double> mu;
  for (int i = 0; i <= 64; ++i)
    mu.push_back(i / 64.0);
  return mu;
}

nlohmann::json rows(const matc::api::CoefficientRows& values) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& row : values)
    out.push_back(row);
  return out;
}

nlohmann::json dump(const matc::api::CompiledMaterial& compiled,
                    const matc::api::TextOutputs& texts, const std::vector<double>& mu) {
  std::vector<double> ndotv, roughness;
  for (double n : {0.05, 0.3, 0.7, 1.0}) {
    for (double r : {0.0, 0.25, 0.6, 1.0}) {
      ndotv.push_back(n);
      roughness.push_back(r);
    }
  }
  nlohmann::json out;
  out["name"] = compiled.name();
  out["coefficients"] = rows(compiled.coefficients());
  out["f0"] = compiled.f0();
  out["f82"] = compiled.f82();
  out["fresnel"] = compiled.fresnel(mu);
  out["exact"] = compiled.exact(mu);
  out["schlick"] = compiled.schlick(mu);
  out["f82_tint"] = compiled.f82_tint(mu);
  out["fbar"] = compiled.fbar(ndotv, roughness);
  if (const auto coat = compiled.coat()) {
    out["under_coat_coefficients"] = rows(coat->under_coat_coefficients);
    out["coat_coefficients"] = coat->coat_coefficients;
  }
  for (const char* language : {"glsl", "hlsl", "wgsl"})
    out["texts"][language] = texts.material_source(language, compiled);
  out["texts"]["json"] = texts.material_json(compiled);
  return out;
}

}  // namespace

int main() {
  std::string line;
  while (std::getline(std::cin, line)) {
    const nlohmann::json request = nlohmann::json::parse(line);
    const nlohmann::json& given = request.value("options", nlohmann::json::object());
    const matc::api::CompileOptions options{given.value("basis", ""), given.value("colorSpace", ""),
                                            given.value("gamutMapping", "")};
    const std::vector<double> mu =
        request.contains("mu") ? request.at("mu").get<std::vector<double>>() : cosines();
    nlohmann::json result;
    try {
      const matc::api::TextOutputs texts(options);
      result["materials"] = nlohmann::json::array();
      for (const matc::api::Material& material : matc::api::parse_materials(
               request.at("text").get<std::string>(), request.at("path").get<std::string>()))
        result["materials"].push_back(dump(matc::api::compile(material, options), texts, mu));
    } catch (const matc::api::MaterialError& error) {
      result["error"] = error.what();
    }
    std::cout << result.dump(-1, ' ', false, nlohmann::json::error_handler_t::strict) << '\n';
  }
}
