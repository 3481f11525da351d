// CSV tables read back, with the file and line of every error (csv_reader.h).
#include <abrade/common/csv_reader.h>
#include <abrade/common/error.h>
#include <abrade/common/input_file.h>

#include <fstream>

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

  namespace
  {
    /// The cells of one line, trimmed: separated by commas outside double quotes (RFC 4180:
    /// "a, b" is one cell, "" inside quotes is a quote).
    std::vector<std::string> split_cells(const std::string &line, const std::string &where)
    {
      std::vector<std::string> cells(1);
      bool                     quoted = false;
      for (std::size_t k = 0; k < line.size(); ++k)
        {
          const char c = line[k];
          if (quoted && c == '"' && k + 1 < line.size() && line[k + 1] == '"')
            cells.back() += '"', ++k;
          else if (c == '"')
            quoted = !quoted;
          else if (c == ',' && !quoted)
            cells.emplace_back();
          else
            cells.back() += c;
        }
      if (quoted)
        throw InputError(where, "a quote that is not closed");
      for (auto &cell : cells)
        {
          const auto b = cell.find_first_not_of(" \t\r"), e = cell.find_last_not_of(" \t\r");
          cell         = b == std::string::npos ? "" : cell.substr(b, e - b + 1);
        }
      return cells;
    }
  } // namespace

  CsvTable read_csv(const std::string &path)
  {
    require_input_file(path);
    std::ifstream in(path);
    if (!in)
      throw InputError(path, "cannot read the file");
    CsvTable t;
    t.file = path;
    std::string text;
    for (long number = 1; std::getline(in, text); ++number)
      {
        if (number == 1 && text.compare(0, 3, "\xEF\xBB\xBF") == 0) // a UTF-8 byte order mark (Excel)
          text.erase(0, 3);
        const auto first = text.find_first_not_of(" \t\r");
        if (first == std::string::npos || text[first] == '#')
          continue;
        const std::vector<std::string> cells = split_cells(text, path + ":" + std::to_string(number));
        if (t.header.empty())
          {
            t.header = cells;
            for (std::size_t c = 0; c < cells.size(); ++c)
              for (std::size_t d = 0; d < c; ++d)
                if (cells[c] == cells[d])
                  throw InputError(path + ":" + std::to_string(number), "column '" + cells[c] + "' comes twice");
          }
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
