// abrade compare: a predicted surface against a field scan (field/commands.h parses its
// options); it writes its report when it ends.
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
  } // namespace

  ABRADE_REGISTER_COMMAND("compare", field::compare_usage, compare_command);
} // namespace abrade::app
