#pragma once
// Reading CSV tables back: the runs' own output tables (studies made of many runs) and users'
// measurement tables. Cells are trimmed; blank lines and lines starting with '#' are skipped;
// the first line left is the header.
#include <string>
#include <vector>

namespace abrade::io
{
  struct CsvTable
  {
    std::string                           file;
    std::vector<std::string>              header;
    std::vector<std::vector<std::string>> rows;
    std::vector<long>                     line; ///< the file's line number of each row

    /// The index of column @p name, or -1.
    int find(const std::string &name) const;
    /// The index of column @p name; RunError naming the file if there is none (for tables
    /// abrade wrote itself).
    int column(const std::string &name) const;
  };

  /// Reads @p path; throws InputError naming it when it cannot be opened, and naming the line
  /// when a row has more or fewer cells than the header. A file without a header comes back
  /// with an empty header.
  CsvTable read_csv(const std::string &path);
} // namespace abrade::io
