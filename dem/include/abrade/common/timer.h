#pragma once
// Named wall-clock sections for the run summary: { ScopedTimer t(timers, "dem"); ... }
#include <chrono>
#include <map>
#include <string>

namespace abrade::io
{
  class Timers
  {
  public:
    void                                 add(const std::string &name, double seconds) { totals[name] += seconds; }
    const std::map<std::string, double> &all() const { return totals; }

  private:
    std::map<std::string, double> totals;
  };

  class ScopedTimer
  {
  public:
    ScopedTimer(Timers &t, std::string n) : timers(t), name(std::move(n)), start(std::chrono::steady_clock::now()) {}
    ~ScopedTimer() { timers.add(name, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()); }

  private:
    Timers                               &timers;
    std::string                           name;
    std::chrono::steady_clock::time_point start;
  };
} // namespace abrade::io
