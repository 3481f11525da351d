// Studies made of many `abrade run` child processes (sweep, concepts): starting them side by
// side, waiting, and collecting what each wrote (child_runs.h).
#include <abrade/common/error.h>
#include <abrade/common/external.h>
#include <abrade/common/progress.h>
#include <abrade/common/termination.h>
#include <abrade/coupling/parameters/parameter_text.h>
#include <abrade/coupling/studies/child_runs.h>
#include <abrade/dem/parallel.h>
#include <abrade/coupling/studies/study_lives.h>

#include <algorithm>
#include <atomic>
#include <sched.h>
#include <system_error>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <thread>

namespace abrade::coupling
{
  std::string run_command(const std::string &abrade, const std::string &file, const std::string &dir,
                          const std::vector<std::string> &sets)
  {
    using io::shell_quote;
    std::string c = shell_quote(abrade) + " run " + shell_quote(file) + " --quiet --output " + shell_quote(dir);
    for (const auto &s : sets)
      c += " --set " + shell_quote(s);
    return c + " > " + shell_quote(dir + ".log") + " 2>&1";
  }

  std::vector<std::string> study_cycle_sets(int seed, const std::string &bed)
  {
    return {"Particles/Generation/Seed=" + std::to_string(seed),
            "Particles/Settling/Bed file=" + bed,
            "Simulation/Threads=1",
            "Output/Write particles=false",
            "Output/Snapshot interval=0",
            "Job=dem"};
  }

  void refuse_study_owned_sets(const std::vector<std::string> &sets, const std::string &option, bool lives)
  {
    std::vector<std::string> owned = study_cycle_sets(0, "");
    if (lives)
      for (const std::string &set : lifetime_run_sets({}, 1, {1}))
        owned.push_back(set);
    for (const std::string &set : sets)
      {
        const std::string key = entry_as_now(set);
        for (const std::string &o : owned)
          if (key == entry_as_now(o))
            throw InputError("command line", option + " " + key + ": the study sets this entry on each of its " +
                                               (lives ? "lifetime runs" : "cycles") +
                                               " itself (the seeds come from --seeds, the updates from --lifetime-updates)");
      }
  }

  namespace
  {
    constexpr std::size_t none = std::numeric_limits<std::size_t>::max();

    struct Share
    {
      std::size_t failed = none; ///< the lowest failed run's index (none: none failed)
      std::size_t ran    = 0;    ///< the runs this rank started
    };

    /// Runs at a time when not told: the cores this process may run on (its MPI rank's
    /// binding, which its child processes inherit; a container's CPU set), at most this
    /// machine's cores shared by its @p ranks_here ranks.
    int default_jobs(int ranks_here)
    {
      const int machine = int(std::max(1u, std::thread::hardware_concurrency()));
      cpu_set_t allowed;
      const int usable  = ::sched_getaffinity(0, sizeof allowed, &allowed) == 0 ? CPU_COUNT(&allowed) : machine;
      return std::max(1, std::min(usable, machine / std::max(1, ranks_here)));
    }

    /// This rank's share of @p runs (run k on rank (@p first + k) mod @p ranks), @p jobs at a
    /// time (0: default_jobs). The progress line counts this rank's runs. Never throws: a
    /// failure to start the work fails this rank's runs, so that every rank still meets the
    /// others in the agreement that follows.
    Share run_share(const std::vector<ChildRun> &runs, std::size_t first, int rank, int ranks, int ranks_here,
                    int jobs, const std::string &what)
    {
      std::vector<std::size_t> mine;
      for (std::size_t k = 0; k < runs.size(); ++k)
        if (int((first + k) % std::size_t(ranks)) == rank)
          mine.push_back(k);
      std::atomic<std::size_t> next{0}, done{0}, started{0}, failed{none};
      const auto               fail = [&failed](std::size_t k) { // (the lowest failed index stays)
        for (std::size_t was = failed.load(); k < was && !failed.compare_exchange_weak(was, k);)
          ;
      };
      try
        {
          if (jobs <= 0)
            jobs = default_jobs(ranks_here);
          io::ProgressLine progress(ranks > 1 ? what + " (" + std::to_string(mine.size()) + " of the " +
                                                  std::to_string(runs.size()) + " runs on rank " +
                                                  std::to_string(rank) + " of " + std::to_string(ranks) + ")"
                                                : what,
                                    double(mine.size()));
          std::vector<std::thread> pool;
          const auto               work = [&] {
            for (std::size_t i; (i = next++) < mine.size();)
              {
                ++started;
                if (io::run_child_command(runs[mine[i]].command) != 0)
                  fail(mine[i]);
                progress.update(double(++done), std::to_string(done.load()) + "/" + std::to_string(mine.size()) + " runs");
              }
          };
          try
            {
              for (int j = 0; j < jobs; ++j)
                pool.emplace_back(work);
            }
          catch (const std::system_error &) // (no more threads: the ones started do the work)
            {
              if (pool.empty())
                work();
            }
          for (auto &t : pool)
            t.join();
          progress.finish();
        }
      catch (const std::exception &)
        {
          if (!mine.empty())
            fail(mine[0]);
        }
      return {failed.load(), started.load()};
    }

