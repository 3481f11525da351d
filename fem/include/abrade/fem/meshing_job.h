#pragma once
// Gmsh, contained (every Gmsh session on a user's file: volume meshes, a CAD wall's surface,
// `abrade convert`). Gmsh can take the whole process down: an exception thrown inside one of its
// OpenMP regions calls std::terminate (a worn surface whose faces became slivers did that at
// 9 mm of uniform wear on the 30 mm knife), and a surface with a repeated facet sends METIS,
// called from its surface classification, into a loop that ignores SIGTERM. So every volume
// mesh Gmsh makes of a user's part or of a worn surface is made by a child process, the
// `abrade-mesher` executable built beside `abrade`: the parent waits for it with a time limit
// and reads the .msh file it wrote. A crash, a hang or a signal to the parent then costs the
// child, never the run: a crash or a time-out becomes an InputError naming the file, which the
// caller can answer by trying another way (PartModel's remesh does).
//
//   MeshingJob job{"part.stl", "part.msh", 0.02};
//   std::vector<std::string> notes = run_meshing_job(job);   // throws InputError
//
// The child has the parent's environment less MPI's launch variables (it is no MPI rank), its
// own standard output and error in OUTPUT.log, and dies with its parent (PR_SET_PDEATHSIG):
// SIGTERM or Ctrl-C to abrade ends it at once, also inside Gmsh or METIS. Where the mesher
// executable cannot be found (ABRADE_MESHER names it explicitly), the job runs in this process
// and a note says so.
#include <abrade/fem/solid_file.h>

#include <string>
#include <vector>

namespace abrade::fem
{
  struct MeshingJob
  {
    std::string input;  ///< a CAD file (.step/.stp/.iges/.igs) or a closed STL surface
    std::string output; ///< the tetrahedral mesh, Gmsh .msh 2.2 (surface numbers as physical groups)
    double      mesh_size = 0; ///< [m] (STL: in the file's unit before the scale)
    /// HXT and Gmsh's optimisers: a second, harder try after a poor first mesh.
    bool again = false;
    /// Fill the STL's own triangles as they are (no surface remeshing).
    bool keep_triangles = false;
    SolidFileSettings settings; ///< scale, size and cell limits, the solid of a CAD file
    /// [s] How long the mesher may take; 0: ABRADE_MESHER_TIME_LIMIT, or 1800 s.
    double time_limit = 0;
    /// What the child makes of the input: "volume" (the tetrahedral mesh above), "surface" (a
    /// CAD file's surfaces as triangles of size mesh_size, written as a surface file:
    /// write_surface_file), "step" (the input's CAD model as STEP: abrade convert) or "msh" (a
    /// user's .msh file read and written again as .msh 2.2, its face names in the notes).
    std::string kind = "volume";
  };

  /// Runs @p job in the mesher process and returns the notes of reading the part (the solid
  /// taken, slivers removed, ...). Throws InputError naming job.input when Gmsh cannot mesh it,
  /// crashes or runs past job.time_limit.
  std::vector<std::string> run_meshing_job(const MeshingJob &job);

  /// The job in this process (what the mesher executable does; solid_file.cc).
  std::vector<std::string> run_meshing_job_here(const MeshingJob &job);

  /// The mesher executable's main: `abrade-mesher INPUT OUTPUT H AGAIN KEEP SCALE MAX_EXTENT
  /// MIN_EXTENT MAX_VOLUME MAX_CELLS SOLID [KIND]`. Exit 0: OUTPUT written, the notes in
  /// OUTPUT.notes; exit 2: the InputError's message in OUTPUT.error.
  int meshing_job_main(int argc, char **argv);
} // namespace abrade::fem
