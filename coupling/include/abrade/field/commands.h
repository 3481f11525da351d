#pragma once
// The command-line front ends of field comparison and calibration (`abrade compare`,
// `abrade calibrate`): each parses its own options and returns the process exit code.
#include <string>
#include <vector>

namespace abrade::field
{
  extern const char *compare_usage;
  extern const char *calibrate_usage;
  int run_compare_command(const std::vector<std::string> &args);
  int run_calibrate_command(const std::vector<std::string> &args);
} // namespace abrade::field
