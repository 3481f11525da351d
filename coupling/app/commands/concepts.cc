// abrade concepts: knife concepts against a baseline on the same beds, with the changes'
// uncertainties (coupling/studies/concepts.h).
#include "../command.h"
#include "../command_line.h"
#include "study_on_ranks.h"

#include <abrade/common/error.h>
#include <abrade/common/progress.h>
#include <abrade/coupling/studies/concepts.h>
#include <abrade/coupling/parameters/parameter_file.h>

#include <filesystem>
#include <sstream>

namespace abrade::app
{
  namespace
  {
    int concepts(const CommandLine &cl);

    int concepts_command(const std::vector<std::string> &args, const std::string &typed)
    {
      const CommandLine cl = parse("concepts", args, typed, {"FILES", "--set", "--output", "--quiet", "--seeds", "--jobs", "--knives", "--lifetime-updates"});
      return study_on_ranks([&] { return concepts(cl); });
    }

    /// The concept study of @p cl, on rank 0 under mpirun.
    int concepts(const CommandLine &cl)
    {
      coupling::ConceptOptions o;
      o.files.push_back(cl.file);
      o.files.insert(o.files.end(), cl.more_files.begin(), cl.more_files.end());
      for (const auto &f : o.files) // fail early on a bad file
        coupling::ParameterFile check(f, cl.sets);
      o.seeds = seed_list(cl.seeds.empty() ? "1,2" : cl.seeds);
      o.knives.clear();
      std::stringstream ks(cl.knives);
      for (std::string k; std::getline(ks, k, ',');)
        o.knives.push_back(k);
      o.sets = cl.sets, o.output = cl.output, o.jobs = cl.jobs, o.quiet = cl.quiet;
      o.lifetime_updates = cl.lifetime_updates;
      io::ProgressLine::set_quiet(cl.quiet);
      return with_report(coupling::run_concepts(o, std::filesystem::canonical("/proc/self/exe").string()), o.output);
    }
  } // namespace

  ABRADE_REGISTER_COMMAND(
    "concepts",
    "  abrade concepts BASELINE.prm CONCEPT.prm... [--seeds 1,2] [--knives right_knife,left_knife]\n"
    "                  [--lifetime-updates N] [--jobs N] [--set ...]... --output DIR\n"
    "      run every knife concept's cycle per bed seed (the same beds for all), and write the\n"
    "      knives' wear per phase, payload, wear per tonne and the change against the baseline with\n"
    "      its uncertainty (concepts.md/.csv, wear.png); with --lifetime-updates, each concept's\n"
    "      knife life too (lifetime/NAME/, lifetime.png); under mpirun the runs are spread over the\n"
    "      ranks (--jobs: at a time on each)\n",
    concepts_command);
} // namespace abrade::app
