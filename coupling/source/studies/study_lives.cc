// The lives of a study's variants (study_lives.h).
#include <abrade/common/error.h>
#include <abrade/common/json.h>
#include <abrade/coupling/studies/study_lives.h>

#include <cmath>
#include <filesystem>
#include <iostream>

namespace abrade::coupling
{
  std::vector<std::string> lifetime_run_sets(std::vector<std::string> sets, int updates, const std::vector<int> &seeds)
  {
    std::string list;
    for (int s : seeds)
      list += (list.empty() ? "" : ",") + std::to_string(s);
    sets.insert(sets.end(), {"Job=lifetime", "Lifetime/Tonnes per cycle=0", "Lifetime/Maximum updates=" + std::to_string(updates),
                             "Lifetime/Seeds=" + list, "Simulation/Threads=1", "Output/Write particles=false",
                             "Output/Snapshot interval=0", "Particles/Settling/Bed file="});
    return sets;
  }

  StudyLife read_study_life(const std::string &dir)
  {
    StudyLife         l;
    const std::string summary = dir + "/summary.json";
    l.tonnes = io::summary_number(summary, "predicted_tonnes_to_end_of_life").value_or(0);
    l.low    = io::summary_number(summary, "predicted_tonnes_low").value_or(0);
    l.high   = io::summary_number(summary, "predicted_tonnes_high").value_or(0);
    if (std::filesystem::exists(dir + "/life_beds.csv"))
      try
        {
          l.beds = lifetime::read_life_beds(dir + "/life_beds.csv"), l.has_beds = true;
        }
      catch (const InputError &e) // (the others' changes are still worth having)
        {
          std::cerr << "warning: " << e.what() << "; its change of life is taken from the two lives' intervals "
                    << "combined (not paired)" << std::endl;
        }
    return l;
  }

  PairedChange life_change(const StudyLife &variant, const StudyLife &baseline)
  {
    PairedChange c;
    if (!(variant.tonnes > 0 && baseline.tonnes > 0))
      return c;
    if (variant.has_beds && baseline.has_beds)
      return lifetime::paired_life_change(variant.beds, baseline.beds);
    c.ratio = c.low = c.high = variant.tonnes / baseline.tonnes;
    if (variant.low > 0 && variant.high > 0 && baseline.low > 0 && baseline.high > 0)
      {
        const double h = std::hypot(0.5 * std::log(variant.high / variant.low), 0.5 * std::log(baseline.high / baseline.low));
        c.low = c.ratio * std::exp(-h), c.high = c.ratio * std::exp(h);
        c.interval    = true;
        c.significant = c.low > 1 || c.high < 1;
      }
    return c;
  }
} // namespace abrade::coupling
