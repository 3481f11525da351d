#include <abrade/common/error.h>
#include <abrade/coupling/lifetime_checkpoints.h>
#include <abrade/dem/parallel.h>

#include <filesystem>
#include <regex>

namespace abrade::coupling
{
  LifetimeCheckpoints::LifetimeCheckpoints(std::string directory)
    : directory(std::move(directory))
  {}

  std::string LifetimeCheckpoints::knife_file(long update) const
  {
    return directory + "/knife-" + std::to_string(update) + ".ckpt";
  }

  std::string LifetimeCheckpoints::state_file(long update) const
  {
    return directory + "/loop-" + std::to_string(update) + ".txt";
  }

  long LifetimeCheckpoints::newest() const
  {
    long             newest = -1;
    const std::regex state(R"(loop-([0-9]+)\.txt)");
    std::error_code  ec;
    for (const auto &entry : std::filesystem::directory_iterator(directory, ec))
      {
        std::smatch      m;
        const std::string name = entry.path().filename().string();
        if (std::regex_match(name, m, state))
          newest = std::max(newest, std::stol(m[1]));
      }
    return newest;
  }

  long LifetimeCheckpoints::resume_point(const dem::Parallel &ranks) const
  {
    const long mine   = newest();
    const long common = std::max(0L, long(ranks.min(double(mine))));
    for (long u = mine; u > common; --u)
      remove(u);
    if (common > 0 && !std::filesystem::exists(state_file(common)))
      throw InputError(state_file(common), "missing: another MPI rank resumes from this update, this rank kept "
                                           "only update " + std::to_string(mine) + " (checkpoints edited?)");
    if (common > 0 && !std::filesystem::exists(knife_file(common)))
      throw InputError(knife_file(common), "missing, but its loop state is there (checkpoints edited?)");
    return common;
  }

  void LifetimeCheckpoints::clear() const
  {
    for (long u = newest(); u >= 0; --u)
      remove(u);
  }

  void LifetimeCheckpoints::commit(long update) const
  {
    std::filesystem::rename(knife_file_aside(update), knife_file(update));
    std::filesystem::rename(state_file_aside(update), state_file(update));
    remove(update - 2);
  }

  void LifetimeCheckpoints::remove(long update) const
  {
    std::error_code ec; // (either may never have been written)
    std::filesystem::remove(state_file(update), ec);
    std::filesystem::remove(knife_file(update), ec);
  }
} // namespace abrade::coupling
