// CSV / xyz / txt point lists.
#include <cmath>
#include <string>

#include "formats.hpp"
#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "text_parse.hpp"

namespace sextant::detail {

PointCloud read_point_list(const std::filesystem::path& file, ScanLoadReport* report) {
  std::string text = read_file_bytes(file);
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // a UTF-8 byte order mark is no data
  ScanLoadReport local;
  PointCloud cloud;
  std::vector<double> values;
  std::string bad;
  std::size_t columns = 0;
  detail::for_each_line(text, [&](std::string_view line, long number) {
    if (is_blank(line) || line.front() == '#') return;
    const bool parsed = parse_numbers(line, values, &bad);
    if (!parsed && columns == 0 && local.header_lines_skipped == 0) {
      ++local.header_lines_skipped;  // e.g. "x,y,z,intensity"
      return;
    }
    if (!parsed) throw InputError(file.string(), at_line(number), bad_number_problem(bad));
    if (values.size() != 3 && values.size() != 4) {
      throw InputError(file.string(), at_line(number),
                       "expected 3 or 4 numbers (x y z [intensity]), found " + std::to_string(values.size()));
    }
    if (columns == 0) columns = values.size();
    if (values.size() != columns) {
      throw InputError(file.string(), at_line(number),
                       "found " + std::to_string(values.size()) + " numbers, but earlier lines had " +
                           std::to_string(columns));
    }
    ++local.points_read;
    bool finite = true;  // NaN, ±Inf and values outside float's range (1e308) alike
    for (double v : values) finite = finite && fits_float(v);
    if (!finite) {
      ++local.non_finite_dropped;
      return;
    }
    const Eigen::Vector3f p = Eigen::Vector3d(values[0], values[1], values[2]).cast<float>();
    if (columns == 4) {
      cloud.push_back(p, static_cast<float>(values[3]));
    } else {
      cloud.push_back(p);
    }
  });
  if (report) *report = local;
  return cloud;
}

void write_point_list(const std::filesystem::path& file, const PointCloud& cloud,
                      bool with_header_and_commas) {
  const char sep = with_header_and_commas ? ',' : ' ';
  std::string text;
  if (with_header_and_commas) text += cloud.has_intensity() ? "x,y,z,intensity\n" : "x,y,z\n";
  text.reserve(text.size() + cloud.size() * 32);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      if (k > 0) text += sep;
      append_number(text, cloud[i][k]);
    }
    if (cloud.has_intensity()) {
      text += sep;
      append_number(text, cloud.intensity()[i]);
    }
    text += '\n';
  }
  write_file_atomically(file, text);
}

}  // namespace sextant::detail
