// The case `abrade run` runs when no parameter file is given: the main job, a lifetime
// prediction, on a small case (cases/lifetime/default.prm, the same text: 600 pellets, a 0.15 m
// knife, three fresh beds per update) followed to its end of life, so that the first run shows
// what the tool is for: a life reached, with its 95 % interval, in under a minute on two cores.
#include <abrade/coupling/parameters/parameter_file.h>

namespace abrade::coupling
{
  const std::string &default_case_text()
  {
    static const std::string text = R"(# abrade embedded default case (= cases/lifetime/default.prm): a small lifetime prediction,
# followed to its end of life. A 0.15 m chisel knife (30 mm plate) cuts a bed of 600 coarse
# pellets once per cycle (DEM); three fresh beds per update give the wear, which moves the
# knife's solid model (FEM), update after update, until the plate is 6 mm deep below its
# design anywhere (the depth a scan gives; a fifth of the plate). The predicted life comes with
# its 95 % interval over all updates' beds (docs/lifetime.md). About 35 s on two cores:
#   abrade run            (or: abrade run cases/lifetime/default.prm)
set Job   = lifetime
set Walls = container, knife
subsection Output
  set Directory = output
end
subsection Simulation
  set Phases = penetration: 0.1, travel: 0.2
  set Domain min = -0.5, -0.3, -0.1
  set Domain max = 0.5, 0.3, 1.0
  # a tenth of the Rayleigh time step: the soft coarse pellets jammed under the knife at
  # 1.5 m/s reach 30-40 % overlap, where 0.2 of it let one of the first fresh beds a run drew
  # (seed 692341759) blow a pellet out of the box
  set Rayleigh fraction = 0.1
  # and jammed pairs reach 35 % in a bed in ten: the limit is a check of the time step, which
  # the tenth makes safe (at 0.2 the pellet that left the box passed 40 % first)
  set Maximum overlap fraction = 0.5
  # a pair jammed under the knife past it (50.02 % in one of 12 beds at one update of this case)
  # is a warning, logged and counted per update in trajectory.csv, not the end of the run: the
  # main job's first run must not stop on one pellet
  set On error = continue
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
subsection Part
  set Length       = 0.15
  set Height       = 0.25
  set Thickness    = 0.03
  set Bevel height = 0.04
  set Mesh size    = 0.015
end
subsection Lifetime
  # nominal material per pass of the knife through the bed
  set Tonnes per cycle         = 0.2
  set Seeds                    = 1, 2, 3
  # one bed's wear at one point of this small bed scatters by about 100 %: more beds are drawn
  # (up to 12 an update) while the life's interval is wider than +-50 %
  set Target interval          = 0.5
  set Maximum beds             = 12
  set Depth increment fraction = 0.1
  set Maximum depth            = 0.006
  set Maximum updates          = 20
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
