// The native side of bench/wasm-compile.sh: the public API's parse + compile, and the texts, of
// the materials in a file of JSON lines ({"text", "path"}), timed on one thread; prints
// "<parse+compile ms> <texts ms>", each the fastest of `runs` passes over all materials.
//   matc_api_compile_timing MATERIALS.jsonl RUNS
#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "matc/matc.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: matc_api_compile_timing MATERIALS.jsonl RUNS\n";
    return 2;
  }
  std::vector<std::pair<std::string, std::string>> inputs;
  std::ifstream file(argv[1]);
  for (std::string line; std::getline(file, line);) {
    const nlohmann::json request = nlohmann::json::parse(line);
    inputs.emplace_back(request.at("text").get<std::string>(),
                        request.at("path").get<std::string>());
  }
  const int runs = std::stoi(argv[2]);
  using Clock = std::chrono::steady_clock;
  double best_compile = std::numeric_limits<double>::infinity();
  double best_texts = std::numeric_limits<double>::infinity();
  std::size_t bytes = 0;  // keeps the texts from being optimised away
  const matc::api::TextOutputs texts;
  for (int run = 0; run < runs; ++run) {
    std::vector<matc::api::CompiledMaterial> compiled;
    const auto start = Clock::now();
    for (const auto& [text, path] : inputs)
      for (const matc::api::Material& material : matc::api::parse_materials(text, path))
        compiled.push_back(matc::api::compile(material));
    const auto compiled_at = Clock::now();
    for (const matc::api::CompiledMaterial& material : compiled) {
      for (const char* language : {"glsl", "hlsl", "wgsl"})
        bytes += texts.material_source(language, material).size();
      bytes += texts.material_json(material).size();
    }
    const auto done = Clock::now();
    best_compile = std::min(best_compile,
                            std::chrono::duration<double, std::milli>(compiled_at - start).count());
    best_texts =
        std::min(best_texts, std::chrono::duration<double, std::milli>(done - compiled_at).count());
  }
  std::cout << best_compile << ' ' << best_texts << ' ' << bytes << '\n';
}
