// Baking the preintegrated table: time and samples per second (docs/performance.md).
#include <thread>

#include <benchmark/benchmark.h>

#include "lut/preintegrate.h"

namespace {

void BakeLut(benchmark::State& state) {
  const matc::LutOptions options{static_cast<std::size_t>(state.range(0)),
                                 static_cast<std::size_t>(state.range(1)),
                                 static_cast<unsigned>(state.range(2))};
  const matc::runtime::BasisView basis = matc::runtime::shipped_basis();
  for (auto _ : state) {
    const matc::Lut lut = matc::preintegrate_lut(basis, options);
    benchmark::DoNotOptimize(lut.texels.data());
  }
  const double samples = static_cast<double>(options.size * options.size * options.samples);
  state.counters["samples/s"] =
      benchmark::Counter(samples, benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK(BakeLut)
    ->ArgNames({"size", "samples", "threads"})
    ->Args({128, 1024, 1})
    ->Args({128, 1024, 2})
    ->Args({64, 1024, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(1.0);

}  // namespace

BENCHMARK_MAIN();
