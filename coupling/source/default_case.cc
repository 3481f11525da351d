// The case `abrade run` runs when no parameter file is given: a small knife-bed cycle (600
// seed-material pellets in a 0.8 m x 0.5 m box, the reference knife scaled to it) that finishes
// in seconds and shows every output.
#include <abrade/coupling/parameter_file.h>

namespace abrade::coupling
{
  const std::string &default_case_text()
  {
    static const std::string text = R"(# abrade embedded default case: a small knife-bed cycle
set Job = dem
set Walls = container, knife
subsection Output
  set Directory = output
  set Snapshot interval = 0.05
end
subsection Simulation
  set Phases = penetration: 0.1, travel: 0.2
  set Domain min = -0.5, -0.3, -0.1
  set Domain max = 0.5, 0.3, 1.0
end
subsection Particles
  subsection Generation
    set Region min = -0.39, -0.24, 0.01
    set Region max = 0.39, 0.24, 0.6
    set Count = 600
    set Seed = 1
  end
  subsection Settling
    set Maximum time = 0.8
    set Kinetic energy threshold = 1e-3
  end
end
subsection Wall container
  set Geometry = box
  set Box min = -0.4, -0.25, 0
  set Box max = 0.4, 0.25, 0.7
end
subsection Wall knife
  set Geometry = chisel knife
  set Knife length = 0.15
  set Knife height = 0.25
  set Offset = -0.2, 0, 0.35
  set Maximum edge length = 0.02
  subsection Motion
    set Type = prescribed
    set Velocities = penetration: 0, 0, -1.5; travel: 1.5, 0, 0
  end
end
)";
    return text;
  }
} // namespace abrade::coupling
