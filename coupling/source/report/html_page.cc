// The run report's page: headings, tables, pictures inlined as data URIs, warnings, the whole
// page one self-contained HTML file (html_page.h).
#include "html_page.h"

#include <vtkBase64Utilities.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace abrade::report
{
  std::string escape_html(const std::string &text)
  {
    std::string out;
    for (std::size_t i = 0; i < text.size();)
      {
        const auto c = static_cast<unsigned char>(text[i]);
        // the length of a UTF-8 sequence starting here (0: not a valid start)
        const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
        bool valid = n > 0 && i + n <= text.size();
        for (std::size_t k = 1; valid && k < n; ++k)
          valid = (static_cast<unsigned char>(text[i + k]) >> 6) == 0x2;
        if (!valid)
          {
            out += "\xEF\xBF\xBD"; // U+FFFD
            ++i;
            continue;
          }
        switch (text[i])
          {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out.append(text, i, n);
          }
        i += n;
      }
    return out;
  }

  namespace
  {
    /// Width and height of a PNG from its IHDR chunk (0, 0 if it is not one).
    std::pair<unsigned, unsigned> png_size(const std::string &bytes)
    {
      if (bytes.size() < 24 || bytes.compare(1, 3, "PNG") != 0)
        return {0, 0};
      auto be32 = [&](std::size_t at) {
        return (unsigned(static_cast<unsigned char>(bytes[at])) << 24) |
               (unsigned(static_cast<unsigned char>(bytes[at + 1])) << 16) |
               (unsigned(static_cast<unsigned char>(bytes[at + 2])) << 8) | unsigned(static_cast<unsigned char>(bytes[at + 3]));
      };
      return {be32(16), be32(20)};
    }

    const char *style = R"(
body { font-family: "DejaVu Sans", Arial, sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em; color: #222; }
h1 { font-size: 1.6em; border-bottom: 2px solid #444; padding-bottom: .2em; }
h2 { font-size: 1.25em; margin-top: 1.6em; border-bottom: 1px solid #bbb; }
.headline { font-size: 1.35em; background: #eef3f8; border-left: 6px solid #2a6ebb; padding: .6em 1em; margin: 1em 0; }
figure { margin: 1em 0; page-break-inside: avoid; }
figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }
figcaption { font-size: .9em; color: #555; }
table { border-collapse: collapse; font-size: .85em; margin: .5em 0; }
.scroll { overflow-x: auto; }
th, td { border: 1px solid #ccc; padding: .2em .5em; text-align: right; }
th { background: #f0f0f0; }
td:first-child, th:first-child { text-align: left; }
.warnings li { color: #8a4b00; }
.none { color: #555; font-style: italic; }
pre { font-size: .8em; background: #f7f7f7; padding: .5em; overflow-x: auto; }
@media print { body { max-width: none; margin: 0; } h2 { page-break-after: avoid; } details { display: block; }
  .scroll { overflow: visible; } table { font-size: .7em; } }
)";
  } // namespace

  HtmlPage::HtmlPage(const std::string &title) : title(title) { heading(title, 1); }

  void HtmlPage::heading(const std::string &text, int level)
  {
    body << "<h" << level << ">" << escape_html(text) << "</h" << level << ">\n";
  }

  void HtmlPage::paragraph(const std::string &html) { body << "<p>" << html << "</p>\n"; }

  void HtmlPage::headline(const std::string &html) { body << "<div class=\"headline\">" << html << "</div>\n"; }

  void HtmlPage::png(const std::string &file, const std::string &caption, const std::string &figure)
  {
    std::error_code   e; // (a regular file only: a link to a device such as /dev/full never ends)
    const bool        regular = std::filesystem::is_regular_file(file, e) && std::filesystem::file_size(file, e) < 100u << 20;
    std::ifstream     in(regular ? file : std::string(), std::ios::binary);
    const std::string bytes = regular ? std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>())
                                      : std::string();
    const auto [w, h] = png_size(bytes);
    if (w == 0)
      {
        body << "<p class=\"none\" data-missing-figure=\"" << escape_html(std::filesystem::path(file).filename().string())
             << "\">(no picture: " << escape_html(file) << " is missing or not a PNG)</p>\n";
        return;
      }
    std::string encoded(4 * ((bytes.size() + 2) / 3) + 1, '\0');
    const auto  n = vtkBase64Utilities::Encode(reinterpret_cast<const unsigned char *>(bytes.data()),
                                              static_cast<unsigned long>(bytes.size()),
                                              reinterpret_cast<unsigned char *>(encoded.data()));
    encoded.resize(n);
    body << "<figure data-figure=\"" << escape_html(figure) << "\"><img src=\"data:image/png;base64," << encoded << "\" width=\"" << w << "\" height=\"" << h
         << "\" data-width=\"" << w << "\" data-height=\"" << h << "\" alt=\"" << escape_html(caption)
         << "\"><figcaption>" << escape_html(caption) << "</figcaption></figure>\n";
  }

  void HtmlPage::table(const std::vector<std::string> &header, const std::vector<std::vector<std::string>> &rows)
  {
    body << "<div class=\"scroll\"><table>";
    if (std::any_of(header.begin(), header.end(), [](const std::string &h) { return !h.empty(); }))
      {
        body << "<thead><tr>";
        for (const auto &h : header)
          body << "<th>" << escape_html(h) << "</th>";
        body << "</tr></thead>";
      }
    body << "<tbody>\n";
    for (const auto &r : rows)
      {
        body << "<tr>";
        for (const auto &c : r)
          body << "<td>" << escape_html(c) << "</td>";
        body << "</tr>\n";
      }
    body << "</tbody></table></div>\n";
  }

  void HtmlPage::warnings(const std::vector<std::string> &list)
  {
    if (list.empty())
      {
        body << "<p class=\"none\" id=\"warnings\">No warnings.</p>\n";
        return;
      }
    body << "<ul class=\"warnings\" id=\"warnings\">\n";
    for (const auto &w : list)
      body << "<li>" << escape_html(w) << "</li>\n";
    body << "</ul>\n";
  }

  void HtmlPage::details(const std::string &summary, const std::string &text)
  {
    body << "<details><summary>" << escape_html(summary) << "</summary><pre>" << escape_html(text)
         << "</pre></details>\n";
  }

  std::string HtmlPage::html() const
  {
    return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + escape_html(title) +
           "</title>\n<style>" + style + "</style></head><body>\n" + body.str() + "</body></html>\n";
  }
} // namespace abrade::report
