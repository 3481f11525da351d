// The options the run-like commands share (command_line.h).
#include "command_line.h"

#include <abrade/common/error.h>
#include <abrade/report/report.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <utility>

namespace abrade::app
{
  namespace
  {
    int integer(const std::string &flag, const std::string &v)
    {
      try
        {
          std::size_t used = 0;
          const int   n    = std::stoi(v, &used);
          if (used == v.size())
            return n;
        }
      catch (const std::exception &)
        {
        }
      throw InputError("command line", flag + " needs a whole number, got '" + v + "'");
    }

    double number(const std::string &flag, const std::string &v)
    {
      try
        {
          std::size_t  used = 0;
          const double x    = std::stod(v, &used);
          if (used == v.size() && std::isfinite(x))
            return x;
        }
      catch (const std::exception &)
        {
        }
      throw InputError("command line", flag + " needs a number, got '" + v + "'");
    }

  } // namespace

  std::vector<int> seed_list(const std::string &text)
  {
    std::vector<int>  seeds;
    std::stringstream ss(text);
    for (std::string s; std::getline(ss, s, ',');)
      {
        const int seed = integer("--seeds", s);
        if (seed < 0)
          throw InputError("command line", "--seeds: a seed is 0 or more, got " + s);
        if (std::find(seeds.begin(), seeds.end(), seed) != seeds.end())
          throw InputError("command line", "--seeds: seed " + s + " is given twice (the same bed twice is no replicate)");
        seeds.push_back(seed);
      }
    return seeds;
  }

  std::string output_option(const std::vector<std::string> &args)
  {
    for (std::size_t k = 0; k < args.size(); ++k)
      {
        const std::string &a = args[k];
        if ((a == "--output" || a == "-o") && k + 1 < args.size())
          return args[k + 1];
        if (a.rfind("--output=", 0) == 0)
          return a.substr(9);
      }
    return "";
  }

  int with_report(int rc, const std::string &directory)
  {
    if (rc != 0 || directory.empty())
      return rc;
    try
      {
        std::cout << "Report: " << report::write_report(directory) << std::endl;
      }
    catch (const std::exception &e)
      {
        std::cerr << "warning: no report written: " << e.what() << std::endl;
      }
    return rc;
  }

  CommandLine parse(const std::string &command, const std::vector<std::string> &args, const std::string &typed,
                    const std::vector<std::string> &takes)
  {
    CommandLine cl;
    cl.command_line = typed;
    cl.command      = command;
    const std::vector<std::string> &a = args;
    auto taken = [&](const std::string &what) { return std::find(takes.begin(), takes.end(), what) != takes.end(); };
    auto refuse = [&](const std::string &what) {
      std::string list;
      for (const auto &t : takes)
        list += (list.empty() ? "" : ", ") + t;
      throw InputError("command line", "abrade " + command + " does not take " + what + " (it takes " +
                                         (list.empty() ? std::string("nothing") : list) + ")");
    };
    static const std::vector<std::string> options = {"--set",   "--output", "--format", "--vary",
                                                     "--edge-height", "--seeds", "--wall", "--jobs",
                                                     "--knives", "--lifetime-updates", "--quiet", "--resume"};
    for (std::size_t k = 0; k < a.size(); ++k)
      {
        // an option this command has no use for is refused, not ignored (convert --set ...)
        {
          const std::string flag = a[k] == "-o" ? "--output" : a[k] == "-q" ? "--quiet" : a[k].substr(0, a[k].find('='));
          if (std::find(options.begin(), options.end(), flag) != options.end() && !taken(flag))
            refuse(flag);
          if ((a[k].empty() || a[k][0] != '-') && !taken("FILE") && !taken("FILES"))
            refuse("a file ('" + a[k] + "')");
        }
        auto value = [&](const std::string &flag) {
          if (k + 1 >= a.size())
            throw InputError("command line", flag + " needs a value");
          if (a[k + 1].empty())
            throw InputError("command line", flag + " needs a value (it is empty)");
          return a[++k];
        };
        if (a[k] == "--set")
          cl.sets.push_back(value("--set"));
        else if (a[k].rfind("--set=", 0) == 0)
          cl.sets.push_back(a[k].substr(6));
        else if (a[k] == "--output" || a[k] == "-o")
          cl.output = value("--output");
        else if (a[k] == "--format")
          cl.format = value("--format");
        else if (a[k] == "--vary")
          cl.varies.push_back(value("--vary"));
        else if (a[k] == "--edge-height")
          cl.edge_height = number("--edge-height", value("--edge-height"));
        else if (a[k] == "--seeds")
          cl.seeds = value("--seeds");
        else if (a[k] == "--wall")
          cl.wall = value("--wall");
        else if (a[k] == "--jobs")
          {
            cl.jobs = integer("--jobs", value("--jobs"));
            if (cl.jobs < 0)
              throw InputError("command line", "--jobs must be 0 (one per core) or more, got " + a[k]);
          }
        else if (a[k] == "--knives")
          cl.knives = value("--knives");
        else if (a[k] == "--lifetime-updates")
          cl.lifetime_updates = integer("--lifetime-updates", value("--lifetime-updates"));
        else if (a[k] == "--quiet" || a[k] == "-q")
          cl.quiet = true;
        else if (a[k] == "--resume")
          cl.resume = true;
        else if (!a[k].empty() && a[k][0] == '-')
          throw InputError("command line", "unknown option '" + a[k] + "'");
        else if (cl.file.empty())
          cl.file = a[k];
        else if (taken("FILES"))
          cl.more_files.push_back(a[k]);
        else
          throw InputError("command line", "more than one parameter file given ('" + cl.file + "', '" + a[k] + "')");
      }
    return cl;
  }

  Launch launch()
  {
    Launch l;
    for (const auto &[rank, size] : {std::pair{"OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE"}, {"PMI_RANK", "PMI_SIZE"}})
      if (const char *n = std::getenv(size))
        {
          const char *r = std::getenv(rank);
          return {true, r ? std::atoi(r) : 0, std::atoi(n)};
        }
    return l;
  }

} // namespace abrade::app
