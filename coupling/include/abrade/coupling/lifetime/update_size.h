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

  /// @p n cycles, or fewer: the update that would cross a limit @p gap ahead [m] ends @p past
  /// beyond it at the fastest rate @p largest_rate [m per cycle] (so the life is interpolated
  /// within a short step, and a limit is not jumped over); at least one cycle. A gap <= 0 or a
  /// rate <= 0 leaves @p n.
  long cycles_to_pass(long n, double gap, double past, double largest_rate);
} // namespace abrade::coupling::lifetime
