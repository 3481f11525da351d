// The processes one DEM simulation is spread over, and its collective operations (parallel.h).
#include <abrade/common/error.h>
#include <abrade/dem/parallel.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace abrade::dem
{
  /// Adds the time of its scope to a Parallel's seconds_in_mpi().
  class MpiTimer
  {
  public:
    explicit MpiTimer(const Parallel &p) : p(p), start(p.distributed() ? MPI_Wtime() : 0) {}
    ~MpiTimer()
    {
      if (p.distributed())
        p.mpi_seconds += MPI_Wtime() - start;
    }

  private:
    const Parallel &p;
    double          start;
  };

  Parallel Parallel::world()
  {
    Parallel p;
    int      initialised = 0, finalised = 0;
    MPI_Initialized(&initialised);
    MPI_Finalized(&finalised);
    if (!initialised || finalised)
      return p;
    int size = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (size == 1)
      return p;
    p.comm    = MPI_COMM_WORLD;
    p.n_ranks = size;
    MPI_Comm_rank(MPI_COMM_WORLD, &p.my_rank);
    return p;
  }

  Parallel Parallel::split(int group) const
  {
    Parallel part;
    part.machine_ranks = ranks_on_this_machine();
    if (!distributed())
      return part;
    MPI_Comm sub;
    MPI_Comm_split(comm, group, my_rank, &sub);
    int size = 1;
    MPI_Comm_size(sub, &size);
    if (size == 1)
      {
        MPI_Comm_free(&sub);
        return part;
      }
    part.comm    = sub;
    part.n_ranks = size;
    MPI_Comm_rank(sub, &part.my_rank);
    part.owned_comm = std::shared_ptr<void>(new MPI_Comm(sub), [](void *c) {
      int finalised = 0;
      MPI_Finalized(&finalised);
      if (!finalised)
        MPI_Comm_free(static_cast<MPI_Comm *>(c));
      delete static_cast<MPI_Comm *>(c);
    });
    return part;
  }

  int Parallel::ranks_on_this_machine() const
  {
    if (machine_ranks > 0)
      return machine_ranks;
    if (!distributed())
      return 1;
    MPI_Comm local;
    MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, my_rank, MPI_INFO_NULL, &local);
    int n = 1;
    MPI_Comm_size(local, &n);
    MPI_Comm_free(&local);
    return n;
  }

  void Parallel::all_reduce(void *data, int count, MPI_Datatype type, MPI_Op op) const
  {
    const MpiTimer t(*this);
    if (distributed() && count > 0)
      MPI_Allreduce(MPI_IN_PLACE, data, count, type, op, comm);
  }

  double Parallel::sum(double v) const { all_reduce(&v, 1, MPI_DOUBLE, MPI_SUM); return v; }
  double Parallel::max(double v) const { all_reduce(&v, 1, MPI_DOUBLE, MPI_MAX); return v; }
  double Parallel::min(double v) const { all_reduce(&v, 1, MPI_DOUBLE, MPI_MIN); return v; }
  long   Parallel::sum(long v) const { all_reduce(&v, 1, MPI_LONG, MPI_SUM); return v; }
  void   Parallel::sum(std::vector<double> &v) const { all_reduce(v.data(), int(v.size()), MPI_DOUBLE, MPI_SUM); }
  void   Parallel::max(std::vector<double> &v) const { all_reduce(v.data(), int(v.size()), MPI_DOUBLE, MPI_MAX); }

  std::pair<double, int> Parallel::max_location(double v) const
  {
    const MpiTimer t(*this);
    if (!distributed())
      return {v, 0};
    struct
    {
      double value;
      int    rank;
    } in{v, my_rank}, out{};
    MPI_Allreduce(&in, &out, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm);
    return {out.value, out.rank};
  }

  std::string Parallel::broadcast(const std::string &text, int root) const
  {
    const MpiTimer t(*this);
    if (!distributed())
      return text;
    int n = static_cast<int>(text.size());
    MPI_Bcast(&n, 1, MPI_INT, root, comm);
    std::string s = my_rank == root ? text : std::string(n, ' ');
    MPI_Bcast(s.data(), n, MPI_CHAR, root, comm);
    return s;
  }

  void Parallel::broadcast(std::vector<double> &values, int root) const
  {
    const MpiTimer t(*this);
    if (!distributed())
      return;
    long n = static_cast<long>(values.size());
    MPI_Bcast(&n, 1, MPI_LONG, root, comm);
    values.resize(n);
    MPI_Bcast(values.data(), static_cast<int>(n), MPI_DOUBLE, root, comm);
  }

  void Parallel::exchange_known(const std::vector<std::vector<double>> &send, const std::vector<int> &counts,
                                std::vector<double> &received) const
  {
    const MpiTimer t(*this);
    received.resize(std::accumulate(counts.begin(), counts.end(), std::size_t(0)));
    if (!distributed())
      {
        std::copy(send[0].begin(), send[0].end(), received.begin());
        return;
      }
    std::vector<MPI_Request> requests;
    requests.reserve(2 * n_ranks);
    std::size_t offset = 0;
    for (int r = 0; r < n_ranks; ++r)
      {
        if (counts[r] > 0)
          {
            if (r == my_rank)
              std::copy(send[r].begin(), send[r].end(), received.begin() + offset);
            else
              {
                requests.emplace_back();
                MPI_Irecv(received.data() + offset, counts[r], MPI_DOUBLE, r, 17, comm, &requests.back());
              }
          }
        offset += counts[r];
      }
    for (int r = 0; r < n_ranks; ++r)
      if (r != my_rank && !send[r].empty())
        {
          sent_bytes += sizeof(double) * send[r].size();
          requests.emplace_back();
          MPI_Isend(send[r].data(), static_cast<int>(send[r].size()), MPI_DOUBLE, r, 17, comm, &requests.back());
        }
    MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  }

  std::vector<double> Parallel::exchange(const std::vector<std::vector<double>> &send, std::vector<int> *received,
                                        const std::vector<int> *partners) const
  {
    std::vector<int> out(n_ranks), in(n_ranks, 0);
    for (int r = 0; r < n_ranks; ++r)
      out[r] = static_cast<int>(send[r].size());
    in[my_rank] = out[my_rank];
    if (distributed())
      {
        const MpiTimer t(*this);
        if (!partners)
          MPI_Alltoall(out.data(), 1, MPI_INT, in.data(), 1, MPI_INT, comm);
        else
          {
            std::vector<MPI_Request> requests(2 * partners->size());
            for (std::size_t k = 0; k < partners->size(); ++k)
              {
                const int r = (*partners)[k];
                MPI_Irecv(&in[r], 1, MPI_INT, r, 18, comm, &requests[2 * k]);
                MPI_Isend(&out[r], 1, MPI_INT, r, 18, comm, &requests[2 * k + 1]);
              }
            MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
          }
      }
    std::vector<double> data;
    exchange_known(send, in, data);
    if (received)
      *received = in;
    return data;
  }

  void Parallel::fail_together(const std::exception_ptr &failure) const
  {
    if (!distributed())
      {
        if (failure)
          std::rethrow_exception(failure);
        return;
      }
    enum Kind
    {
      none,
      input,
      run,
      other
    };
    Kind        kind = none;
    std::string message;
    if (failure)
      try
        {
          std::rethrow_exception(failure);
        }
      catch (const InputError &e)
        {
          kind = input, message = e.what();
        }
      catch (const RunError &e)
        {
          kind = run, message = e.what();
        }
      catch (const std::exception &e)
        {
          kind = other, message = e.what();
        }
      catch (...)
        {
          kind = other, message = "an exception of unknown type";
        }
    // the lowest failing rank: the largest n_ranks - rank among the failing ones
    const auto [flag, first] = max_location(kind != none ? double(n_ranks - my_rank) : 0.0);
    if (!(flag > 0))
      return;
    message = broadcast(message, first);
    std::vector<double> k{double(kind)};
    broadcast(k, first);
    switch (Kind(int(k[0])))
      {
        case input:
          throw InputError("", message);
        case run:
          throw RunError(message);
        default:
          throw std::runtime_error(message);
      }
  }

  std::vector<double> Parallel::gather(const std::vector<double> &local) const
  {
    const MpiTimer t(*this);
    if (!distributed())
      return local;
    int              n = static_cast<int>(local.size());
    std::vector<int> counts(n_ranks), offsets(n_ranks + 1, 0);
    MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
    for (int r = 0; r < n_ranks; ++r)
      offsets[r + 1] = offsets[r] + counts[r];
    std::vector<double> all(my_rank == 0 ? offsets[n_ranks] : 0);
    MPI_Gatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0, comm);
    return all;
  }
} // namespace abrade::dem
