#pragma once
// A small ordered JSON value for writing run summaries (summary.json). Writing only: abrade reads
// its input from deal.II parameter files, never from JSON.
#include <map>
#include <memory>
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
} // namespace abrade::io
