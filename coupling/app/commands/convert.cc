// abrade convert: a part drawn as a Gmsh script (or a CAD file) written as STEP.
#include "../command.h"
#include "../command_line.h"

#include <abrade/common/error.h>
#include <abrade/fem/solid_file.h>

#include <iostream>

namespace abrade::app
{
  namespace
  {
    int convert_command(const std::vector<std::string> &args, const std::string &typed)
    {
      const CommandLine cl = parse("convert", args, typed, {"FILE", "--output"});
      if (cl.file.empty() || cl.output.empty())
        throw InputError("command line", "convert needs an input file and --output FILE.step");
      fem::convert_to_step(cl.file, cl.output);
      std::cout << cl.output << "\n";
      return 0;
    }
  } // namespace

  ABRADE_REGISTER_COMMAND("convert",
                          "  abrade convert SCRIPT.geo|FILE.step|FILE.brep --output FILE.step\n"
                          "      write the CAD model of a Gmsh script (OpenCASCADE kernel) as STEP, its numbers as they\n"
                          "      are (a script in millimetres gives a STEP in millimetres): a part drawn as a script\n",
                          convert_command);
} // namespace abrade::app
