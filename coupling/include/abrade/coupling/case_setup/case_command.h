#pragma once
// `abrade case PART --output FILE.prm [...]`: a lifetime case written around a user's part, so
// that a first run needs no guesses (docs/user-guide.md, "A case for your own part"). From the
// part's placed bounding box, volume and surface, a tool motion (the part dragged through a bed
// as the knife-bed drags its knife: down into it, then along x) and a material preset (iron-ore
// pellets, gravel, coal, soil), it chooses the bed box, the container, the domain, the particle
// size (coarse-grained to a particle count), the settling time, the phases, the tonnes per cycle
// (the swept volume x the bulk density, said as such) and a first end of life, and writes them
// as a commented .prm; the bed's fill is checked by reading the file back as a run would.
#include <string>
#include <vector>

namespace abrade::coupling
{
  /// Runs `abrade case` on its arguments (after the command); returns the exit code. Bad
  /// arguments or a part that cannot be read: InputError.
  int run_case_command(const std::vector<std::string> &args);
} // namespace abrade::coupling
