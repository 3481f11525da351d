#pragma once
// Errors that reach the user. An InputError is a problem with what the user gave us (a
// parameter file, a mesh, a scan, a command line): the CLI prints its one-line message and exits
// with code 2. A RunError is a problem found while running (NaN, lost particle, inverted cell):
// exit code 3.
#include <stdexcept>
#include <string>

namespace abrade
{
  class InputError : public std::runtime_error
  {
  public:
    /// @p where names the file (with ":line" when known), @p what says what is wrong.
    InputError(const std::string &where, const std::string &what)
      : std::runtime_error(where.empty() ? what : where + ": " + what)
    {}
  };

  class RunError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };
} // namespace abrade
