#pragma once
// A CSV file with a fixed header: one call per row, values written with full precision.
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace abrade::io
{
  class CsvWriter
  {
  public:
    CsvWriter() = default;
    CsvWriter(const std::string &path, const std::vector<std::string> &columns);
    void open(const std::string &path, const std::vector<std::string> &columns);
    bool is_open() const { return out.is_open(); }

    /// Writes one row; the number of values must match the header. Returns the row's text
    /// (without its newline), as raw_row takes it back.
    std::string row(const std::vector<double> &values);
    /// Writes one row given as (column, value) pairs, in any order: each of the header's
    /// columns exactly once (else std::logic_error naming the column: a bug). Returns the row's
    /// text as row() does.
    std::string named_row(const std::vector<std::pair<std::string, double>> &named);
    /// Writes one row whose first column is text (a name, a phase).
    void row(const std::string &label, const std::vector<double> &values);
    /// Writes a row given as text (rows kept from an earlier, resumed run).
    void raw_row(const std::string &line);
    /// Hands what is buffered to the file; RunError naming it when the write failed (a full
    /// disk), as every row does once the buffer is written.
    void flush();
    /// Flushes and closes the file (RunError as flush): the last rows' write checked too.
    void close();

  private:
    void          check();
    std::ofstream out;
    std::string   path;
    std::size_t   n_columns = 0;
    std::vector<std::string> names; ///< the header's columns
  };
} // namespace abrade::io
