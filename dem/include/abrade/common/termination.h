#pragma once
// How a run ends on SIGTERM, SIGINT (Ctrl-C) and SIGHUP (a closed terminal): at once, with a line
// on stderr saying so, summary.json replaced by one whose status is "interrupted", and exit code
// 128 + the signal (143, 130, 129). Checkpoints are written aside and renamed into place, so the
// last complete one is intact whenever the signal comes, and `abrade run ... --resume` continues
// a lifetime run from it. The handler makes only async-signal-safe calls (open, write, rename,
// _exit): the summary's text is prepared while the run is set up. Child runs registered here are
// sent the same signal and waited for first.
#include <string>

namespace abrade::io
{
  /// Installs the handlers (again, after a library such as Gmsh installed its own).
  void install_termination_handlers();

  /// The summary.json that a signal leaves: @p path and its complete @p text.
  void prepare_interrupted_summary(const std::string &path, const std::string &text);

  /// Child runs (a sweep's, a comparison's): the process group @p pgid is sent the signal that
  /// ends this process, which then waits up to 10 s for it to end (and kills what is left), so
  /// that no child run goes on writing after its parent was stopped. At most 256 at once.
  void register_child_group(int pgid);
  void unregister_child_group(int pgid);

  /// Runs @p command with /bin/sh in a process group of its own, registered as above while it
  /// runs, and returns its exit status as std::system() does (-1 if it could not start). The
  /// command gets this process's environment without the MPI launcher's variables (OMPI_*,
  /// PMIX_*, PMI_*, ...; Open MPI settings given as OMPI_MCA_* go too): a child of an MPI rank
  /// (a study's run) is no part of its MPI job.
  int run_child_command(const std::string &command);
} // namespace abrade::io
