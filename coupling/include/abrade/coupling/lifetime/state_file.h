#pragma once
// A small `key = value` file: the lifetime loop's resume state (and anything else that must be
// read back exactly). Numbers are written with 17 significant digits, so they read back bit for
// bit (a resumed run continues byte-identically); lists are space separated. Every key is
// written by name, so adding a field cannot shift the others; reading a key that is missing, or
// a value that is not a finite number, is an InputError naming the file and the line. The last
// line is a checksum (64-bit FNV-1a of all before it): a file changed by hand, cut short by a
// crash or written by an older version is refused when it is read, never taken as state.
#include <map>
#include <string>
#include <vector>

namespace abrade::coupling
{
  class StateFile
  {
  public:
    StateFile() = default;
    /// Reads @p path (InputError naming it when it cannot be read, its checksum does not match
    /// or a line has no '=').
    static StateFile read(const std::string &path);
    /// Writes to @p path (RunError when the write fails).
    void write(const std::string &path) const;

    void set(const std::string &key, const std::string &value);
    void set(const std::string &key, double value);
    void set(const std::string &key, const std::vector<double> &values);

    const std::string  &text(const std::string &key) const;
    double              number(const std::string &key) const;
    std::vector<double> numbers(const std::string &key) const;
    bool                has(const std::string &key) const { return values.count(key) > 0; }

  private:
    std::string                        path;
    std::map<std::string, std::string> values;
    std::map<std::string, int>         line_of;
    std::vector<std::string>           order;
    std::string                        where(const std::string &key) const;
  };
} // namespace abrade::coupling
