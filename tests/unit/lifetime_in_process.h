#pragma once
// A lifetime run inside a test program (the toy plugins' tests): the analytic case
// tests/lifetime/analytic_uniform.prm with @p sets, into a fresh directory @p name under the
// system's temporary directory; returns summary.json's results (the directory: @p dir).
#include <abrade/common/json.h>
#include <abrade/common/log.h>
#include <abrade/common/output_directory.h>
#include <abrade/common/timer.h>
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/parameters/parameter_file.h>

#include <filesystem>
#include <string>
#include <vector>

inline abrade::io::Json run_analytic_lifetime(const std::string &name, std::vector<std::string> sets,
                                              std::string *dir = nullptr)
{
  const std::string out_dir = std::filesystem::temp_directory_path().string() + "/" + name;
  std::filesystem::remove_all(out_dir);
  sets.push_back("Output/Directory=" + out_dir);
  abrade::coupling::ParameterFile params(std::string(ABRADE_TESTS_DIR) + "/lifetime/analytic_uniform.prm", sets);
  abrade::io::OutputDirectory     out(out_dir);
  abrade::io::Json                results;
  abrade::io::Timers              timers;
  abrade::io::Log                 log;
  log.set_echo(false);
  abrade::coupling::JobContext ctx{params, out, results, timers, log};
  abrade::coupling::make_job("lifetime")->run(ctx);
  if (dir)
    *dir = out_dir;
  return results;
}
