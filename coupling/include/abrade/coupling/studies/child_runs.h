#pragma once
// Studies made of many `abrade run`s (sweep, concepts): child processes, as many at a time as
// asked, their output tables read back. Under mpirun the runs are spread over the ranks
// (StudyRanks), each rank starting its share on its own machine.
#include <abrade/common/csv_reader.h>
#include <abrade/dem/parallel.h>

#include <map>
#include <string>
#include <vector>

namespace abrade::coupling
{
  /// One `abrade run`: its output folder and the full shell command (output to DIR.log).
  struct ChildRun
  {
    std::string dir;
    std::string command;
  };

  /// `abrade run FILE --quiet --output DIR --set ...` for the executable @p abrade; the log
  /// goes to DIR.log.
  std::string run_command(const std::string &abrade, const std::string &file, const std::string &dir,
                          const std::vector<std::string> &sets);

  /// The entries a study sets on each of its cycles, whatever the file says: seed @p seed from
  /// the settled bed @p bed, one thread, no particle or snapshot output, Job = dem (a cycle,
  /// whatever the file's own job: a lifetime case's, say).
  std::vector<std::string> study_cycle_sets(int seed, const std::string &bed);
  /// InputError (exit 2) when one of @p sets ("Section/Key=value" or a key alone, given with
  /// @p option) names
  /// an entry that study_cycle_sets() sets, or with @p lives (the study's lifetime runs)
  /// lifetime_run_sets() (study_lives.h): it would be overridden without a word.
  void refuse_study_owned_sets(const std::vector<std::string> &sets, const std::string &option, bool lives);

  /// Runs @p runs, @p jobs at a time (0: one per core), with a progress line named @p what;
  /// throws RunError naming a failed run's log (the first in @p runs' order). Under mpirun
  /// (called on rank 0, the others serving: StudyRanks) the runs go round the ranks (run k of
  /// a batch to rank (f + k) mod ranks, f where the last batch ended), and each rank runs its
  /// share @p jobs at a time (0: the cores it is bound to, at most its machine's cores shared
  /// by the ranks on it; its runs inherit its binding). The runs are the same processes either
  /// way (each outside the MPI job), so a study's results do not depend on how many ranks ran
  /// it.
  void run_children(const std::vector<ChildRun> &runs, int jobs, const std::string &what);

  /// A study's ranks under mpirun (serial otherwise: one rank that leads). Rank 0 leads: it
  /// makes the study (its beds, tables and report), and each of its run_children() calls hands
  /// the other ranks their share of the runs. The other ranks serve() those calls until the
  /// study ends: end() with the exit code, or the leader's StudyRanks going out of scope (code
  /// 1 while an exception unwinds it). MPI must be started (fem::init_mpi_once) before.
  class StudyRanks
  {
  public:
    StudyRanks();
    ~StudyRanks();
    StudyRanks(const StudyRanks &) = delete;
    StudyRanks &operator=(const StudyRanks &) = delete;

    bool leads() const { return ranks.rank() == 0; }
    /// Rank 0: the study ended with exit code @p code; the others' serve() returns it.
    void end(int code);
    /// Ranks other than 0: runs their share of each of the leader's batches; returns the
    /// leader's exit code when it ends the study.
    int serve() const;

  private:
    dem::Parallel ranks;
    bool          ended = false;
  };

  using io::CsvTable;
  /// A table a child run wrote; RunError when the run left none.
  CsvTable read_csv_table(const std::string &path);
} // namespace abrade::coupling
