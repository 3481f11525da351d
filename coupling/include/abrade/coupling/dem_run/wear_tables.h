#pragma once
// The wear outputs of a DEM run, from whatever wear laws its walls have (dem/wear_law.h):
//  - per-triangle fields of the ParaView snapshots: each volume field as a depth (volume /
//    triangle area, "archard_depth", also per phase "archard_depth_PHASE"), every other field
//    as it is recorded;
//  - walls/NAME_wear.csv, one row per phase and a "total" row: each field's sum over the
//    triangles, a volume field's largest depth ("archard_max_depth"), and the wall's centroid
//    path in the phase (path_length [m]); the same numbers in summary.json's "wear".
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/dem/output.h>
#include <abrade/dem/wear.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace abrade::coupling
{
  void add_wear_fields(dem::DemOutput &output, const std::shared_ptr<dem::WearRecorder> &wear, const DemCase &c);

  /// @p path_length: per phase, per wall the distance its centroid moved [m].
  void write_wear_table(JobContext &ctx, const dem::Simulation &sim, const dem::WearRecorder &wear, std::size_t wall,
                        const std::vector<Phase> &phases, const std::map<std::string, std::vector<double>> &path_length);

  /// "archard_volume" -> "archard_max_depth".
  std::string max_depth_column(const dem::WearField &field);
} // namespace abrade::coupling
