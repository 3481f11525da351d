// CSV files with a fixed header, rows by position or by column name (csv_writer.h).
#include <abrade/common/csv_writer.h>
#include <abrade/common/error.h>

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace abrade::io
{
  CsvWriter::CsvWriter(const std::string &path, const std::vector<std::string> &columns)
  {
    open(path, columns);
  }

  void CsvWriter::open(const std::string &p, const std::vector<std::string> &columns)
  {
    path = p;
    out.open(path);
    if (!out)
      throw RunError("cannot write CSV file " + path);
    n_columns = columns.size();
    names     = columns;
    for (std::size_t i = 0; i < columns.size(); ++i)
      out << (i ? "," : "") << columns[i];
    out << '\n' << std::setprecision(10);
  }

  std::string CsvWriter::row(const std::vector<double> &values)
  {
    if (values.size() != n_columns)
      throw std::logic_error("CSV row width mismatch in " + path);
    std::ostringstream line;
    line << std::setprecision(10);
    for (std::size_t i = 0; i < values.size(); ++i)
      line << (i ? "," : "") << values[i];
    out << line.str() << '\n';
    check();
    return line.str();
  }

  void CsvWriter::raw_row(const std::string &line)
  {
    out << line << '\n';
    check();
  }

  void CsvWriter::flush()
  {
    out.flush();
    check();
  }

  void CsvWriter::close()
  {
    if (!out.is_open())
      return;
    out.close();
    check();
  }

  void CsvWriter::check()
  {
    if (!out)
      throw RunError("cannot write " + path + " (disk full, or not writable?)");
  }

  std::string CsvWriter::named_row(const std::vector<std::pair<std::string, double>> &named)
  {
    std::vector<double> values(n_columns);
    std::vector<char>   given(n_columns, 0);
    for (const auto &[name, value] : named)
      {
        const auto at = std::find(names.begin(), names.end(), name);
        if (at == names.end() || given[std::size_t(at - names.begin())])
          throw std::logic_error("CSV column " + name + (at == names.end() ? " is not in " : " given twice in ") + path);
        given[std::size_t(at - names.begin())] = 1;
        values[std::size_t(at - names.begin())] = value;
      }
    for (std::size_t i = 0; i < n_columns; ++i)
      if (!given[i])
        throw std::logic_error("CSV column " + names[i] + " has no value in a row of " + path);
    return row(values);
  }

  void CsvWriter::row(const std::string &label, const std::vector<double> &values)
  {
    if (values.size() + 1 != n_columns)
      throw std::logic_error("CSV row width mismatch in " + path);
    out << label;
    for (double v : values)
      out << ',' << v;
    out << '\n';
    check();
  }
} // namespace abrade::io
