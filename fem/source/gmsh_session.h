#pragma once
// Gmsh started for abrade: without its configuration files. With them (the API's default)
// gmsh::initialize reads ~/.gmshrc and ~/.gmsh-options, which let a user's own Gmsh settings
// change abrade's meshes, and its FLTK start-up rewrites FLTK's preference files in /etc/fltk
// and ~/.fltk: writes outside the run's output directory, on every part job.
#include <gmsh.h>

namespace abrade::fem
{
  inline void start_gmsh() { gmsh::initialize(0, nullptr, false); }
} // namespace abrade::fem
