// abrade export-walls: every wall of a case as the simulation sees it at t = 0, as STL.
#include "../command.h"
#include "../command_line.h"

#include <abrade/common/error.h>
#include <abrade/common/log.h>
#include <abrade/common/output_directory.h>
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/parameters/part_parameters.h>
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/dem/mesh_io.h>

#include <filesystem>
#include <iostream>

namespace abrade::app
{
  namespace
  {
    int export_walls_command(const std::vector<std::string> &args, const std::string &typed)
    {
      const CommandLine cl = parse("export-walls", args, typed, {"FILE", "--set", "--output"});
      if (cl.output.empty())
        throw InputError("command line", "export-walls needs --output DIR");
      coupling::ParameterFile p(cl.file, cl.sets);
      auto                     c = coupling::read_dem_case(p);
      io::OutputDirectory      out(cl.output);
      out.claim();
      io::Log                  log; // to the terminal
      log.set_echo(true);
      for (const auto &note : c.notes)
        log.line(note);
      coupling::fill_solid_model_walls(c, p, out.root(), log); // the FEM part's surface, placed
      for (const auto &w : c.walls)
        {
          std::error_code ec;
          for (const auto &input : c.input_files)
            if (std::filesystem::equivalent(input, out.file(w.wall.name + ".stl"), ec))
              throw InputError(input, "is wall " + w.wall.name + "'s mesh and the file export-walls would write "
                                      "it to: choose another --output");
          dem::write_stl(out.file(w.wall.name + ".stl"), w.wall.mesh);
          std::cout << out.file(w.wall.name + ".stl") << ": " << w.wall.mesh.n_triangles() << " triangles\n";
        }
      return 0;
    }
  } // namespace

  ABRADE_REGISTER_COMMAND("export-walls",
                          "  abrade export-walls [FILE.prm] [--set ...]... --output DIR\n"
                          "      write every wall of the case, as the simulation sees it at t = 0, as DIR/NAME.stl\n",
                          export_walls_command);
} // namespace abrade::app
