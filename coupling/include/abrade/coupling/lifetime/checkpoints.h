#pragma once
// The lifetime loop's checkpoints (`abrade run ... --resume`). After update u the loop writes
// knife-u.ckpt (the part's exact mesh and fields) and loop-u.txt (the loop's state), each
// aside and then renamed, the state last: a checkpoint is complete when its state file exists,
// whenever the process was killed. The newest two are kept, because under mpirun every rank
// writes its own and a kill can fall between two ranks' writes of one update: the ranks then
// resume together from the newest update that all of them completed (they are never more than
// one update apart: each update's DEM cycles need all of them).
#include <string>
#include <vector>

namespace abrade::dem
{
  class Parallel;
}

namespace abrade::coupling
{
  class LifetimeCheckpoints
  {
  public:
    /// Checkpoints in @p directory (which exists).
    explicit LifetimeCheckpoints(std::string directory);

    /// Where to resume: the newest update whose checkpoint every rank of @p ranks has (0: none
    /// on some rank, start afresh). This rank's newer checkpoints are removed (they will be
    /// redone). Throws InputError naming the file if one is missing (checkpoints edited).
    long resume_point(const dem::Parallel &ranks) const;

    /// Removes every checkpoint (a run that starts afresh: stale ones of an earlier run in the
    /// same directory must not be resumed from later).
    void clear() const;

    /// Where the part of update @p update is (0: the fresh part, which has no state file), in
    /// knife-u.ckpt (the name the checkpoints of every abrade have).
    std::string part_file(long update) const;
    /// Where the loop's state after update @p update is.
    std::string state_file(long update) const;
    /// Where to write them before commit().
    std::string part_file_aside(long update) const { return part_file(update) + ".tmp"; }
    std::string state_file_aside(long update) const { return state_file(update) + ".tmp"; }

    /// Renames the files written aside for @p update into place (the part, then the state)
    /// and removes the checkpoint two updates older.
    void commit(long update) const;

  private:
    std::string directory;
    /// The newest complete checkpoint on this process (-1: none).
    long newest() const;
    /// Every update that has a file here (ascending).
    std::vector<long> updates() const;
    /// Removes the checkpoint of @p update (what there is of it).
    void remove(long update) const;
  };
} // namespace abrade::coupling
