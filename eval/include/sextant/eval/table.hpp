#pragma once
// One table model, rendered to Markdown, LaTeX (booktabs), CSV and HTML. Columns may be grouped
// under a spanning header, e.g. "tx" over "ours | thesis"; cells may be numbers, text or missing.
//
//   Table t;
//   t.caption = "Table 5.3: ML-NDT relative error";
//   t.add_column("statistic");
//   t.add_compared_column("tx", 2);        // adds "tx / ours" and "tx / thesis"
//   t.add_row({Cell::text("mean"), Cell::number(0.91), Cell::number(0.97)});
//   write_table(t, TableFormat::latex, "report/e02/table_5_3.tex");
#include <filesystem>
#include <string>
#include <vector>

namespace sextant {

struct Cell {
  enum class Kind { missing, number, text };
  Kind kind = Kind::missing;
  double value = 0.0;
  std::string content;
  int precision = -1;  ///< digits after the point; −1 uses the column's

  static Cell missing() { return {}; }
  static Cell number(double v, int precision = -1);
  static Cell text(std::string s);
};

struct TableColumn {
  std::string header;   ///< e.g. "ours"
  std::string group;    ///< spanning header for consecutive columns with the same group; "" = none
  int precision = 2;    ///< digits after the point for number cells
  bool numeric = true;  ///< right-aligned; false for label columns (left-aligned)

  /// The header as one string: "group (header)" when grouped, else header.
  std::string flat_header() const;
};

struct Table {
  std::string caption;  ///< LaTeX caption / HTML caption / Markdown title line
  std::string label;    ///< LaTeX \label; also the HTML id
  std::string note;     ///< footnote under the table (units, source); may be empty
  std::vector<TableColumn> columns;
  std::vector<std::vector<Cell>> rows;

  /// A left-aligned text column.
  Table& add_column(const std::string& header);
  Table& add_number_column(const std::string& header, int precision = 2, const std::string& group = "");
  /// Two numeric columns "ours" and "thesis" under `group`.
  Table& add_compared_column(const std::string& group, int precision = 2);
  /// Rows shorter than the column count are padded with missing cells; longer rows are an error
  /// (std::invalid_argument, a programming mistake).
  Table& add_row(std::vector<Cell> cells);
};

enum class TableFormat { markdown, latex, csv, html };

/// Formats a cell as text ("" for missing; NaN/inf as "nan"/"inf").
std::string format_cell(const Cell& cell, const TableColumn& column);

std::string render_markdown(const Table& table);  ///< GitHub-flavoured; missing = "–"
std::string render_latex(const Table& table);     ///< booktabs tabular in a table float; missing = "--"
std::string render_csv(const Table& table);       ///< RFC 4180 quoting; missing = empty field
std::string render_html(const Table& table);      ///< <table> with colspan group headers; missing = "–"
std::string render_table(const Table& table, TableFormat format);

/// Renders and writes atomically.
void write_table(const Table& table, TableFormat format, const std::filesystem::path& path);

/// Escapes for the target syntax.
std::string escape_latex(const std::string& s);
std::string escape_html(const std::string& s);

}  // namespace sextant
