#pragma once
// How many operating cycles one lifetime update stands for. Fixed (Lifetime/Cycles per update),
// or adaptive: the largest wear depth increment of the update is a set fraction of the part's
// mesh size, so that the surface moves by a fraction of an element per update whatever the
// wear rate (Lifetime/Depth increment fraction). The rate is the wear depth per cycle after the
// surface filter, the same depth that the end-of-life criteria measure.
namespace abrade::coupling::lifetime
{
  /// @p fixed > 0: that many; otherwise max(1, floor(fraction x mesh size / largest depth rate)).
  /// @p largest_rate: the largest depth per cycle over the part [m] (> 0).
  long cycles_for_update(long fixed, double fraction, double mesh_size, double largest_rate);

  /// The loop's choice: adaptive updates sized from the previous update's largest rate
  /// @p previous_rate (0: none, the first update: from @p current_rate), not from the beds that
  /// then move the part (their own size would make the update's tonnes carry their scatter as
  /// 1 / rate and bias the life long by about c^2 / beds), and at most twice the increment at
  /// the @p current_rate (the mesh must follow).
  long cycles_for_update(long fixed, double fraction, double mesh_size, double previous_rate, double current_rate);
} // namespace abrade::coupling::lifetime
