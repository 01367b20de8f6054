#include <fstream>
#include <stdexcept>

#include "particles/html/document.h"

namespace particles::html {

std::string escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void Document::heading(const std::string& text, int level) {
  // Appended piece by piece: GCC 12 flags "<" + h + ">" with a false -Wrestrict.
  const char digit = static_cast<char>('0' + (level < 1 ? 1 : level > 4 ? 4 : level));
  body_.append("<h").push_back(digit);
  body_.append(">").append(escape(text)).append("</h").push_back(digit);
  body_.append(">\n");
}

void Document::paragraph(const std::string& text) {
  body_ += "<p>" + escape(text) + "</p>\n";
}

void Document::note(const std::string& text) {
  body_ += "<p class=\"note\">" + escape(text) + "</p>\n";
}

void Document::table(const Table& t) {
  body_ += "<table>\n";
  if (!t.caption.empty()) body_ += "<caption>" + escape(t.caption) + "</caption>\n";
  body_ += "<tr>";
  for (const std::string& h : t.header) body_ += "<th>" + escape(h) + "</th>";
  body_ += "</tr>\n";
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    const std::string cls = i < t.rowClass.size() ? t.rowClass[i] : "";
    body_ += cls.empty() ? "<tr>" : "<tr class=\"" + escape(cls) + "\">";
    for (std::size_t k = 0; k < t.rows[i].size(); ++k) {
      const std::string& c = t.rows[i][k];
      const std::string href =
          i < t.links.size() && k < t.links[i].size() ? t.links[i][k] : std::string();
      body_ += href.empty() ? "<td>" + escape(c) + "</td>"
                            : "<td><a href=\"" + escape(href) + "\">" + escape(c) + "</a></td>";
    }
    body_ += "</tr>\n";
  }
  body_ += "</table>\n";
}

void Document::plot(const Plot& p) {
  const std::string svg = renderSvg(p);
  if (!svg.empty()) {
    body_ += "<figure>" + svg + "</figure>\n";
    return;
  }
  // Say it once per document in full, then briefly: the tables carry the data.
  note(warnedNoGnuplot_ ? "Plot \"" + p.title + "\" not drawn (no gnuplot)."
                        : "Plot \"" + p.title +
                              "\" not drawn: gnuplot is not installed (Debian: gnuplot-nox). "
                              "The tables and CSV files hold the same data.");
  warnedNoGnuplot_ = true;
}

std::string Document::html() const {
  // All style inline; no script, font or image is fetched from anywhere.
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
         escape(title_) +
         "</title>\n<style>\n"
         "body{font-family:sans-serif;max-width:1100px;margin:1.5em auto;padding:0 1em;"
         "color:#222}\n"
         "table{border-collapse:collapse;margin:0.8em 0;font-size:0.9em}\n"
         "th,td{border:1px solid #bbb;padding:3px 8px;text-align:left}\n"
         "th{background:#eef}\ncaption{text-align:left;font-weight:bold;padding:4px 0}\n"
         "tr.good td{background:#e8f6e8}\ntr.bad td{background:#fbe3e3}\n"
         "tr.mark td{font-weight:bold}\n"
         ".note{background:#fff6d5;border-left:4px solid #e0b000;padding:6px 10px}\n"
         "figure{margin:1em 0}\nsvg{max-width:100%;height:auto}\n"
         "</style>\n</head>\n<body>\n<h1>" +
         escape(title_) + "</h1>\n" + body_ + "</body>\n</html>\n";
}

void Document::write(const std::filesystem::path& dir) const {
  const std::filesystem::path file = dir / "index.html";
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  out << html();
  if (!out) throw std::runtime_error("error writing " + file.string());
}

}  // namespace particles::html
