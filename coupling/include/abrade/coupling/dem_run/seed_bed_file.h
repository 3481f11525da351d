#pragma once
// Where a run keeps the bed of a seed: the lifetime loop's cycles and the studies' runs alike
// (abrade concepts hands its beds to its lifetime runs under these names).
#include <string>

namespace abrade::coupling
{
  /// Seed @p seed's bed, relative to the output directory ("beds/bed-seed3.bed").
  inline std::string seed_bed_file(int seed) { return "beds/bed-seed" + std::to_string(seed) + ".bed"; }
} // namespace abrade::coupling
