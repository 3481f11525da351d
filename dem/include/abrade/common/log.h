#pragma once
// Run log: every line goes to stdout and to the run's log.txt. Warnings are prefixed.
#include <fstream>
#include <sstream>
#include <string>

namespace abrade::io
{
  class Log
  {
  public:
    void open(const std::string &path) { file.open(path, std::ios::app); }
    void line(const std::string &text);
    void warning(const std::string &text) { line("warning: " + text); }

  private:
    std::ofstream file;
  };
} // namespace abrade::io
