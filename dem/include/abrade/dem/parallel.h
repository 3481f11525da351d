#pragma once
// The processes one DEM simulation is spread over, and the few collective operations the
// engine needs (sums, maxima, sparse point-to-point exchanges, gathers). A simulation uses
// MPI_COMM_WORLD when the program runs under `mpirun -np N` with N > 1 and MPI has been
// initialised; otherwise it is serial and no MPI function is ever called (so the engine and its
// unit tests work without MPI_Init).
//
// Every collective here must be called by all ranks in the same order; the engine calls them at
// the same points of every step on every rank.
//
// split() cuts the ranks into groups that each run a simulation of their own (the beds of a
// lifetime update side by side: an ensemble); a group of one rank is serial, as a run of one
// process is, so that its results are those of that run.
#include <mpi.h>

#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <vector>

namespace abrade::dem
{
  class Parallel
  {
  public:
    /// Serial.
    Parallel() = default;
    /// MPI_COMM_WORLD if MPI is initialised (and not finalised) with more than one rank,
    /// otherwise serial.
    static Parallel world();
    /// The ranks of this one that give the same @p group, as a Parallel of their own (ranked
    /// as here; serial when alone). Its ranks_on_this_machine() stays this one's: the groups
    /// on a machine share its cores. Collective.
    Parallel split(int group) const;

    int  rank() const { return my_rank; }
    /// Ranks that share this machine (1 when serial; for a group of split(), the ranks of the
    /// Parallel it was split from). Collective when distributed.
    int  ranks_on_this_machine() const;
    int  size() const { return n_ranks; }
    bool distributed() const { return n_ranks > 1; }

    double sum(double v) const;
    double max(double v) const;
    double min(double v) const;
    long   sum(long v) const;
    /// Element-wise sums (in place).
    void sum(std::vector<double> &v) const;
    /// Element-wise maxima (in place).
    void max(std::vector<double> &v) const;
    /// The rank holding the largest @p v (ties: the lowest rank) and that value.
    std::pair<double, int> max_location(double v) const;
    /// @p text as held by rank @p root, on every rank.
    std::string broadcast(const std::string &text, int root) const;
    /// @p values as held by rank @p root, on every rank (in place).
    void broadcast(std::vector<double> &values, int root) const;

    /// Sends send[r] to rank r and returns what every rank sent here, concatenated in rank
    /// order; the counts received from each rank go to @p received (if given). Collective
    /// (all-to-all of the counts, then point-to-point messages to the ranks with data). With
    /// @p partners (a symmetric relation: r lists this rank if this rank lists r), the counts
    /// go only to and from the partners, and only they may have data to send (no all-to-all:
    /// the cost does not grow with the number of ranks).
    std::vector<double> exchange(const std::vector<std::vector<double>> &send, std::vector<int> *received = nullptr,
                                 const std::vector<int> *partners = nullptr) const;
    /// As exchange(), with the receive counts already known (a ghost update between two
    /// neighbour-list builds): only the ranks with non-zero counts talk to each other.
    void exchange_known(const std::vector<std::vector<double>> &send, const std::vector<int> &receive_counts,
                        std::vector<double> &received) const;
    /// Fails on every rank when any rank failed (an error found by one rank alone: the others
    /// would wait for it in their next collective for ever): rethrows, everywhere, the failure
    /// of the lowest rank that has one, as an InputError, a RunError or a std::runtime_error
    /// with its message. @p failure: this rank's (null: none). Collective.
    void fail_together(const std::exception_ptr &failure) const;

    /// Concatenation of every rank's @p local on rank 0 (empty elsewhere).
    std::vector<double> gather(const std::vector<double> &local) const;

    /// Seconds this object has spent in MPI calls (waiting for the other ranks included).
    double seconds_in_mpi() const { return mpi_seconds; }
    /// Bytes this object has sent to other ranks in exchanges.
    double bytes_sent() const { return sent_bytes; }

  private:
    /// MPI_Allreduce in place, timed; nothing when serial.
    void all_reduce(void *data, int count, MPI_Datatype type, MPI_Op op) const;

    MPI_Comm       comm    = MPI_COMM_NULL;
    int            my_rank = 0, n_ranks = 1;
    int            machine_ranks = 0;   ///< set by split(): the ranks on this machine; 0: count them
    std::shared_ptr<void> owned_comm;   ///< a communicator of split(), freed with its last copy
    mutable double mpi_seconds = 0, sent_bytes = 0;
    friend class MpiTimer;
  };

  /// Packs an integer into a double's bits (and back) for the exchange buffers.
  inline double pack_integer(std::int64_t v)
  {
    double d;
    static_assert(sizeof d == sizeof v);
    __builtin_memcpy(&d, &v, sizeof d);
    return d;
  }
  inline std::int64_t unpack_integer(double d)
  {
    std::int64_t v;
    __builtin_memcpy(&v, &d, sizeof v);
    return v;
  }
} // namespace abrade::dem
