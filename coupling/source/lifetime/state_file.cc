// The lifetime loop's state file (key = value, with a checksum): what a resumed run starts from
// (state_file.h).
#include <abrade/common/error.h>
#include <abrade/common/file_extension.h>
#include <abrade/common/finite_number.h>
#include <abrade/common/hash.h>
#include <abrade/coupling/lifetime/state_file.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

namespace abrade::coupling
{
  namespace
  {
    std::string format(double x)
    {
      char buffer[40];
      std::snprintf(buffer, sizeof buffer, "%.17g", x);
      return buffer;
    }

  } // namespace

  namespace
  {
    const std::string checksum_key = "checksum";
  }

  StateFile StateFile::read(const std::string &path)
  {
    std::ifstream in(path, std::ios::binary);
    if (!in)
      throw InputError(path, "cannot read the state file");
    const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // the last line is the checksum of everything before it: a changed or cut file is named,
    // never read as state
    const auto last = all.rfind(checksum_key + " = ");
    if (last == std::string::npos || (last > 0 && all[last - 1] != '\n'))
      throw InputError(path, "no checksum line (cut short, or written by an older abrade): start afresh without --resume");
    const std::string stored = io::trimmed(all.substr(last + checksum_key.size() + 3));
    if (stored != io::fnv1a_hex(all.substr(0, last)))
      throw InputError(path, "corrupt state file (its checksum does not match: changed or cut); start afresh "
                             "without --resume");
    StateFile          s;
    s.path = path;
    std::istringstream lines(all.substr(0, last));
    int                n = 0;
    for (std::string line; std::getline(lines, line);)
      {
        ++n;
        if (io::trimmed(line).empty() || io::trimmed(line)[0] == '#')
          continue;
        const auto eq = line.find('=');
        if (eq == std::string::npos)
          throw InputError(path + ":" + std::to_string(n), "expected 'key = value', found '" + line.substr(0, 80) + "'");
        const std::string key = io::trimmed(line.substr(0, eq));
        s.set(key, io::trimmed(line.substr(eq + 1)));
        s.line_of[key] = n;
      }
    return s;
  }

  void StateFile::write(const std::string &file) const
  {
    std::ostringstream text;
    for (const auto &key : order)
      text << key << " = " << values.at(key) << '\n';
    std::ofstream out(file, std::ios::binary);
    out << text.str() << checksum_key << " = " << io::fnv1a_hex(text.str()) << '\n';
    out.close();
    if (!out)
      throw RunError("cannot write " + file);
  }

  void StateFile::set(const std::string &key, const std::string &value)
  {
    if (!values.count(key))
      order.push_back(key);
    values[key] = value;
  }

  void StateFile::set(const std::string &key, double value) { set(key, format(value)); }

  void StateFile::set(const std::string &key, const std::vector<double> &v)
  {
    std::string s;
    for (std::size_t k = 0; k < v.size(); ++k)
      s += (k ? " " : "") + format(v[k]);
    set(key, s);
  }

  std::string StateFile::where(const std::string &key) const
  {
    const auto it = line_of.find(key);
    return it == line_of.end() ? path : path + ":" + std::to_string(it->second);
  }

  const std::string &StateFile::text(const std::string &key) const
  {
    const auto it = values.find(key);
    if (it == values.end())
      throw InputError(path, "no '" + key + "' in the state file (corrupt, or written by another version)");
    return it->second;
  }

  double StateFile::number(const std::string &key) const
  {
    const std::vector<double> v = numbers(key);
    if (v.size() != 1)
      throw InputError(where(key), "'" + key + "' must be one number");
    return v[0];
  }

  std::vector<double> StateFile::numbers(const std::string &key) const
  {
    std::vector<double> out;
    std::istringstream  in(text(key));
    for (std::string word; in >> word;)
      {
        const auto x = io::finite_number(word); // (a subnormal reads back as written)
        if (!x)
          throw InputError(where(key), "'" + key + "': '" + word.substr(0, 40) + "' is not a finite number");
        out.push_back(*x);
      }
    return out;
  }
} // namespace abrade::coupling
