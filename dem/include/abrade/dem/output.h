#pragma once
// DEM output for ParaView and for analysis:
//   particles/particles_NNNNN.vtp + particles.pvd  (radius, velocity, force, id)
//   walls/<wall>_NNNNN.vtp + <wall>.pvd             (per-triangle impulses and hook fields)
//   walls/<wall>_forces.csv                         (time, phase, force, torque, position)
#include <abrade/common/csv_writer.h>
#include <abrade/common/vtk_output.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace abrade::dem
{
  class Simulation;

  class DemOutput
  {
  public:
    /// @p directory: the run's output root; files go to its particles/ and walls/ folders.
    DemOutput(const std::string &directory, const Simulation &sim, bool write_particles = true);

    /// A per-triangle field that the wall .vtp files carry (wear depth from a wear law, say).
    using TriangleField = std::function<std::vector<double>(const Simulation &, std::size_t wall)>;
    void add_triangle_field(const std::string &name, TriangleField f);

    /// Writes the particle and wall snapshots (ParaView time series).
    void write_snapshot(const Simulation &sim);
    /// Appends one row per wall to the force CSV files.
    void write_forces(const Simulation &sim);
    /// Closes the force CSV files (RunError naming one whose write failed).
    void close();

  private:
    std::string                                       particle_dir, wall_dir;
    bool                                              particles_on;
    int                                               counter = 0;
    io::PvdSeries                                     particle_series;
    std::vector<io::PvdSeries>                        wall_series;
    std::vector<std::unique_ptr<io::CsvWriter>>       force_csv;
    std::vector<std::pair<std::string, TriangleField>> fields;
  };
} // namespace abrade::dem
