// abrade sweep: the case for every value of the varied parameters and every seed, side by
// side, with the study's tables, plots and surfaces (coupling/studies/sweep.h).
#include "../command.h"
#include "../command_line.h"
#include "study_on_ranks.h"

#include <abrade/common/error.h>
#include <abrade/common/progress.h>
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/studies/sweep.h>

#include <filesystem>

namespace abrade::app
{
  namespace
  {
    int sweep(const CommandLine &cl);

    int sweep_command(const std::vector<std::string> &args, const std::string &typed)
    {
      const CommandLine cl = parse("sweep", args, typed, {"FILE", "--set", "--output", "--quiet", "--seeds", "--jobs", "--lifetime-updates", "--vary", "--edge-height", "--wall"});
      return study_on_ranks([&] { return sweep(cl); });
    }

    /// The sweep of @p cl, on rank 0 under mpirun.
    int sweep(const CommandLine &cl)
    {
      if (cl.file.empty())
        throw InputError("command line", "sweep needs a parameter file");
      coupling::ParameterFile check(cl.file, cl.sets); // fail early on a bad file
      coupling::SweepOptions  o;
      o.parameter_file = std::filesystem::absolute(cl.file).string();
      for (const auto &v : cl.varies)
        coupling::parse_vary(v, o);
      o.edge_height = cl.edge_height;
      o.seeds       = seed_list(cl.seeds.empty() ? "1,2,3" : cl.seeds);
      o.sets = cl.sets, o.output = cl.output, o.wall = cl.wall, o.jobs = cl.jobs, o.quiet = cl.quiet;
      o.lifetime_updates = cl.lifetime_updates;
      io::ProgressLine::set_quiet(cl.quiet);
      return with_report(coupling::run_sweep(o, std::filesystem::canonical("/proc/self/exe").string()), o.output);
    }
  } // namespace

  ABRADE_REGISTER_COMMAND(
    "sweep",
    "  abrade sweep FILE.prm --vary \"Section/Key=v1,v2,...\" [--vary \"Key2=...\"]... [--seeds 1,2,3]\n"
    "               [--wall knife] [--edge-height 0.04] [--lifetime-updates N] [--jobs N] [--set ...]...\n"
    "               --output DIR\n"
    "      run the case for every value (several --vary: every combination) and seed (one settled\n"
    "      bed per seed and particle parameters, reused), in parallel, and write study.csv/.md (mean\n"
    "      and std over seeds), plots/*.png and surfaces/*.vtp; with --lifetime-updates, each\n"
    "      combination's life too, paired against the first's (lifetime/NAME/); under mpirun the\n"
    "      runs are spread over the ranks (--jobs: at a time on each)\n",
    sweep_command);
} // namespace abrade::app
