// External programs: shell quoting, and gnuplot run beside its data (external.h).
#include <abrade/common/external.h>

#include <abrade/common/error.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <sys/wait.h>

namespace abrade::io
{
  std::string shell_quote(const std::string &s)
  {
    std::string q = "'";
    for (char c : s)
      q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  }

  namespace
  {
    int gnuplot_status(const std::string &directory, const std::string &script)
    {
      // (the log by its absolute path: what the run writes is named inside its directory, also
      // for a tracer of the file calls that does not follow the shell's cd)
      std::error_code   ec;
      const std::string log = (std::filesystem::absolute(directory, ec) / (script + ".log")).string();
      const std::string command = "cd " + shell_quote(directory) + " && gnuplot " + shell_quote(script) + " > " +
                                  shell_quote(log) + " 2>&1";
      return std::system(command.c_str());
    }
  } // namespace

  void run_gnuplot_for(const std::string &directory, const std::string &script, const std::vector<std::string> &outputs)
  {
    const int status = gnuplot_status(directory, script);
    if (status != 0 && WIFEXITED(status) && WEXITSTATUS(status) == 127) // the shell found no gnuplot
      {
        std::cerr << "warning: gnuplot is missing (scripts/install-deps.sh installs it): no pictures; their script is "
                  << directory << "/" << script << std::endl;
        return;
      }
    for (const auto &o : outputs)
      {
        std::error_code ec;
        const auto      path = std::filesystem::path(directory) / o;
        if (status != 0 || !std::filesystem::is_regular_file(path, ec) || std::filesystem::file_size(path, ec) == 0)
          {
            std::ifstream log(directory + "/" + script + ".log");
            std::string   line, last;
            while (std::getline(log, line))
              if (!line.empty())
                last = line;
            throw RunError("cannot write " + path.string() + " (gnuplot " +
                           (last.empty() ? std::string("wrote nothing") : "said: " + last.substr(0, 200)) +
                           "; a full disk?)");
          }
      }
  }

  bool run_gnuplot(const std::string &directory, const std::string &script, bool quiet)
  {
    const bool ok = gnuplot_status(directory, script) == 0;
    if (!ok && !quiet)
      std::cerr << "warning: gnuplot failed or is missing (scripts/install-deps.sh installs it); the plot script is "
                << directory << "/" << script << " (its output: " << script << ".log)" << std::endl;
    return ok;
  }
} // namespace abrade::io
