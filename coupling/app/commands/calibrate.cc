// abrade calibrate: the wear coefficient (and the footprint) fitted to measured wear
// (field/commands.h parses its options); it writes its report when it ends.
#include "../command.h"
#include "../command_line.h"

#include <abrade/field/commands.h>

namespace abrade::app
{
  namespace
  {
    int calibrate_command(const std::vector<std::string> &args, const std::string &)
    {
      return with_report(field::run_calibrate_command(args), output_option(args));
    }
  } // namespace

  ABRADE_REGISTER_COMMAND("calibrate", field::calibrate_usage, calibrate_command);
} // namespace abrade::app
