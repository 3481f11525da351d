// abrade case: a commented lifetime case written around the user's part
// (coupling/case_setup/case_command.h parses its options).
#include "../command.h"

#include <abrade/coupling/case_setup/case_command.h>

namespace abrade::app
{
  namespace
  {
    int case_command(const std::vector<std::string> &args, const std::string &)
    {
      return coupling::run_case_command(args);
    }
  } // namespace

  ABRADE_REGISTER_COMMAND("case",
                          "  abrade case PART --output FILE.prm [--material iron-ore-pellets|gravel|coal|soil]\n"
                          "              [--clamped \"SELECTORS\"] [--depth D] [--travel L] [--particles N] [...]\n"
                          "      write a commented lifetime case around your part: the part dragged through a bed of the\n"
                          "      material, the bed, container, particle size, phases and tonnes per cycle chosen from the\n"
                          "      part (abrade case alone lists every option)\n",
                          case_command);
} // namespace abrade::app
