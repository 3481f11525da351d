#pragma once
// A mechanism that moves walls (a grab's rope mechanism: rope_grab_driver.h): once a step's
// forces are known, it takes the loads on the walls it drives (WallMotion::Kind::driven),
// integrates its own equations of motion and sets those walls' velocities, with which the next
// step moves them. Walls are replicated over the MPI ranks and their loads summed, so every
// rank drives them alike.
#include <string>

namespace abrade::dem
{
  class Simulation;

  class WallDriver
  {
  public:
    virtual ~WallDriver() = default;
    /// After the step's forces (each wall's force, and torque about its centre, are this
    /// step's): sets the velocities of the walls it drives for the next step of @p dt.
    virtual void drive(Simulation &sim, double dt) = 0;
    /// The simulation enters @p phase ("settle" while a bed settles).
    virtual void phase_changed(Simulation &sim, const std::string &phase) = 0;
  };
} // namespace abrade::dem
