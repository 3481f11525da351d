#pragma once
// A small ordered JSON value for writing run summaries (summary.json). Input comes from deal.II
// parameter files, never from JSON; studies that read a finished run's summary back only look a
// number up (summary_number).
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace abrade::io
{
  class Json
  {
  public:
    Json() : value(nullptr) {}
    Json(double v) : value(v) {}
    Json(int v) : value(static_cast<double>(v)) {}
    Json(long v) : value(static_cast<double>(v)) {}
    Json(unsigned long v) : value(static_cast<double>(v)) {}
    Json(unsigned int v) : value(static_cast<double>(v)) {}
    Json(bool v) : value(v) {}
    Json(const char *v) : value(std::string(v)) {}
    Json(std::string v) : value(std::move(v)) {}
    Json(const std::vector<double> &v);

    /// Object access: creates the key (in insertion order) when missing.
    Json &operator[](const std::string &key);
    /// Appends to an array (turns a null value into an array).
    void push_back(Json v);

    /// The value as a number (0 if it is not one).
    double number() const
    {
      auto d = std::get_if<double>(&value);
      return d ? *d : 0.0;
    }
    std::string dump(int indent = 2) const;
    void        write(const std::string &path) const;

  private:
    using Object = std::vector<std::pair<std::string, Json>>;
    using Array  = std::vector<Json>;
    std::variant<std::nullptr_t, bool, double, std::string, Object, Array> value;
    void dump(std::string &out, int indent, int level) const;
  };

  /// The first number stored under @p key in the summary.json file @p path (keys are unique in
  /// a run's results); nothing when the file or the key is missing.
  std::optional<double> summary_number(const std::string &path, const std::string &key);
  /// The first string value of @p key in the JSON file @p path, if any.
  std::optional<std::string> summary_string(const std::string &path, const std::string &key);
} // namespace abrade::io
