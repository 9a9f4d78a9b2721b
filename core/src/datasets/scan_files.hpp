#pragma once
// Private: lists the scan files of a dataset folder in natural order (scan2 before scan10), names
// that are a number with a fraction (1565943695.228028.pcd, as bag exports write them) by that
// number, with what a user must hear about them: gaps in the numbering and mixed formats are
// reported as notes; two files with the same number (scan001.3d and scan1.3d, 000002.bin and
// 000002.pcd) are ambiguous and refused.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sextant::detail {

struct NumberedFile {
  std::uint64_t number = 0;  ///< the last run of digits in the name before the extension
  std::filesystem::path path;
  std::string extension;  ///< the matched extension, e.g. ".xyz32.bin"
  /// The digits after a point that follows `number` ("228028" of 1565943695.228028.pcd), without
  /// trailing zeros (empty for 12.000 and for a number without a fraction).
  std::string fraction;
  bool decimal = false;  ///< the number is written with a point and a fraction
  bool has_fraction() const { return decimal; }
  double value() const;  ///< number.fraction
};

struct ScanListing {
  std::vector<NumberedFile> files;    ///< ascending number
  std::vector<std::string> notes;     ///< gaps, mixed formats, files left out: reported, not errors
  std::vector<std::string> left_out;  ///< "first.pcd (no number in its name, …)": cloud files not listed
};

/// Regular files named <prefix>…<digits><extension> or <prefix>…<digits>.<digits><extension> for
/// one of `extensions` (the longest one a name ends with wins, case-insensitive), ascending by
/// number (with its fraction, compared digit by digit, not as a float). A file with such an extension that
/// is not listed (no number, another prefix, not a file) is in `left_out` and, when there are scans,
/// in a note. InputError naming both files when two share a number, for a link to nothing with such
/// an extension, and for a file whose digits do not fit 19 places.
ScanListing list_scans(const std::filesystem::path& folder, const std::string& prefix,
                       const std::vector<std::string>& extensions);

/// "2 point-cloud files are not a scan of the sequence: a.pcd (…), b.pcd (…)".
std::string left_out_note(const std::vector<std::string>& left_out);

/// "3 numbers missing: 001–002, 004" style description of the gaps of an ascending listing
/// (empty when consecutive, and for numbers with fractions, which are times, not counts).
std::string describe_gaps(const std::vector<NumberedFile>& files);

/// The numbers in the names as the scans' times [s] when every name is a number with a fraction
/// (the names of a bag export), else empty.
std::vector<double> times_in_names(const std::vector<NumberedFile>& files);

/// The folder's own name, also for "a/b/" and "." paths.
std::string folder_name(const std::filesystem::path& folder);

}  // namespace sextant::detail
