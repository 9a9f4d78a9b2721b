#include "sextant/eval/thesis_tables.hpp"

namespace sextant {

namespace {

Cell optional_cell(const std::optional<double>& v) {
  return v ? Cell::number(*v) : Cell::missing();
}

}  // namespace

Table registration_error_table(const RegistrationStats& ours, const ParameterReference* thesis,
                               const std::string& caption, const std::string& label) {
  Table t;
  t.caption = caption;
  t.label = label;
  t.note = "Relative error E = T_gt⁻¹·T_est; translations in cm, angles in degrees; " +
           std::to_string(ours.count) + " registrations.";
  t.add_column("");
  for (const std::string& name : parameter_names()) t.add_compared_column(name, 2);
  const char* row_names[3] = {"Mean", "Std", "Max"};
  for (int r = 0; r < 3; ++r) {
    std::vector<Cell> row{Cell::text(row_names[r])};
    for (std::size_t k = 0; k < 6; ++k) {
      const SampleStats& s = ours.parameters[k];
      const double value = r == 0 ? s.mean : r == 1 ? s.std : s.max;
      row.push_back(s.count > 0 ? Cell::number(value) : Cell::missing());
      if (!thesis) {
        row.push_back(Cell::missing());
        continue;
      }
      const auto& column = r == 0 ? thesis->mean : r == 1 ? thesis->std : thesis->max;
      row.push_back(optional_cell(column[k]));
    }
    t.add_row(std::move(row));
  }
  return t;
}

}  // namespace sextant
