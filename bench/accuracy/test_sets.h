// The curves the accuracy studies score on (basis_study.cpp, table_study.cpp): measured metals,
// alternative data sets, random and edge-of-range artistic inputs, dielectrics. None was in any
// training set.
#pragma once

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fit/accuracy.h"
#include "optics/gulbrandsen.h"
#include "optics/reflectance_curve.h"

namespace matc::bench {

struct TestCurve {
  std::string name;
  std::unique_ptr<ReflectanceCurve> exact;
  std::unique_ptr<AccuracyGridCurve> cached;
  std::size_t channels = 3;  // grey curves count once
  // Gulbrandsen's (r, g) per channel where the curve is one (artistic inputs, dielectrics).
  std::optional<std::array<ArtisticParameters, 3>> artistic;
};

struct TestSet {
  std::string name;
  std::vector<TestCurve> curves;
  void add(std::string curve_name, std::unique_ptr<ReflectanceCurve> exact, std::size_t channels,
           std::optional<std::array<ArtisticParameters, 3>> artistic = std::nullopt);
};

TestSet measured_metals();
TestSet alternative_metals(const std::filesystem::path& directory);
TestSet artistic(std::size_t count, double r_max);
// Grey artistic inputs at one edge tint, r = first, first + step, ... up to last.
TestSet edge_tint_line(double g, double first, double last, double step);
TestSet dielectrics();

// All of the above, in the order the tables print them.
std::vector<TestSet> study_test_sets(const std::filesystem::path& alternative_directory);

}  // namespace matc::bench
