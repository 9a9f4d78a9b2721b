// CSV / xyz / txt point lists.
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include "formats.hpp"
#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "text_parse.hpp"

namespace sextant::detail {

namespace {

/// The columns of a header line ("x,y,z,nx,ny,nz", "//X Y Z Intensity", "\"x\",\"y\",\"z\""): names
/// lower-cased, quotes and CloudCompare's leading "//" removed.
std::vector<std::string> header_names(std::string_view line) {
  std::vector<std::string> names;
  std::string name;
  const auto flush = [&] {
    if (name.rfind("//", 0) == 0) name.erase(0, 2);
    if (!name.empty()) names.push_back(name);
    name.clear();
  };
  for (const char c : line) {
    if (c == ',' || c == ' ' || c == '\t' || c == '\r') {
      flush();
    } else if (c != '"' && c != '\'') {
      name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  flush();
  return names;
}

/// Where x, y, z and the intensity are in a line, by the header's names or by position.
struct ColumnLayout {
  std::size_t columns = 0;  ///< values per line; 0 until known
  std::size_t x = 0, y = 1, z = 2;
  std::optional<std::size_t> intensity;
  std::vector<std::string> ignored;  ///< named columns that are not read (normals, colours, …)
};

ColumnLayout layout_from_header(const std::vector<std::string>& names, const std::filesystem::path& file,
                                long number) {
  ColumnLayout layout;
  layout.columns = names.size();
  const auto find = [&](std::initializer_list<const char*> wanted) -> std::optional<std::size_t> {
    for (const char* w : wanted)
      for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == w) return i;
    return std::nullopt;
  };
  std::size_t* axes[3] = {&layout.x, &layout.y, &layout.z};
  for (int k = 0; k < 3; ++k) {
    const std::string axis(1, "xyz"[k]);
    const auto at = find({axis.c_str()});
    if (!at) {
      std::string all;
      for (const std::string& n : names) all += (all.empty() ? "" : ", ") + n;
      throw InputError(file.string(), at_line(number),
                       "the header names no '" + axis + "' column (columns: " + all + ")");
    }
    *axes[k] = *at;
  }
  layout.intensity = find({"intensity", "reflectance", "scalar_intensity", "i", "remission"});
  for (std::size_t i = 0; i < names.size(); ++i)
    if (i != layout.x && i != layout.y && i != layout.z && i != layout.intensity)
      layout.ignored.push_back(names[i]);
  return layout;
}

}  // namespace

PointCloud read_point_list(const std::filesystem::path& file, ScanLoadReport* report) {
  std::string text = read_file_bytes(file);
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // a UTF-8 byte order mark is no data
  ScanLoadReport local;
  PointCloud cloud;
  std::vector<double> values;
  std::string bad;
  ColumnLayout layout;
  bool named = false;  // columns found by the header's names
  detail::for_each_line(text, [&](std::string_view line, long number) {
    if (is_blank(line) || line.front() == '#') return;
    const bool parsed = parse_numbers(line, values, &bad);
    if (!parsed && layout.columns == 0 && local.header_lines_skipped == 0) {
      ++local.header_lines_skipped;  // e.g. "x,y,z,intensity": its names say where the values are
      layout = layout_from_header(header_names(line), file, number);
      named = true;
      return;
    }
    if (!parsed) throw InputError(file.string(), at_line(number), bad_number_problem(bad));
    if (!named && values.size() != 3 && values.size() != 4) {
      throw InputError(file.string(), at_line(number),
                       "expected 3 or 4 numbers (x y z [intensity]) or a header naming the columns, found " +
                           std::to_string(values.size()));
    }
    if (layout.columns == 0) {
      layout.columns = values.size();
      if (layout.columns == 4) layout.intensity = 3;
    }
    if (values.size() != layout.columns) {
      throw InputError(file.string(), at_line(number),
                       "found " + std::to_string(values.size()) + " numbers, but " +
                           (named ? "the header names " : "earlier lines had ") +
                           std::to_string(layout.columns));
    }
    ++local.points_read;
    const double x = values[layout.x], y = values[layout.y], z = values[layout.z];
    const double intensity = layout.intensity ? values[*layout.intensity] : 0.0;
    // NaN, ±Inf and values outside float's range (1e308) alike
    if (!fits_float(x) || !fits_float(y) || !fits_float(z) || !fits_float(intensity)) {
      ++local.non_finite_dropped;
      return;
    }
    const Eigen::Vector3f p = Eigen::Vector3d(x, y, z).cast<float>();
    if (layout.intensity) {
      cloud.push_back(p, static_cast<float>(intensity));
    } else {
      cloud.push_back(p);
    }
  });
  if (!layout.ignored.empty()) {
    std::string names;
    for (const std::string& n : layout.ignored) names += (names.empty() ? "" : ", ") + n;
    local.warnings.push_back("columns not read (no point field of Sextant's): " + names);
  }
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
