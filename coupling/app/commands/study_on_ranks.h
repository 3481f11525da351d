#pragma once
// A study command (sweep, concepts) under mpirun: rank 0 makes the study, the other ranks run
// their share of its runs (coupling/studies/child_runs.h, StudyRanks).
#include <functional>

namespace abrade::app
{
  /// Runs @p study on rank 0 and serves its runs on the other ranks under mpirun (MPI started
  /// here), or runs it alone; every rank returns the study's exit code (an error on rank 0 is
  /// thrown there and ends the others with its code: 2 bad input, 3 a failed run).
  int study_on_ranks(const std::function<int()> &study);
} // namespace abrade::app