    // A batch as rank 0 broadcasts it: "batch", the rank of its first run, the jobs, then each
    // run's directory and command, every field as its length and its text; "end" and the exit
    // code end the study.
    std::string field(const std::string &text) { return std::to_string(text.size()) + ":" + text; }

    std::string batch_text(const std::vector<ChildRun> &runs, std::size_t first, int jobs)
    {
      std::string text = field("batch") + field(std::to_string(first)) + field(std::to_string(jobs));
      for (const auto &r : runs)
        text += field(r.dir) + field(r.command);
      return text;
    }

    /// The fields of @p text (batch_text's or the end's).
    std::vector<std::string> fields_of(const std::string &text)
    {
      std::vector<std::string> fields;
      for (std::size_t at = 0; at < text.size();)
        {
          const std::size_t colon = text.find(':', at);
          const std::size_t size  = std::stoul(text.substr(at, colon - at));
          fields.push_back(text.substr(colon + 1, size));
          at = colon + 1 + size;
        }
      return fields;
    }

    /// Every rank's lowest failed run (none: none failed), agreed; on rank 0 (unless quiet), a
    /// line with the runs each rank started (what = "": a serving rank's).
    std::size_t agree_on(const dem::Parallel &ranks, const Share &share, const std::string &what)
    {
      const double        f = ranks.min(share.failed == none ? 1e300 : double(share.failed));
      std::vector<double> ran(ranks.size(), 0.0);
      ran[ranks.rank()] = double(share.ran);
      ranks.sum(ran);
      if (ranks.distributed() && ranks.rank() == 0 && !io::ProgressLine::quiet())
        {
          std::string each;
          for (std::size_t r = 0; r < ran.size(); ++r)
            each += (r ? ", " : "") + std::to_string(long(ran[r]));
          std::cout << what << ": runs started by the " << ran.size() << " MPI ranks: " << each << std::endl;
        }
      return f >= 1e300 ? none : std::size_t(f);
    }

    /// The rank of the next batch's first run: the batches go round the ranks (a batch of
    /// fewer runs than ranks does not always land on the first ranks).
    std::size_t next_first = 0;
  } // namespace

  void run_children(const std::vector<ChildRun> &runs, int jobs, const std::string &what)
  {
    const dem::Parallel ranks = dem::Parallel::world(); // (under mpirun: rank 0, StudyRanks)
    const std::size_t   first = next_first;
    next_first                = (next_first + runs.size()) % std::size_t(ranks.size());
    if (ranks.distributed())
      ranks.broadcast(batch_text(runs, first, jobs), 0);
    const int         here   = ranks.ranks_on_this_machine();
    const Share       share  = run_share(runs, first, ranks.rank(), ranks.size(), here, jobs, what);
    const std::size_t failed = agree_on(ranks, share, what);
    if (failed != none)
      throw RunError(what + ": run " + runs[failed].dir + " failed (see " + runs[failed].dir + ".log)");
  }

  StudyRanks::StudyRanks() : ranks(dem::Parallel::world()) {}

  StudyRanks::~StudyRanks()
  {
    if (leads())
      end(std::uncaught_exceptions() > 0 ? 1 : 0);
  }

  void StudyRanks::end(int code)
  {
    if (!ranks.distributed() || ended)
      return;
    ended = true;
    ranks.broadcast(field("end") + field(std::to_string(code)), 0);
  }

  int StudyRanks::serve() const
  {
    try
      {
        for (;;)
          {
            const std::string text = ranks.broadcast("", 0);
            std::vector<std::string> f;
            std::vector<ChildRun>    runs;
            std::size_t              first = 0;
            int                      jobs  = 0;
            bool                     read  = true;
            try // (a batch this rank cannot read fails here, after the others agree)
              {
                f = fields_of(text);
                if (f.at(0) == "end")
                  return std::stoi(f.at(1));
                first = std::stoul(f.at(1));
                jobs  = std::stoi(f.at(2));
                for (std::size_t k = 3; k + 1 < f.size(); k += 2)
                  runs.push_back({f[k], f[k + 1]});
              }
            catch (const std::exception &)
              {
                read = false;
              }
            const int here  = ranks.ranks_on_this_machine();
            Share     share = read ? run_share(runs, first, ranks.rank(), ranks.size(), here, jobs, "") : Share{0, 0};
            agree_on(ranks, share, "");
          }
      }
    catch (const std::exception &e) // (outside a batch: the leader would wait for ever)
      {
        std::cerr << "abrade: error: rank " << ranks.rank() << " of a study: " << e.what() << std::endl;
        MPI_Abort(MPI_COMM_WORLD, 1);
      }
    return 1;
  }

  CsvTable read_csv_table(const std::string &path)
  {
    if (!std::filesystem::is_regular_file(path))
      throw RunError("missing output " + path);
    return io::read_csv(path);
  }
} // namespace abrade::coupling
