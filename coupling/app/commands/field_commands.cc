// abrade compare and abrade calibrate: a predicted surface against a field scan, and the wear
// coefficient fitted to measured wear (field/commands.h parses their options); each writes its
// report when it ends.
#include "../command.h"
#include "../command_line.h"

#include <abrade/field/commands.h>

namespace abrade::app
{
  namespace
  {
    int compare_command(const std::vector<std::string> &args, const std::string &)
    {
      return with_report(field::run_compare_command(args), output_option(args));
    }

    int calibrate_command(const std::vector<std::string> &args, const std::string &)
    {
      return with_report(field::run_calibrate_command(args), output_option(args));
    }
  } // namespace

  ABRADE_REGISTER_COMMAND("compare", field::compare_usage, compare_command);
  ABRADE_REGISTER_COMMAND("calibrate", field::calibrate_usage, calibrate_command);
} // namespace abrade::app
