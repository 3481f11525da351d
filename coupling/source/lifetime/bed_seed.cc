// The seeds of the beds that each update of a lifetime run draws its wear from (wear_source.h).
#include <abrade/coupling/lifetime/wear_source.h>

#include <cstdint>

namespace abrade::coupling::lifetime
{
  int bed_seed(int seed, long update, long round)
  {
    if (update == 1 && round == 0)
      return seed;
    // SplitMix64 over the three numbers: well mixed, so that no two (seed, update, round) of a
    // run or of runs with neighbouring seeds meet (a collision would repeat a bed)
    auto mix = [](std::uint64_t z) {
      z += 0x9E3779B97F4A7C15ULL;
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
      return z ^ (z >> 31);
    };
    const std::uint64_t h = mix(mix(mix(std::uint64_t(std::uint32_t(seed))) ^ std::uint64_t(update)) ^
                                (std::uint64_t(round) << 32));
    return int(h & 0x3FFFFFFF) + 1; // 1 .. 2^30
  }
} // namespace abrade::coupling::lifetime
