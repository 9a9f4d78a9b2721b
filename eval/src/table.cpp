#include "sextant/eval/table.hpp"

#include <cmath>
#include <locale>
#include <sstream>
#include <stdexcept>

#include "sextant/core/atomic_file.hpp"

namespace sextant {

namespace {

const char* kMissingText = "–";  // en dash for Markdown and HTML
const char* kMissingLatex = "--";

/// A run of consecutive columns under the same group header.
struct GroupSpan {
  std::string group;
  std::size_t first = 0, count = 0;
};

std::vector<GroupSpan> group_spans(const std::vector<TableColumn>& columns) {
  std::vector<GroupSpan> spans;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (!spans.empty() && !columns[c].group.empty() && spans.back().group == columns[c].group)
      ++spans.back().count;
    else
      spans.push_back({columns[c].group, c, 1});
  }
  return spans;
}

bool has_groups(const std::vector<TableColumn>& columns) {
  for (const TableColumn& c : columns)
    if (!c.group.empty()) return true;
  return false;
}

/// Rows pushed directly into Table::rows may be short; absent cells are missing.
const Cell& cell_at(const std::vector<Cell>& row, std::size_t k) {
  static const Cell missing;
  return k < row.size() ? row[k] : missing;
}

std::string cell_or(const Cell& cell, const TableColumn& column, const std::string& missing) {
  return cell.kind == Cell::Kind::missing ? missing : format_cell(cell, column);
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t pos = s.find(from); pos != std::string::npos; pos = s.find(from, pos + to.size()))
    s.replace(pos, from.size(), to);
  return s;
}

std::string escape_markdown(const std::string& s) {
  return replace_all(s, "|", "\\|");
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  return "\"" + replace_all(s, "\"", "\"\"") + "\"";
}

}  // namespace

Cell Cell::number(double v, int precision) {
  Cell c;
  c.kind = Kind::number;
  c.value = v;
  c.precision = precision;
  return c;
}

Cell Cell::text(std::string s) {
  Cell c;
  c.kind = Kind::text;
  c.content = std::move(s);
  return c;
}

std::string TableColumn::flat_header() const {
  return group.empty() ? header : group + " (" + header + ")";
}

Table& Table::add_column(const std::string& header) {
  TableColumn c;
  c.header = header;
  c.numeric = false;
  columns.push_back(c);
  return *this;
}

Table& Table::add_number_column(const std::string& header, int precision, const std::string& group) {
  TableColumn c;
  c.header = header;
  c.group = group;
  c.precision = precision;
  columns.push_back(c);
  return *this;
}

Table& Table::add_compared_column(const std::string& group, int precision) {
  add_number_column("ours", precision, group);
  return add_number_column("thesis", precision, group);
}

Table& Table::add_row(std::vector<Cell> cells) {
  if (cells.size() > columns.size())
    throw std::invalid_argument("table row has " + std::to_string(cells.size()) + " cells for " +
                                std::to_string(columns.size()) + " columns");
  cells.resize(columns.size());
  rows.push_back(std::move(cells));
  return *this;
}

/// From this magnitude on a number cell is written in scientific notation (3 significant digits).
constexpr double kScientificFrom = 1e9;

