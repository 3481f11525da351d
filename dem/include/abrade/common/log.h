#pragma once
// Run log: every line goes to stdout and to the run's log.txt. Warnings are prefixed.
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace abrade::io
{
  class Log
  {
  public:
    void open(const std::string &path) { file.open(path, std::ios::app); }
    /// Whether lines also go to stdout (off on MPI ranks > 0).
    void set_echo(bool on) { echo = on; }
    void line(const std::string &text);
    void warning(const std::string &text)
    {
      given.push_back(text);
      line("warning: " + text);
    }
    /// The warnings given since the last call (a quiet log passes its warnings on this way).
    std::vector<std::string> take_warnings()
    {
      std::vector<std::string> w;
      w.swap(given);
      return w;
    }
    /// Only into log.txt (for what is printed elsewhere, such as the final error on stderr).
    void file_only(const std::string &text)
    {
      if (file)
        file << text << std::endl;
    }

  private:
    std::ofstream            file;
    bool                     echo = true;
    std::vector<std::string> given;
  };
} // namespace abrade::io
