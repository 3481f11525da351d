#pragma once
// How many operating cycles one lifetime update stands for. Fixed (Lifetime/Cycles per update),
// or adaptive: the largest wear depth increment of the update is a set fraction of the knife's
// mesh size, so that the surface moves by a fraction of an element per update whatever the
// wear rate (Lifetime/Depth increment fraction). The rate is the wear depth per cycle after the
// surface filter, the same depth that the end-of-life criteria measure.
namespace abrade::coupling::lifetime
{
  /// @p fixed > 0: that many; otherwise max(1, floor(fraction x mesh size / largest depth rate)).
  /// @p largest_rate: the largest depth per cycle over the knife [m] (> 0).
  long cycles_for_update(long fixed, double fraction, double mesh_size, double largest_rate);
} // namespace abrade::coupling::lifetime
