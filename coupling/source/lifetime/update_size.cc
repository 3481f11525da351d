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
} // namespace abrade::coupling::lifetime
