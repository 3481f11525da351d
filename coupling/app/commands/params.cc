// abrade params: every parameter with its documentation, unit, range and default.
#include "../command.h"
#include "../command_line.h"

#include <abrade/common/error.h>
#include <abrade/coupling/parameters/parameter_file.h>

#include <iostream>

namespace abrade::app
{
  namespace
  {
    int params_command(const std::vector<std::string> &args, const std::string &typed)
    {
      const CommandLine       cl = parse("params", args, typed, {"--format"});
      coupling::ParameterFile p;
      if (cl.format == "prm")
        std::cout << p.canonical_text();
      else if (cl.format == "text")
        p.handler().print_parameters(std::cout, dealii::ParameterHandler::Text);
      else
        throw InputError("command line", "--format must be text or prm");
      return 0;
    }
  } // namespace

  ABRADE_REGISTER_COMMAND("params",
                          "  abrade params [--format text|prm]\n"
                          "      print every parameter with its documentation, unit, allowed range and default\n",
                          params_command);
} // namespace abrade::app
