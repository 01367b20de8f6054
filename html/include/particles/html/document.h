// A small self-contained HTML document: headings, paragraphs, tables and
// plots. Plots are rendered by gnuplot to SVG and embedded inline; when
// gnuplot is missing or fails, the plot's place holds a note and its data
// stays available in the tables and CSV files the caller writes.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace particles::html {

// Escapes &, <, >, " and ' for text and attribute values.
std::string escape(std::string_view text);

struct Table {
  std::string caption;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // cells as text (escaped when written)
  // Optional per-row CSS class ("good", "bad", "mark"), same length as rows or empty.
  std::vector<std::string> rowClass;
  // Optional per-cell link targets, shaped like rows (shorter rows or empty
  // entries: no link). A non-empty entry makes that cell <a href="...">;
  // the caller gives it relative to the document so the report can be moved.
  std::vector<std::vector<std::string>> links = {};
};

struct Series {
  std::string title;
  std::vector<std::pair<double, double>> points;  // (x, y); non-finite points are left out
  // gnuplot style: "points", "linespoints" or "lines".
  std::string style = "linespoints";
  int pointType = 7;  // gnuplot point type
  int color = 0;      // index into the report's palette, 0-based
};

struct Plot {
  std::string title, xLabel, yLabel;
  bool logX = false, logY = false;
  std::vector<Series> series;
  int width = 860, height = 480;  // pixels
};

// Renders `plot` with gnuplot as an <svg> element (no XML prolog), or
// returns an empty string if gnuplot is not on PATH or fails.
std::string renderSvg(const Plot& plot);
bool gnuplotAvailable();

class Document {
 public:
  explicit Document(std::string title) : title_(std::move(title)) {}
  void heading(const std::string& text, int level = 2);
  void paragraph(const std::string& text);  // escaped
  void note(const std::string& text);       // a highlighted paragraph, escaped
  void rawHtml(const std::string& html) { body_ += html; }
  void table(const Table& table);
  void plot(const Plot& plot);  // inline SVG, or a note when gnuplot is unavailable

  std::string html() const;
  // Writes DIR/index.html (DIR must exist). Throws std::runtime_error on failure.
  void write(const std::filesystem::path& dir) const;

 private:
  std::string title_;
  std::string body_;
  bool warnedNoGnuplot_ = false;
};

}  // namespace particles::html
