// The C++ runtime evaluating F on 1,000,000 cosines (one thread): the baseline of the Python
// module's vectorised F in bench/python-bench.sh (docs/performance.md, "From Python").
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "compile/compile.h"
#include "matc/runtime/fresnel.h"
#include "matc/runtime/shader_basis.h"

namespace {

constexpr std::size_t kCosines = 1'000'000;

struct Inputs {
  matc::CompiledMaterial compiled;
  std::vector<double> mu;
};

Inputs inputs() {
  // gold_rgb_ior's complex IOR (examples/materials), the material the Python benchmark uses.
  matc::Material material;
  material.name = "gold_rgb_ior";
  material.model = matc::IorInput{{0.143, 0.374, 1.442}, {3.983, 2.385, 1.603}};
  Inputs made{matc::compile_material(material, matc::runtime::shipped_basis()),
              std::vector<double>(kCosines)};
  std::mt19937_64 random(1);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (double& cosine : made.mu)
    cosine = uniform(random);
  return made;
}

void count_cosines(benchmark::State& state) {
  state.counters["cosines/s"] = benchmark::Counter(static_cast<double>(kCosines),
                                                   benchmark::Counter::kIsIterationInvariantRate);
}

// One call per cosine.
void EvaluateFresnelEach(benchmark::State& state) {
  const Inputs in = inputs();
  const matc::runtime::ShaderBasis& basis = matc::runtime::shipped_shader_basis();
  std::vector<matc::runtime::Rgb> out(kCosines);
  for (auto _ : state) {
    for (std::size_t i = 0; i < kCosines; ++i)
      out[i] = matc::runtime::evaluate_fresnel(in.compiled.coefficients, basis, in.mu[i]);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  count_cosines(state);
}

// One call for all of them (what the Python module calls, per thread).
void EvaluateFresnelSpan(benchmark::State& state) {
  const Inputs in = inputs();
  const matc::runtime::ShaderBasis& basis = matc::runtime::shipped_shader_basis();
  std::vector<double> out(3 * kCosines);
  for (auto _ : state) {
    matc::runtime::evaluate_fresnel(in.compiled.coefficients, basis, in.mu, out);
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  count_cosines(state);
}

BENCHMARK(EvaluateFresnelEach)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);
BENCHMARK(EvaluateFresnelSpan)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

}  // namespace

BENCHMARK_MAIN();
