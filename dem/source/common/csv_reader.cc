#include <abrade/common/csv_reader.h>
#include <abrade/common/error.h>

#include <fstream>
#include <sstream>

namespace abrade::io
{
  int CsvTable::find(const std::string &name) const
  {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == name)
        return static_cast<int>(c);
    return -1;
  }

  int CsvTable::column(const std::string &name) const
  {
    const int c = find(name);
    if (c < 0)
      throw RunError(file + ": no column '" + name + "'");
    return c;
  }

  CsvTable read_csv(const std::string &path)
  {
    std::ifstream in(path);
    if (!in)
      throw InputError(path, "file not found");
    CsvTable t;
    t.file = path;
    std::string text;
    for (long number = 1; std::getline(in, text); ++number)
      {
        const auto first = text.find_first_not_of(" \t\r");
        if (first == std::string::npos || text[first] == '#')
          continue;
        std::vector<std::string> cells;
        std::stringstream        s(text);
        for (std::string cell; std::getline(s, cell, ',');)
          {
            const auto b = cell.find_first_not_of(" \t\r"), e = cell.find_last_not_of(" \t\r");
            cells.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
          }
        if (t.header.empty())
          t.header = std::move(cells);
        else if (cells.size() != t.header.size())
          throw InputError(path + ":" + std::to_string(number),
                           std::to_string(cells.size()) + " cells, the header has " + std::to_string(t.header.size()) +
                             " (a comma inside a value, or a cell missing?)");
        else
          t.rows.push_back(std::move(cells)), t.line.push_back(number);
      }
    return t;
  }
} // namespace abrade::io
