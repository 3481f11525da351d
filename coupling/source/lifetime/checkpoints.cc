// The lifetime run's checkpoints: which exist, which is the latest whole one, and removing the
// older ones (checkpoints.h).
#include <abrade/common/error.h>
#include <abrade/coupling/lifetime/checkpoints.h>
#include <abrade/dem/parallel.h>

#include <algorithm>
#include <filesystem>
#include <regex>

namespace abrade::coupling
{
  LifetimeCheckpoints::LifetimeCheckpoints(std::string directory)
    : directory(std::move(directory))
  {}

  std::string LifetimeCheckpoints::part_file(long update) const
  {
    return directory + "/knife-" + std::to_string(update) + ".ckpt";
  }

  std::string LifetimeCheckpoints::state_file(long update) const
  {
    return directory + "/loop-" + std::to_string(update) + ".txt";
  }

  std::vector<long> LifetimeCheckpoints::updates() const
  {
    // the updates that have a state or a part file (a stray name with a 30-digit number is
    // not one: at most 15 digits)
    std::vector<long> found;
    const std::regex  files(R"((loop-([0-9]{1,15})\.txt)|(knife-([0-9]{1,15})\.ckpt))");
    std::error_code   ec;
    for (const auto &entry : std::filesystem::directory_iterator(directory, ec))
      {
        std::smatch       m;
        const std::string name = entry.path().filename().string();
        if (std::regex_match(name, m, files))
          found.push_back(std::stol(m[2].matched ? m[2].str() : m[4].str()));
      }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    return found;
  }

  long LifetimeCheckpoints::newest() const
  {
    long newest = -1;
    for (const long u : updates())
      if (std::filesystem::exists(state_file(u)))
        newest = std::max(newest, u);
    return newest;
  }

  long LifetimeCheckpoints::resume_point(const dem::Parallel &ranks) const
  {
    const long mine   = newest();
    const long common = std::max(0L, long(ranks.min(double(mine))));
    for (const long u : updates()) // those beyond the common point (not counted down: a stray
      if (u > common)              // loop-999999999999.txt would take years)
        remove(u);
    if (common > 0 && !std::filesystem::exists(state_file(common)))
      throw InputError(state_file(common), "missing: another MPI rank resumes from this update, this rank kept "
                                           "only update " + std::to_string(mine) + " (checkpoints edited?)");
    if (common > 0 && !std::filesystem::exists(part_file(common)))
      throw InputError(part_file(common), "missing, but its loop state is there (checkpoints edited?)");
    return common;
  }

  void LifetimeCheckpoints::clear() const
  {
    for (const long u : updates())
      remove(u);
  }

  void LifetimeCheckpoints::commit(long update) const
  {
    std::filesystem::rename(part_file_aside(update), part_file(update));
    std::filesystem::rename(state_file_aside(update), state_file(update));
    remove(update - 2);
  }

  void LifetimeCheckpoints::remove(long update) const
  {
    std::error_code ec; // (either may never have been written)
    std::filesystem::remove(state_file(update), ec);
    std::filesystem::remove(part_file(update), ec);
  }
} // namespace abrade::coupling
