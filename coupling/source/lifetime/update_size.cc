// How many operating cycles one lifetime update stands for (update_size.h).
#include <abrade/coupling/lifetime/update_size.h>

#include <algorithm>
#include <cmath>

namespace abrade::coupling::lifetime
{
  long cycles_for_update(long fixed, double fraction, double mesh_size, double largest_rate)
  {
    if (fixed > 0)
      return fixed;
    const double n = std::floor(fraction * mesh_size / largest_rate);
    return n >= 1 ? (n < 1e15 ? long(n) : long(1e15)) : 1L;
  }

  long cycles_for_update(long fixed, double fraction, double mesh_size, double previous_rate, double current_rate)
  {
    if (fixed > 0)
      return fixed;
    const long n = cycles_for_update(0, fraction, mesh_size, previous_rate > 0 ? previous_rate : current_rate);
    return std::min(n, cycles_for_update(0, 2 * fraction, mesh_size, current_rate));
  }
} // namespace abrade::coupling::lifetime
