#pragma once
// The private state of a Simulation (simulation.cc, neighbour_lists.cc, pair_forces.cc,
// wall_forces.cc, domain_exchange.cc):
// neighbour lists, contact histories, the cell grid, the domain decomposition and its ghost
// layer, and per-thread scratch space: everything the time loop needs that is not particle
// state.
#include <abrade/dem/decomposition.h>
#include <abrade/dem/parallel.h>
#include <abrade/dem/simulation.h>
#include <abrade/dem/thread_governor.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace abrade::dem
{
  /// The contiguous share of @p n items of thread @p t of @p team (static schedule).
  inline std::pair<std::size_t, std::size_t> share(std::size_t n, int t, int team)
  {
    return {n * t / team, n * (t + 1) / team};
  }

  struct Simulation::Impl
  {
    /// The shares each step's work is cut into (Settings::threads): they, not the number of
    /// threads working on them, fix the arithmetic (partitions, buffers, summation order).
    int n_threads = 1;
    /// How many threads work on the shares now (thread_governor.h); a share s is worked by
    /// thread s % team.
    /// (Shared with the simulations before and after this one when Settings::governor is set.)
    std::shared_ptr<ThreadGovernor> governor;
    int            team() const { return governor->team(); }

    // the ranks and who owns which part of space
    Parallel      parallel;
    Decomposition decomposition;
    bool          balanced = false; ///< decomposition computed at least once

    // particle-particle half list (CSR, rows: owned particles; columns: owned particles and
    // ghosts) with the tangential history of each pair
    std::vector<std::size_t> offsets;
    std::vector<int>         neighbours;
    std::vector<int>         row_of; // per pair: its row (the pair scan streams over pairs)
    /// Doubles of history per contact (ContactLaw::history: the tangential spring's 3, and the
    /// rolling spring's 3 with the epsd model), for pairs and walls alike.
    int                      history = 3;
    std::vector<double>      shear; // history per pair, for the row particle relative to the column
    /// per pair: in contact at the last step (0: its shear history is zero)
    std::vector<unsigned char> touching;
    int one_material = -1; ///< the material of all owned particles and ghosts, if they share one
    std::vector<std::vector<int>> thread_lists; // scratch of the list build, one per thread

    // Pair histories carried across a rebuild (and a migration), keyed by the partner's id:
    // particle a's row holds (id of b, shear of a relative to b), for every pair with history.
    std::vector<std::size_t>  carried_offsets;
    std::vector<std::int64_t> carried_partner;
    std::vector<double>       carried_shear;
    std::vector<std::int64_t> carried_owner; // id of each row's particle (rows of others are ignored)
    /// Pair histories carried (the four arrays above), being assembled.
    struct CarriedHistories
    {
      std::vector<std::size_t>  offsets;
      std::vector<std::int64_t> partner;
      std::vector<double>       shear;
      std::vector<std::int64_t> owner;
    };

    // the steps of a migration (Simulation::rebalance_and_migrate, domain_exchange.cc)
    /// Appends owned particle @p i of @p P to @p b: its record, its wall histories, its carried
    /// pair histories.
    void pack_migrant(const ParticleStore &P, std::size_t i, std::vector<double> &b) const;
    /// The particles of @p send (per rank) sent, the ones for this rank received: among the
    /// neighbouring boxes only (@p nearby) when the boxes were not @p cut and no particle went
    /// farther than to a neighbour (within @p skin), else all to all. Collective.
    std::vector<double> exchange_migrants(const std::vector<std::vector<double>> &send, bool cut, double skin,
                                          bool &nearby) const;
    /// The carried pair histories of the particles that stay (@p stay: their rows, in order).
    CarriedHistories carried_histories_of(const ParticleStore &P, const std::vector<std::size_t> &stay) const;
    /// The particles received (@p in, as pack_migrant packed them) appended to @p P, their wall
    /// histories to this one's and their pair histories to @p carried; returns their number.
    std::size_t unpack_migrants(ParticleStore &P, const std::vector<double> &in, CarriedHistories &carried);

    /// Whether carried row @p row holds the histories of the particle with id @p id.
    bool carries(std::size_t row, std::int64_t id) const
    {
      return row < carried_owner.size() && carried_owner[row] == id;
    }

    // particle-wall candidates (CSR) and up to K contact histories per particle
    static constexpr int        K = 4;
    std::vector<std::size_t>    wall_offsets;
    std::vector<int>            candidate_wall, candidate_triangle;
    std::vector<int>            wall_particles; // owned particles with wall candidates
    std::vector<int>            hist_wall, hist_tri; // K per particle, -1: free slot
    std::vector<double>         hist_shear;          // history x K per particle
    std::vector<unsigned char>  hist_used;           // K per particle
    /// Wall histories for @p n particles (new ones free).
    void resize_wall_histories(std::size_t n)
    {
      hist_wall.resize(K * n, -1), hist_tri.resize(K * n, -1);
      hist_shear.resize(std::size_t(history) * K * n, 0.0);
      hist_used.resize(K * n, 0);
    }

    // per-share ranges of the pair loop, balanced by pair count (deterministic, unlike a
    // dynamic schedule)
    std::vector<std::size_t> thread_begin;

    // positions at the last build
    std::vector<double> x0, y0, z0;
    double              max_displacement = 0;

    // cell grid: owned particles sorted by cell (cell_start), ghosts after them, also sorted
    // by cell (ghost_cell_start, absolute indices)
    double              cell = 1;
    Vec3                lo;
    long                nx = 1, ny = 1, nz = 1;
    std::vector<int>    cell_start, ghost_cell_start;
    /// The cell of a position (outside the grid: the nearest cell).
    long cell_of(double x, double y, double z) const
    {
      const long i = std::clamp(long((x - lo[0]) / cell), 0L, nx - 1);
      const long j = std::clamp(long((y - lo[1]) / cell), 0L, ny - 1);
      const long k = std::clamp(long((z - lo[2]) / cell), 0L, nz - 1);
      return (k * ny + j) * nx + i;
    }
    /// Counting sort by cell of particles first .. first + count - 1 of @p P (those with
    /// keep[k] set, if @p keep is given): @p start gets each cell's first position in the
    /// sorted order; returns the order (indices relative to @p first).
    std::vector<std::size_t> sort_by_cell(const ParticleStore &P, std::size_t first, std::size_t count,
                                          const std::vector<char> *keep, std::vector<int> &start) const;

    // the steps of Simulation::build_neighbour_lists() (neighbour_lists.cc)
    /// The cell grid (cell, lo, nx, ny, nz) over the particles of @p P inside the domain
    /// @p domain_min .. @p domain_max (@p keep: 0 for the others, lost), under MPI with a margin
    /// of one interaction range for the ghosts. Returns the largest radius over all ranks;
    /// @p cutoff: the interaction range, twice that plus @p skin.
    double make_grid(const ParticleStore &P, const Vec3 &domain_min, const Vec3 &domain_max, double skin,
                     std::vector<char> &keep, double &cutoff);
    /// The half neighbour list (offsets, neighbours, row_of) of the owned particles of @p P,
    /// sorted by cell, against the owned ones and the ghosts: the pairs within their radii
    /// plus @p skin. Each share lists a block of rows into its own buffer, then copied in place.
    void list_pairs(const ParticleStore &P, double skin);
    /// The candidates of row @p i (particle positions @p X, @p Y, @p Z) in the list: the
    /// particles after it in its own cell and the next along x, three cells of the next row,
    /// three rows of three cells in the layer above (contiguous ranges: the particles are sorted
    /// by cell, cells numbered x fastest), and with @p any_ghosts the ghosts of all 27 cells;
    /// their begin/end pairs into @p range; returns their number.
    int candidate_ranges(std::size_t i, const double *X, const double *Y, const double *Z, bool any_ghosts,
                         int (&range)[2 * 14]) const;
    /// Each listed pair's tangential history: zero, or the one carried across the rebuild when
    /// the pair had one (@p order: the row each owned particle had before the cell sort).
    void pick_up_pair_histories(const ParticleStore &P, const std::vector<std::size_t> &order);
    /// The pair loop's shares (thread_begin): equal shares of pairs plus a constant per particle.
    void balance_pair_shares(std::size_t n);
    /// The wall candidates (wall_offsets, candidate_wall, candidate_triangle): the triangles of
    /// @p walls within each owned particle's radius plus @p skin (@p r_max: the largest radius,
    /// which bounds the cells searched), and the particles that have any (wall_particles); the
    /// others' wall histories are freed.
    void find_wall_candidates(const ParticleStore &P, const std::vector<Wall> &walls, double r_max, double skin);

    // ghost layer: owned particles sent to each rank, the values received from each rank per
    // update, and where each received ghost record went after the cell sort
    static constexpr int             ghost_state = 9; // x y z vx vy vz wx wy wz
    std::vector<std::vector<int>>    ghost_send;
    std::vector<int>                 ghost_receive_counts;
    std::vector<std::size_t>         ghost_slot; // ghost k (index size() + k) <- received record ghost_slot[k]
    std::vector<std::vector<double>> send_buffer;
    std::vector<double>              receive_buffer;

    // per-share force buffers (share 0 writes to the particle arrays), wall loads and wall
    // contacts (ContactLog::per_thread holds one list per share)
    std::vector<std::vector<double>> buffers;    // 7 n_local per share >= 1 (force, torque, rolling)
    /// The particles a share's pairs touch: its rows and the partners after them (the list is
    /// a forward half list of particles sorted by cell, so a share of about n / shares rows
    /// reaches a layer of cells beyond them): owned ones and ghosts, each [begin, end). A share's
    /// buffer is zeroed and added back over these only: the rest of it is never read (it may
    /// hold an earlier list's sums, at other offsets: the buffers are resized, not cleared).
    struct ShareSpan
    {
      std::size_t owned_begin = 0, owned_end = 0, ghost_begin = 0, ghost_end = 0;
    };
    std::vector<ShareSpan> share_spans;
    std::vector<std::vector<double>> wall_loads; // 6 per wall per share
    ContactLog                       log;

    // problems found during a step
    double worst_overlap_ratio = 0;
    long   worst_overlap_i = -1, worst_overlap_j = -1;
    double worst_overlap_all  = 0; ///< the largest over all ranks
    int    worst_overlap_rank = 0; ///< and the rank that has it
    bool   force_rebuild = true;
  };
} // namespace abrade::dem
