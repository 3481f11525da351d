// abrade: predicts where and how fast bulk-handling tools wear.
//
//   abrade COMMAND [ARGUMENTS]...      (abrade --help lists the commands: commands/*.cc)
//   abrade --version
//
// Each command is a file in commands/ that registers itself (command.h). Here the command is
// found and what it throws becomes the exit code: 0 success, 2 bad input (command line,
// parameter file, mesh), 3 run-time failure (NaN, lost particle, inverted element), 1 anything
// else.
#include "command.h"
#include "command_line.h"

#include <abrade/common/error.h>
#include <abrade/common/external.h>
#include <abrade/common/termination.h>
#include <abrade/common/version.h>
#include <abrade/dem/parallel.h>

#include <iostream>
#include <string>
#include <vector>

using namespace abrade;

namespace
{
  /// Every command's usage, in the registry's order.
  std::string usage()
  {
    std::string text = "usage:\n";
    for (const auto &c : app::make_commands())
      text += c->usage();
    return text + "  abrade --version\n";
  }

  /// The final error line. Under mpirun the ranks fail together with the same message (the
  /// DEM's errors are agreed on), so only rank 0 prints it; every rank's log.txt has it.
  void print_error(const char *what, const std::string &message)
  {
    if (dem::Parallel::world().rank() == 0 && app::launch().rank == 0) // the latter also before MPI_Init
      std::cerr << what << message << std::endl;
  }
} // namespace

int main(int argc, char **argv)
{
  io::install_termination_handlers();
  try
    {
      const std::vector<std::string> words(argv + 1, argv + argc);
      if (words.empty())
        throw InputError("command line", "no command given\n" + usage());
      const std::string &name = words[0];
      if (name == "--version" || name == "version")
        {
          std::cout << "abrade " << version_string << std::endl;
          return 0;
        }
      if (name == "--help" || name == "-h" || name == "help")
        {
          std::cout << usage();
          return 0;
        }
      if (const auto command = app::make_command(name))
        {
          // --help (or -h) anywhere after it: the command's usage
          for (std::size_t k = 1; k < words.size(); ++k)
            if (words[k] == "--help" || words[k] == "-h")
              {
                std::cout << "usage:\n" << command->usage();
                return 0;
              }
          std::string typed;
          for (int k = 0; k < argc; ++k)
            typed += (k ? " " : "") + io::shell_quote(argv[k]);
          return command->run(std::vector<std::string>(words.begin() + 1, words.end()), typed);
        }
      throw InputError("command line", "unknown command '" + name + "'\n" + usage());
    }
  catch (const InputError &e)
    {
      print_error("abrade: error: ", e.what());
      return 2;
    }
  catch (const RunError &e)
    {
      print_error("abrade: run failed: ", e.what());
      return 3;
    }
  catch (const std::exception &e)
    {
      // not an input problem (those are InputErrors): a bug, and what to report
      print_error("abrade: internal error: ", std::string(e.what()) + " (a bug in abrade " + version_string +
                                           ", not in the input: please report it with the command line, the "
                                           "parameter file and this line)");
      return 1;
    }
  catch (...)
    {
      print_error("abrade: internal error: ", std::string("an exception of unknown type (a bug in abrade ") +
                                           version_string + ": please report it with the command line and the "
                                                            "parameter file)");
      return 1;
    }
}
