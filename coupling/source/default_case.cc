// The case `abrade run` runs when no parameter file is given: the main job, a lifetime
// prediction, on a small case (cases/lifetime/small.prm: 600 pellets, a 0.15 m knife, four
// updates) that finishes in seconds and shows every output.
#include <abrade/coupling/parameter_file.h>

namespace abrade::coupling
{
  const std::string &default_case_text()
  {
    static const std::string text = R"(# abrade embedded default case (= cases/lifetime/small.prm): a small lifetime prediction
set Job   = lifetime
set Walls = container, knife
subsection Output
  set Directory = output
end
subsection Simulation
  set Phases = penetration: 0.1, travel: 0.2
  set Domain min = -0.5, -0.3, -0.1
  set Domain max = 0.5, 0.3, 1.0
  set Maximum overlap fraction = 0.3
end
subsection Particles
  subsection Generation
    set Region min = -0.39, -0.24, 0.01
    set Region max = 0.39, 0.24, 0.6
    set Count = 600
  end
  subsection Settling
    set Maximum time = 0.8
    set Kinetic energy threshold = 1e-3
  end
end
subsection Knife
  set Length       = 0.15
  set Height       = 0.25
  set Thickness    = 0.03
  set Bevel height = 0.04
  set Mesh size    = 0.015
end
subsection Lifetime
  # nominal material per pass of the knife through the bed
  set Tonnes per cycle         = 0.2
  set Seeds                    = 1
  set Depth increment fraction = 0.05
  set Maximum depth            = 0.01
  set Maximum updates          = 4
  # the middle of the edge of this 0.15 m knife
  set Recession points         = 0.075, 0, 0
end
subsection Wall container
  set Geometry = box
  set Box min = -0.4, -0.25, 0
  set Box max = 0.4, 0.25, 0.7
end
subsection Wall knife
  set Geometry = solid model
  # the knife's edge at x = -0.275 .. -0.125, 0.35 m above the floor
  set Offset = -0.275, 0, 0.35
  subsection Wear
    set Laws = archard
    # W = K / H for a wear-resistant steel against iron ore: K = 1e-4, H = 5e9 Pa (calibrate!)
    subsection Archard
      set Coefficient = 2e-14
    end
  end
  subsection Motion
    set Type = prescribed
    set Velocities = penetration: 0, 0, -1.5; travel: 1.5, 0, 0
  end
end
)";
    return text;
  }
} // namespace abrade::coupling
