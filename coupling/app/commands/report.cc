// abrade report: a run's report.html written again (after editing a plot script, or for a run
// directory that has none).
#include "../command.h"

#include <abrade/common/error.h>
#include <abrade/report/report.h>

#include <iostream>

namespace abrade::app
{
  namespace
  {
    int report_command(const std::vector<std::string> &args, const std::string &)
    {
      if (args.size() != 1)
        throw InputError("command line", "usage: abrade report RUN_DIR");
      std::cout << report::write_report(args[0]) << std::endl;
      return 0;
    }
  } // namespace

  ABRADE_REGISTER_COMMAND("report",
                          "  abrade report RUN_DIR\n"
                          "      write RUN_DIR/report.html, one self-contained page (pictures inlined) for a lifetime,\n"
                          "      part (a preview), sweep, concepts, compare or calibrate run; those runs write it\n"
                          "      themselves when they end\n",
                          report_command);
} // namespace abrade::app