std::string format_cell(const Cell& cell, const TableColumn& column) {
  switch (cell.kind) {
    case Cell::Kind::missing: return "";
    case Cell::Kind::text: return cell.content;
    case Cell::Kind::number: break;
  }
  if (std::isnan(cell.value)) return "nan";
  if (std::isinf(cell.value)) return cell.value > 0 ? "inf" : "-inf";
  std::ostringstream out;
  out.imbue(std::locale::classic());
  if (std::abs(cell.value) >= kScientificFrom) {  // 19 digits of a degenerate NEES read as noise
    out.setf(std::ios::scientific);
    out.precision(2);
    out << cell.value;
    return out.str();
  }
  out.setf(std::ios::fixed);
  out.precision(cell.precision >= 0 ? cell.precision : column.precision);
  out << cell.value;
  std::string s = out.str();
  // "-0.00" reads as a sign that is not there.
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string render_markdown(const Table& table) {
  std::ostringstream out;
  if (!table.caption.empty()) out << "**" << escape_markdown(table.caption) << "**\n\n";
  out << "|";
  for (const TableColumn& c : table.columns) out << " " << escape_markdown(c.flat_header()) << " |";
  out << "\n|";
  for (const TableColumn& c : table.columns) out << (c.numeric ? " ---: |" : " :--- |");
  out << "\n";
  for (const auto& row : table.rows) {
    out << "|";
    for (std::size_t k = 0; k < table.columns.size(); ++k)
      out << " " << escape_markdown(cell_or(cell_at(row, k), table.columns[k], kMissingText)) << " |";
    out << "\n";
  }
  if (!table.note.empty()) out << "\n" << escape_markdown(table.note) << "\n";
  return out.str();
}

std::string escape_latex(const std::string& s) {
  std::string out;
  for (char ch : s) {
    switch (ch) {
      case '\\': out += "\\textbackslash{}"; break;
      case '&':
      case '%':
      case '$':
      case '#':
      case '_':
      case '{':
      case '}':
        out += '\\';
        out += ch;
        break;
      case '~': out += "\\textasciitilde{}"; break;
      case '^': out += "\\textasciicircum{}"; break;
      default: out += ch;
    }
  }
  return out;
}

std::string render_latex(const Table& table) {
  std::ostringstream out;
  out << "\\begin{table}[htbp]\n  \\centering\n";
  if (!table.caption.empty()) out << "  \\caption{" << escape_latex(table.caption) << "}\n";
  if (!table.label.empty()) out << "  \\label{" << table.label << "}\n";
  out << "  \\begin{tabular}{";
  for (const TableColumn& c : table.columns) out << (c.numeric ? 'r' : 'l');
  out << "}\n    \\toprule\n";
  if (has_groups(table.columns)) {
    std::string rules;
    out << "    ";
    bool first = true;
    for (const GroupSpan& span : group_spans(table.columns)) {
      for (std::size_t k = 0; k < (span.group.empty() ? span.count : 1); ++k) {
        if (!first) out << " & ";
        first = false;
        if (!span.group.empty())
          out << "\\multicolumn{" << span.count << "}{c}{" << escape_latex(span.group) << "}";
      }
      if (!span.group.empty())
        rules += " \\cmidrule(lr){" + std::to_string(span.first + 1) + "-" +
                 std::to_string(span.first + span.count) + "}";
    }
    out << " \\\\\n    " << rules.substr(1) << "\n";
  }
  out << "    ";
  for (std::size_t k = 0; k < table.columns.size(); ++k)
    out << (k ? " & " : "") << escape_latex(table.columns[k].header);
  out << " \\\\\n    \\midrule\n";
  for (const auto& row : table.rows) {
    out << "    ";
    for (std::size_t k = 0; k < table.columns.size(); ++k) {
      out << (k ? " & " : "");
      const Cell& cell = cell_at(row, k);
      out << (cell.kind == Cell::Kind::missing ? std::string(kMissingLatex)
                                               : escape_latex(format_cell(cell, table.columns[k])));
    }
    out << " \\\\\n";
  }
  out << "    \\bottomrule\n  \\end{tabular}\n";
  if (!table.note.empty()) out << "  \\par\\smallskip{\\footnotesize " << escape_latex(table.note) << "}\n";
  out << "\\end{table}\n";
  return out.str();
}

std::string render_csv(const Table& table) {
  std::ostringstream out;
  for (std::size_t k = 0; k < table.columns.size(); ++k)
    out << (k ? "," : "") << csv_field(table.columns[k].flat_header());
  out << "\n";
  for (const auto& row : table.rows) {
    for (std::size_t k = 0; k < table.columns.size(); ++k)
      out << (k ? "," : "") << csv_field(cell_or(cell_at(row, k), table.columns[k], ""));
    out << "\n";
  }
  return out.str();
}

std::string escape_html(const std::string& s) {
  std::string out;
  for (char ch : s) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += ch;
    }
  }
  return out;
}

std::string render_html(const Table& table) {
  std::ostringstream out;
  out << "<table class=\"sx-table\"";
  if (!table.label.empty()) out << " id=\"" << escape_html(table.label) << "\"";
  out << ">\n";
  if (!table.caption.empty()) out << "<caption>" << escape_html(table.caption) << "</caption>\n";
  out << "<thead>\n<tr>";
  const bool grouped = has_groups(table.columns);
  for (const GroupSpan& span : group_spans(table.columns)) {
    if (span.group.empty()) {
      for (std::size_t k = span.first; k < span.first + span.count; ++k)
        out << "<th" << (grouped ? " rowspan=\"2\"" : "") << ">" << escape_html(table.columns[k].header)
            << "</th>";
    } else {
      out << "<th colspan=\"" << span.count << "\">" << escape_html(span.group) << "</th>";
    }
  }
  out << "</tr>\n";
  if (grouped) {
    out << "<tr>";
    for (const TableColumn& c : table.columns)
      if (!c.group.empty()) out << "<th>" << escape_html(c.header) << "</th>";
    out << "</tr>\n";
  }
  out << "</thead>\n<tbody>\n";
  for (const auto& row : table.rows) {
    out << "<tr>";
    for (std::size_t k = 0; k < table.columns.size(); ++k) {
      out << (table.columns[k].numeric ? "<td class=\"num\">" : "<td>");
      out << escape_html(cell_or(cell_at(row, k), table.columns[k], kMissingText)) << "</td>";
    }
    out << "</tr>\n";
  }
  out << "</tbody>\n</table>\n";
  if (!table.note.empty()) out << "<p class=\"sx-note\">" << escape_html(table.note) << "</p>\n";
  return out.str();
}

std::string render_table(const Table& table, TableFormat format) {
  switch (format) {
    case TableFormat::markdown: return render_markdown(table);
    case TableFormat::latex: return render_latex(table);
    case TableFormat::csv: return render_csv(table);
    case TableFormat::html: return render_html(table);
  }
  return {};
}

void write_table(const Table& table, TableFormat format, const std::filesystem::path& path) {
  write_file_atomically(path, render_table(table, format));
}

}  // namespace sextant
