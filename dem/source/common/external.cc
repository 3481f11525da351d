#include <abrade/common/external.h>

#include <cstdlib>
#include <iostream>

namespace abrade::io
{
  std::string shell_quote(const std::string &s)
  {
    std::string q = "'";
    for (char c : s)
      q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  }

  bool run_gnuplot(const std::string &directory, const std::string &script, bool quiet)
  {
    const std::string command =
      "cd " + shell_quote(directory) + " && gnuplot " + shell_quote(script) + " > " + shell_quote(script + ".log") + " 2>&1";
    const bool ok = std::system(command.c_str()) == 0;
    if (!ok && !quiet)
      std::cerr << "warning: gnuplot failed or is missing (scripts/install-deps.sh installs it); the plot script is "
                << directory << "/" << script << " (its output: " << script << ".log)" << std::endl;
    return ok;
  }
} // namespace abrade::io
