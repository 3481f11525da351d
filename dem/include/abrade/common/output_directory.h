#pragma once
// The layout of a run's output directory, the same for every job:
//   DIR/summary.json      version, parameter hash, timings, key results
//   DIR/parameters.prm    the parameters actually used (all of them, defaults included)
//   DIR/log.txt           what was printed to the terminal
//   DIR/particles/        particle .vtp files + particles.pvd
//   DIR/walls/            wall .vtp files + <wall>.pvd, <wall>_forces.csv
//   DIR/part/             the part: its solid mesh per update (part.pvd, part_NNNNN.vtu),
//                         worn surface (part_NNNNN.stl), profiles and sections; a run
//                         of an abrade before the part was called so has DIR/knife/knife*
//                         instead: read as it is, and kept when resumed (part_folder)
//   DIR/checkpoint/       restart data
//   DIR/.rank-N/          under mpirun, what rank N > 0 writes (each rank runs the same job on
//                         globally reduced data; rank 0's files are the results)
//
// A directory belongs to one run: claim() takes DIR/.abrade-lock (an flock(), which the kernel
// releases when the process ends, also by SIGKILL), so a second run on the same directory is
// refused with the first one's pid instead of mixing both runs' files; and it refuses a
// directory holding symbolic links, which the run's writes would follow out of it.
#include <memory>
#include <string>

namespace abrade::io
{
  /// The folder of run directory @p run that holds the part's files, which is also their
  /// stem ("part": DIR/part/part.pvd): "knife" when the run has DIR/knife and no DIR/part (a
  /// run of an abrade from before subsection Knife was named Part: read as it is, and resumed
  /// in its own layout; a fresh
  /// run in that directory writes part/, OutputDirectory::part_folder).
  std::string part_folder(const std::string &run);

  class OutputDirectory
  {
  public:
    /// @p shared: the directory that inputs named relative to the output (a settled bed) are
    /// read from and written to, if not @p root itself (a rank > 0 writes into its own root).
    explicit OutputDirectory(std::string root, std::string shared = "");
    const std::string &root() const { return root_path; }
    /// Path of @p name inside the root directory.
    std::string file(const std::string &name) const { return root_path + "/" + name; }
    /// Path of @p name inside the shared directory (the root, except on MPI ranks > 0).
    std::string shared_file(const std::string &name) const { return shared_path + "/" + name; }
    /// Creates (if needed) and returns the subdirectory @p name.
    std::string subdirectory(const std::string &name) const;
    /// The folder a run writes the part's files into: "part", also in a directory an earlier
    /// abrade wrote (its knife/ left as it was); a @p resumed run goes on in the folder it
    /// began in (io::part_folder: an earlier abrade's run resumed keeps its knife/).
    std::string part_folder(bool resumed = false) const { return resumed ? io::part_folder(root_path) : "part"; }
    /// Makes the directory this process's own until it ends (see above); throws InputError
    /// naming the directory when another process holds it or a symbolic link is inside it. A
    /// second claim of a directory this process holds already does nothing.
    void claim();

  private:
    std::string           root_path, shared_path;
    std::shared_ptr<void> lock; ///< the open lock file while claimed
  };
} // namespace abrade::io
