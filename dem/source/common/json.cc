// A small JSON value for summary.json and its kin: built, dumped, written at once (json.h).
#include <abrade/common/atomic_file.h>
#include <abrade/common/error.h>
#include <abrade/common/json.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <regex>

namespace abrade::io
{
  Json::Json(const std::vector<double> &v) : value(Array(v.begin(), v.end())) {}

  Json &Json::operator[](const std::string &key)
  {
    if (std::holds_alternative<std::nullptr_t>(value))
      value = Object();
    auto &obj = std::get<Object>(value);
    for (auto &kv : obj)
      if (kv.first == key)
        return kv.second;
    obj.emplace_back(key, Json());
    return obj.back().second;
  }

  void Json::push_back(Json v)
  {
    if (std::holds_alternative<std::nullptr_t>(value))
      value = Array();
    std::get<Array>(value).push_back(std::move(v));
  }

  namespace
  {
    void escape(std::string &out, const std::string &s)
    {
      out += '"';
      for (char c : s)
        switch (c)
          {
            case '"': out += "\\\""; break;
            case '\\': out += "\\\\"; break;
            case '\n': out += "\\n"; break;
            case '\t': out += "\\t"; break;
            default:
              if (static_cast<unsigned char>(c) < 0x20)
                {
                  char buf[8];
                  std::snprintf(buf, sizeof buf, "\\u%04x", c);
                  out += buf;
                }
              else
                out += c;
          }
      out += '"';
    }
  } // namespace

  void Json::dump(std::string &out, int indent, int level) const
  {
    const std::string pad(indent * (level + 1), ' '), pad_end(indent * level, ' ');
    const char       *nl = indent ? "\n" : "";
    if (std::holds_alternative<std::nullptr_t>(value))
      out += "null";
    else if (auto b = std::get_if<bool>(&value))
      out += *b ? "true" : "false";
    else if (auto d = std::get_if<double>(&value))
      {
        if (!std::isfinite(*d))
          out += "null";
        else
          {
            char buf[32];
            std::snprintf(buf, sizeof buf, "%.12g", *d);
            out += buf;
          }
      }
    else if (auto s = std::get_if<std::string>(&value))
      escape(out, *s);
    else if (auto o = std::get_if<Object>(&value))
      {
        out += '{';
        for (std::size_t i = 0; i < o->size(); ++i)
          {
            out += (i ? "," : "");
            out += nl + pad;
            escape(out, (*o)[i].first);
            out += indent ? ": " : ":";
            (*o)[i].second.dump(out, indent, level + 1);
          }
        out += (o->empty() ? "" : nl + pad_end) + "}";
      }
    else
      {
        const auto &a = std::get<Array>(value);
        out += '[';
        for (std::size_t i = 0; i < a.size(); ++i)
          {
            out += (i ? ", " : "");
            a[i].dump(out, 0, 0);
          }
        out += ']';
      }
  }

  std::string Json::dump(int indent) const
  {
    std::string out;
    dump(out, indent, 0);
    return out + "\n";
  }

  void Json::write(const std::string &path) const
  {
    write_file_atomically(path, dump()); // checked; a crash leaves the old summary or the new one
  }

  namespace
  {
    /// The first match of @p pattern (its group 1) after "@p key": in the file @p path.
    std::optional<std::string> summary_match(const std::string &path, const std::string &key, const std::string &pattern)
    {
      std::ifstream     in(path);
      const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      std::smatch       m;
      if (std::regex_search(text, m, std::regex("\"" + key + "\": *" + pattern)))
        return m[1].str();
      return std::nullopt;
    }
  } // namespace

  std::optional<double> summary_number(const std::string &path, const std::string &key)
  {
    const auto v = summary_match(path, key, "([-+0-9.eE]+)");
    return v ? std::optional<double>(std::stod(*v)) : std::nullopt;
  }

  std::optional<std::string> summary_string(const std::string &path, const std::string &key)
  {
    return summary_match(path, key, "\"([^\"]*)\"");
  }
} // namespace abrade::io
