#pragma once
// A report page being written: headings, paragraphs, tables, inlined pictures (base64 data
// URIs, so the page is one file), warnings, and a print-friendly style sheet.
#include <sstream>
#include <string>
#include <vector>

namespace abrade::report
{
  /// @p text for HTML: markup characters escaped, and bytes that are not UTF-8 (a parameter
  /// file in Latin-1) replaced by U+FFFD.
  std::string escape_html(const std::string &text);

  class HtmlPage
  {
  public:
    explicit HtmlPage(const std::string &title);

    void heading(const std::string &text, int level = 2);
    void paragraph(const std::string &html);
    /// The headline: one sentence in large type; @p html may hold a span with the number.
    void headline(const std::string &html);
    /// A PNG file inlined, with its caption; a note if the file is missing. @p figure names
    /// what it shows (data-figure, for the browser test: "trajectory", "knife", "profile").
    void png(const std::string &file, const std::string &caption, const std::string &figure = "");
    void table(const std::vector<std::string> &header, const std::vector<std::vector<std::string>> &rows);
    /// The warnings, each on its line (a "none" line when there are none).
    void warnings(const std::vector<std::string> &list);
    /// A collapsed block of preformatted text (the parameter file).
    void details(const std::string &summary, const std::string &text);

    /// The page so far, closed.
    std::string html() const;

  private:
    std::ostringstream body;
    std::string        title;
  };
} // namespace abrade::report
