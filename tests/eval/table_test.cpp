#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "sextant/eval/table.hpp"

namespace sextant {
namespace {

Table small_table() {
  Table t;
  t.caption = "Errors";
  t.label = "tab:err";
  t.note = "cm";
  t.add_column("statistic").add_compared_column("tx", 2);
  t.add_row({Cell::text("mean"), Cell::number(0.914), Cell::number(0.97)});
  t.add_row({Cell::text("max"), Cell::number(90.891)});  // thesis value missing
  return t;
}

TEST(Table, Markdown) {
  EXPECT_EQ(render_markdown(small_table()),
            "**Errors**\n\n"
            "| statistic | tx (ours) | tx (thesis) |\n"
            "| :--- | ---: | ---: |\n"
            "| mean | 0.91 | 0.97 |\n"
            "| max | 90.89 | – |\n"
            "\ncm\n");
}

TEST(Table, LatexBooktabs) {
  EXPECT_EQ(render_latex(small_table()),
            "\\begin{table}[htbp]\n"
            "  \\centering\n"
            "  \\caption{Errors}\n"
            "  \\label{tab:err}\n"
            "  \\begin{tabular}{lrr}\n"
            "    \\toprule\n"
            "     & \\multicolumn{2}{c}{tx} \\\\\n"
            "    \\cmidrule(lr){2-3}\n"
            "    statistic & ours & thesis \\\\\n"
            "    \\midrule\n"
            "    mean & 0.91 & 0.97 \\\\\n"
            "    max & 90.89 & -- \\\\\n"
            "    \\bottomrule\n"
            "  \\end{tabular}\n"
            "  \\par\\smallskip{\\footnotesize cm}\n"
            "\\end{table}\n");
}

TEST(Table, Csv) {
  EXPECT_EQ(render_csv(small_table()),
            "statistic,tx (ours),tx (thesis)\n"
            "mean,0.91,0.97\n"
            "max,90.89,\n");
  Table quoted;
  quoted.add_column("name").add_number_column("v", 1);
  quoted.add_row({Cell::text("a, \"b\""), Cell::number(-0.04)});
  EXPECT_EQ(render_csv(quoted), "name,v\n\"a, \"\"b\"\"\",0.0\n");
}

TEST(Table, HtmlGroupsSpanColumns) {
  const std::string html = render_html(small_table());
  EXPECT_NE(html.find("<th rowspan=\"2\">statistic</th><th colspan=\"2\">tx</th>"), std::string::npos)
      << html;
  EXPECT_NE(html.find("<th>ours</th><th>thesis</th>"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"num\">–</td>"), std::string::npos);
  EXPECT_NE(html.find("id=\"tab:err\""), std::string::npos);
}

TEST(Table, CellFormatting) {
  TableColumn c;
  c.precision = 2;
  EXPECT_EQ(format_cell(Cell::number(-0.001), c), "0.00");
  EXPECT_EQ(format_cell(Cell::number(-0.76), c), "-0.76");
  EXPECT_EQ(format_cell(Cell::number(1.23456, 4), c), "1.2346");
  EXPECT_EQ(format_cell(Cell::number(999999999.0), c), "999999999.00");
  EXPECT_EQ(format_cell(Cell::number(3185814733472572416.0), c), "3.19e+18");
  EXPECT_EQ(format_cell(Cell::number(-1.5e12), c), "-1.50e+12");
  EXPECT_EQ(format_cell(Cell::number(std::numeric_limits<double>::quiet_NaN()), c), "nan");
  EXPECT_EQ(format_cell(Cell::missing(), c), "");
  EXPECT_EQ(escape_latex("50% of a_b & c"), "50\\% of a\\_b \\& c");
  EXPECT_EQ(escape_html("<a & \"b\">"), "&lt;a &amp; &quot;b&quot;&gt;");
}

TEST(Table, RowLongerThanColumnsIsAnError) {
  Table t;
  t.add_column("a");
  EXPECT_THROW(t.add_row({Cell::text("x"), Cell::text("y")}), std::invalid_argument);
  t.rows.push_back({});  // a short row pushed directly renders as missing cells
  EXPECT_EQ(render_csv(t), "a\n\n");
}

TEST(Table, WritesFilesAtomically) {
  const auto dir = std::filesystem::temp_directory_path() / "sextant_eval_table_test";
  std::filesystem::remove_all(dir);
  write_table(small_table(), TableFormat::csv, dir / "t.csv");
  std::ifstream in(dir / "t.csv");
  std::stringstream content;
  content << in.rdbuf();
  EXPECT_EQ(content.str(), render_csv(small_table()));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sextant
