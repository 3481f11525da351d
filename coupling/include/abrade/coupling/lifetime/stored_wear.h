#pragma once
// Every update's wear as the loop received it, before the filter, kept with the surface it fell
// on (wear/update_NNNNN.wear in the run's directory; update 0: the pilot cycle), so that the
// loop can be run again without its wear source (Lifetime/Wear source = replay).
//
// What for: the footprint (Lifetime/Smoothing radius) acts after the DEM, on each cycle's wear.
// A second footprint, r', needs no DEM run of its own: the replay moves the part again with
// the stored wear filtered at r' (docs/field.md, "Candidate footprints without a DEM run each").
//
// How exact that is: a replay's update takes the stored update nearest in state, the one that
// began with the most volume worn off but not more than the replay's part has lost (the worn
// volume does not depend on the footprint; at another W it is reached at other tonnes). The
// stored wear fell on the stored run's surface; at another footprint the part has another
// shape after the first update, and the replay carries the stored wear onto it (a wear volume
// per unit area, interpolated at each vertex's closest point on the stored surface, the total
// kept). What the replay leaves out is how the DEM's wear itself would have changed with that
// shape (the geometry feedback): exact in the first update and in a replay at the stored
// footprint (the surfaces are the same: the stored volumes are used as they are, bit for bit),
// an approximation after it. On the knife-bed (stored at 27.5 mm, replayed at 13.75 mm and
// W 3e-14 against the DEM run there) the edge recession lags the DEM's by 10-13 % at 1.5-2 Mt
// and the life comes out 20 % long (docs/field.md). A stored update's beds can serve more than
// one update of a replay: its life's interval then counts them as fresh beds (too narrow; warned).

#include <abrade/coupling/lifetime/wear_source.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace abrade::coupling::lifetime
{
  /// One update's (or the pilot cycle's) unfiltered wear, with what a replay needs to use it.
  struct StoredWear
  {
    long                     update       = 0; ///< 0: the pilot cycle
    double                   tonnes_start = 0; ///< the tonnes handled before it
    std::vector<int>         bed_seeds;        ///< the beds of wear.seed_volume, in order
    CycleWear                wear;             ///< per-vertex volumes per cycle of @p surface
    fem::SolidSurface        surface;          ///< the part's surface it fell on (vertices, triangles, ids)
    double                   wear_coefficient = 0;
    bool                     removes_volume   = true;
    double                   coarse_graining_factor = 1; ///< of the particles at the part (DemCase::factor_at_tools)
    std::vector<std::string> phases;
  };

  /// Writes @p stored to @p path (a StateFile: numbers read back bit for bit, checksummed).
  void write_stored_wear(const std::string &path, const StoredWear &stored);

  /// Reads a file written by write_stored_wear (InputError naming it when it is not one).
  StoredWear read_stored_wear(const std::string &path);

  /// The file name of update @p update's stored wear in a run's directory (wear/update_00001.wear).
  std::string stored_wear_file(const std::string &run_directory, long update);

  /// Wear volumes per vertex of @p from carried onto @p to: as a volume per unit area (a third
  /// of each vertex's triangles), interpolated at each vertex of @p to from its closest point
  /// on @p from, times its own area; then scaled to the same total (the DEM's worn volume is
  /// kept). When @p to is @p from (the same vertices and triangles), @p volume itself.
  std::vector<double> carry_wear_volume(const fem::SolidSurface &from, const std::vector<double> &volume,
                                        const fem::SolidSurface &to);

  /// The same for several fields (a cycle's beds), each vertex's closest point found once.
  std::vector<std::vector<double>> carry_wear_volumes(const fem::SolidSurface &from,
                                                      const std::vector<std::vector<double>> &volumes,
                                                      const fem::SolidSurface &to);

  /// The same update of several runs of one case on one surface, one or more beds each (e.g.
  /// one-update runs of fixed cycles, a bed per run, made at different times or on different
  /// machines), as one run of all their beds stores it: the beds and their volumes in the
  /// runs' order, the phases' volumes the beds' mean (added bed by bed, each over the beds'
  /// number, as the DEM wear source adds them: one-bed runs of a part with one knife joined are
  /// the bits of one run of their beds; a grab's two knives are averaged first, so its joined
  /// phases differ from the DEM's at round-off), the largest particle the last bed's (as the
  /// DEM keeps it). With @p tonnes_from_payload (a grab: Lifetime/Tonnes per cycle 0) the
  /// tonnes per cycle are the beds' mean; otherwise they must be the same. InputError naming the
  /// run (@p names, in the order of @p parts) whose update, surface, W, law, phases,
  /// coarse-graining factor, tonnes before it or tonnes per cycle is not the first's, or whose
  /// bed another run has too (one bed twice is not two).
  StoredWear join_stored_wear(const std::vector<StoredWear> &parts, const std::vector<std::string> &names,
                              bool tonnes_from_payload = false);

  /// Lifetime/Wear source = replay: the wear stored by the runs in @p run_directories (one run, or
  /// several joined update by update with join_stored_wear as long as their parts have the same
  /// surface: after the first update each run's part has worn its own way, and the joined run ends
  /// there, said once in the first cycle's CycleWear::notes). A cycle asked on beds @p bed_seeds on
  /// @p surface takes the stored update (or pilot) of these beds (in any order) on this very
  /// surface (the same run again), else the stored update that began with the most volume worn off
  /// but not more than @p surface has lost (the enclosed volume below the first stored surface's),
  /// its volumes carried onto @p surface (carry_wear_volume), its beds in CycleWear::bed_seeds.
  /// Said once each in CycleWear::warnings: a part that has lost more than the stored run did by
  /// its end (its last update's wear is used), a stored update serving a second update (the pilot
  /// cycle, on @p seeds' pilot beds, is not an update). @p design: this run's unworn surface, which
  /// must be the stored run's (the same extent within a tenth of @p tolerance, the same volume
  /// within 0.1 %), and @p coarse_graining_factor the stored run's, else InputError; InputError
  /// also when the directory holds no stored wear (a run of an abrade before it kept its wear).
  /// @p tonnes_from_payload: the tonnes per cycle are a grab's payload (join_stored_wear).
  std::unique_ptr<WearSource> make_replayed_wear_source(const std::vector<std::string> &run_directories,
                                                        const fem::SolidSurface &design, double tolerance,
                                                        double coarse_graining_factor, bool tonnes_from_payload,
                                                        const std::vector<int> &seeds);
} // namespace abrade::coupling::lifetime
