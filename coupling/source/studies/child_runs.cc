// Studies made of many `abrade run` child processes (sweep, concepts): starting them side by
// side, waiting, and collecting what each wrote (child_runs.h).
#include <abrade/common/error.h>
#include <abrade/common/external.h>
#include <abrade/common/list_items.h>
#include <abrade/common/progress.h>
#include <abrade/common/termination.h>
#include <abrade/coupling/studies/child_runs.h>
#include <abrade/coupling/studies/study_lives.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <mutex>
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

  namespace
  {
    /// The entry a --set names, spelt as the parameter file reads it ("Particles / Generation
    /// /Seed" is Particles/Generation/Seed: each part trimmed, empty ones left out).
    std::string entry_path(const std::string &set)
    {
      std::string path;
      for (const std::string &part : io::list_items(set.substr(0, set.find('=')), '/'))
        path += (path.empty() ? "" : "/") + part;
      return path;
    }
  } // namespace

  void refuse_study_owned_sets(const std::vector<std::string> &sets, const std::string &option, bool lives)
  {
    std::vector<std::string> owned = study_cycle_sets(0, "");
    if (lives)
      for (const std::string &set : lifetime_run_sets({}, 1, {1}))
        owned.push_back(set);
    for (const std::string &set : sets)
      {
        const std::string key = entry_path(set);
        for (const std::string &o : owned)
          if (key == entry_path(o))
            throw InputError("command line", option + " " + key + ": the study sets this entry on each of its " +
                                               (lives ? "lifetime runs" : "cycles") +
                                               " itself (the seeds come from --seeds, the updates from --lifetime-updates)");
      }
  }

  void run_children(const std::vector<ChildRun> &runs, int jobs, const std::string &what)
  {
    if (jobs <= 0)
      jobs = int(std::max(1u, std::thread::hardware_concurrency()));
    std::atomic<std::size_t> next{0}, done{0};
    std::mutex               failure_mutex;
    std::string              failure;
    io::ProgressLine         progress(what, double(runs.size()));
    std::vector<std::thread> pool;
    for (int j = 0; j < jobs; ++j)
      pool.emplace_back([&] {
        for (std::size_t k; (k = next++) < runs.size();)
          {
            if (io::run_child_command(runs[k].command) != 0)
              {
                std::lock_guard<std::mutex> lock(failure_mutex);
                failure = "run " + runs[k].dir + " failed (see " + runs[k].dir + ".log)";
              }
            progress.update(double(++done), std::to_string(done.load()) + "/" + std::to_string(runs.size()) + " runs");
          }
      });
    for (auto &t : pool)
      t.join();
    progress.finish();
    if (!failure.empty())
      throw RunError(what + ": " + failure);
  }

  CsvTable read_csv_table(const std::string &path)
  {
    if (!std::filesystem::is_regular_file(path))
      throw RunError("missing output " + path);
    return io::read_csv(path);
  }
} // namespace abrade::coupling
