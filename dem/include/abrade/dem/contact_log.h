#pragma once
// What happened at every particle-wall contact in one time step, handed to the step hooks (wear
// laws, probes, per-triangle force accumulation) after the force computation. Hooks are called
// once per step with the whole log, so there is no virtual call per contact.
#include <abrade/common/closest_point.h>

#include <cstdint>
#include <string>
#include <vector>

namespace abrade::dem
{
  struct WallContactRecord
  {
    int          wall;
    int          triangle;             ///< triangle that carries the contact point
    Feature      feature;              ///< where on that triangle: face, edge or vertex
    int          particle;             ///< index (valid during this step)
    std::int64_t particle_id;
    double       point[3];             ///< contact point on the wall [m]
    double       normal[3];            ///< unit normal from the wall to the particle
    double       normal_force;         ///< signed, along normal (positive pushes the particle away) [N]
    double       tangential_force[3];  ///< on the particle [N]
    double       normal_velocity;      ///< particle relative to wall along normal (< 0 approaching) [m/s]
    double       tangential_velocity[3]; ///< sliding velocity of the contact point [m/s]
    double       overlap;              ///< [m]
    double       centre_velocity[3];   ///< particle centre relative to the wall's material point [m/s]
    bool         began;                ///< the contact began this step (its history is new): an impact
  };

  /// One record vector per share of the step's work (Settings::threads; each filled by the one
  /// thread that works that share, without locks); read in share order (deterministic, whatever
  /// the number of threads).
  struct ContactLog
  {
    std::vector<std::vector<WallContactRecord>> per_thread;

    template <typename F>
    void for_each(F &&f) const
    {
      for (const auto &v : per_thread)
        for (const auto &r : v)
          f(r);
    }
    std::size_t size() const
    {
      std::size_t n = 0;
      for (const auto &v : per_thread)
        n += v.size();
      return n;
    }
  };

  class Simulation;

  /// A per-step plug-in: wear laws and probes implement it (next to the built-in per-triangle
  /// impulse accumulation).
  class StepHook
  {
  public:
    virtual ~StepHook() = default;
    /// Called after every step's force computation, with the step's wall contacts.
    virtual void after_step(const Simulation &sim, const ContactLog &log) = 0;
    /// Called when the simulation enters a new phase.
    virtual void phase_changed(const Simulation &sim, const std::string &phase) {}
  };
} // namespace abrade::dem
