// The run's log: to the terminal and to log.txt (log.h).
#include <abrade/common/log.h>

#include <iostream>

namespace abrade::io
{
  void Log::line(const std::string &text)
  {
    if (echo)
      std::cout << text << std::endl;
    if (file)
      file << text << std::endl;
  }
} // namespace abrade::io
