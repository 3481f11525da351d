#pragma once
// The layout of a run's output directory, the same for every job:
//   DIR/summary.json      version, parameter hash, timings, key results
//   DIR/parameters.prm    the parameters actually used (all of them, defaults included)
//   DIR/log.txt           what was printed to the terminal
//   DIR/particles/        particle .vtp files + particles.pvd
//   DIR/walls/            wall .vtp files + <wall>.pvd, <wall>_forces.csv
//   DIR/knife/            FEM knife .vtu/.pvd/.stl (lifetime runs)
//   DIR/checkpoint/       restart data
#include <string>

namespace abrade::io
{
  class OutputDirectory
  {
  public:
    explicit OutputDirectory(std::string root);
    const std::string &root() const { return root_path; }
    /// Path of @p name inside the root directory.
    std::string file(const std::string &name) const { return root_path + "/" + name; }
    /// Creates (if needed) and returns the subdirectory @p name.
    std::string subdirectory(const std::string &name) const;

  private:
    std::string root_path;
  };
} // namespace abrade::io
