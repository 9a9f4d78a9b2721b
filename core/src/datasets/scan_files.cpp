#include "scan_files.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <string>

#include "sextant/core/error.hpp"

namespace sextant::detail {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

/// The longest of `extensions` that `name` ends with (case-insensitive), or empty.
std::string matched_extension(const std::string& name, const std::vector<std::string>& extensions) {
  const std::string low = lower(name);
  std::string best;
  for (const std::string& e : extensions) {
    const std::string ext = lower(e);
    if (low.size() > ext.size() && low.compare(low.size() - ext.size(), ext.size(), ext) == 0 &&
        ext.size() > best.size())
      best = ext;
  }
  return best;
}

/// The run of digits ending at `end` (inclusive) in `stem`, and where it begins.
std::size_t digits_ending_at(const std::string& stem, std::size_t end, std::string& digits) {
  std::size_t begin = end;
  while (begin > 0 && std::isdigit(static_cast<unsigned char>(stem[begin - 1]))) --begin;
  digits = stem.substr(begin, end - begin + 1);
  return begin;
}

/// The last number in `stem`: its integer digits and, when it is <digits>.<digits>, the digits
/// after the point; false when the stem has no digit.
bool last_number(const std::string& stem, std::string& digits, std::string& fraction, bool& decimal) {
  const auto end = stem.find_last_of("0123456789");
  if (end == std::string::npos) return false;
  const std::size_t begin = digits_ending_at(stem, end, digits);
  fraction.clear();
  decimal = begin >= 2 && stem[begin - 1] == '.' && std::isdigit(static_cast<unsigned char>(stem[begin - 2]));
  if (decimal) {
    fraction = digits;
    digits_ending_at(stem, begin - 2, digits);
    fraction.erase(fraction.find_last_not_of('0') + 1);  // 0.50 is 0.5
  }
  return true;
}

/// a before b: by number, then by fraction digit by digit ("" < "05" < "5"), then by path.
bool numbered_before(const NumberedFile& a, const NumberedFile& b) {
  if (a.number != b.number) return a.number < b.number;
  if (a.fraction != b.fraction)
    return a.fraction < b.fraction;  // no trailing zeros: lexicographic is numeric
  return a.path < b.path;
}

bool same_number(const NumberedFile& a, const NumberedFile& b) {
  return a.number == b.number && a.fraction == b.fraction;  // 12, 12.0 and 12.00 are one number
}

std::string number_text(const NumberedFile& f) {
  return std::to_string(f.number) + (f.has_fraction() ? "." + (f.fraction.empty() ? "0" : f.fraction) : "");
}

std::string range_text(std::uint64_t from, std::uint64_t to) {
  return from == to ? std::to_string(from) : std::to_string(from) + "–" + std::to_string(to);
}

}  // namespace

ScanListing list_scans(const std::filesystem::path& folder, const std::string& prefix,
                       const std::vector<std::string>& extensions) {
  ScanListing listing;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    const std::string extension = matched_extension(name, extensions);
    if (extension.empty() || name[0] == '.') continue;  // not a cloud file (poses.txt, a hidden file)
    std::error_code status_error;
    const bool file = entry.is_regular_file(status_error);
    if (!file && entry.is_symlink(status_error))
      throw InputError(entry.path().string(), "",
                       "a link to nothing (" +
                           std::filesystem::read_symlink(entry.path(), status_error).string() +
                           "): the scan cannot be read; restore its target or remove the link");
    if (!file) {
      listing.left_out.push_back(name + " (not a file)");
      continue;
    }
    if (name.compare(0, prefix.size(), prefix) != 0) {
      listing.left_out.push_back(name + " (not named " + prefix + "NNN" + extension + ")");
      continue;
    }
    std::string digits, fraction;
    bool decimal = false;
    const std::string stem = name.substr(prefix.size(), name.size() - prefix.size() - extension.size());
    if (!last_number(stem, digits, fraction, decimal)) {
      listing.left_out.push_back(name + " (no number in its name, which orders the scans)");
      continue;
    }
    const auto first = digits.find_first_not_of('0');
    const std::string significant = first == std::string::npos ? "0" : digits.substr(first);
    if (significant.size() > 19)
      throw InputError(entry.path().string(), "", "the number in the name has more than 19 digits");
    listing.files.push_back({std::stoull(significant), entry.path(), extension, fraction, decimal});
  }
  std::sort(listing.files.begin(), listing.files.end(), numbered_before);
  for (std::size_t i = 1; i < listing.files.size(); ++i) {
    if (same_number(listing.files[i], listing.files[i - 1]))
      throw InputError(folder.string(), "",
                       "ambiguous scan order: " + listing.files[i - 1].path.filename().string() + " and " +
                           listing.files[i].path.filename().string() + " both carry the number " +
                           number_text(listing.files[i]) + "; remove or rename one");
  }
  std::sort(listing.left_out.begin(), listing.left_out.end());
  if (!listing.files.empty() && !listing.left_out.empty())
    listing.notes.push_back(left_out_note(listing.left_out));
  if (const std::string gaps = describe_gaps(listing.files); !gaps.empty())
    listing.notes.push_back("the numbering of the scans has gaps (" + gaps +
                            "); the scans are chained in order as if consecutive");
  std::map<std::string, std::size_t> per_extension;
  for (const NumberedFile& f : listing.files) ++per_extension[f.extension];
  if (per_extension.size() > 1) {
    std::string mix;
    for (const auto& [extension, count] : per_extension)
      mix += (mix.empty() ? "" : ", ") + std::to_string(count) + " " + extension;
    listing.notes.push_back("the scans mix file formats (" + mix + ")");
  }
  return listing;
}

std::string left_out_note(const std::vector<std::string>& left_out) {
  std::string names;
  for (std::size_t i = 0; i < left_out.size() && i < 4; ++i) names += (i ? ", " : "") + left_out[i];
  return std::to_string(left_out.size()) +
         (left_out.size() == 1 ? " point-cloud file is" : " point-cloud files are") +
         " not a scan of the sequence: " + names + (left_out.size() > 4 ? ", …" : "");
}

std::string describe_gaps(const std::vector<NumberedFile>& files) {
  if (std::any_of(files.begin(), files.end(), [](const NumberedFile& f) { return f.has_fraction(); }))
    return {};
  std::uint64_t missing = 0;
  std::size_t gaps = 0;
  std::string ranges;
  for (std::size_t i = 1; i < files.size(); ++i) {
    const std::uint64_t a = files[i - 1].number, b = files[i].number;
    if (b - a <= 1) continue;
    missing += b - a - 1;
    if (++gaps <= 4) ranges += (ranges.empty() ? "" : ", ") + range_text(a + 1, b - 1);
  }
  if (missing == 0) return {};
  return std::to_string(missing) + (missing == 1 ? " number" : " numbers") + " missing: " + ranges +
         (gaps > 4 ? ", …" : "");
}

double NumberedFile::value() const {
  return std::stod(std::to_string(number) + "." + (fraction.empty() ? "0" : fraction));
}

std::vector<double> times_in_names(const std::vector<NumberedFile>& files) {
  if (files.empty() ||
      !std::all_of(files.begin(), files.end(), [](const NumberedFile& f) { return f.has_fraction(); }))
    return {};
  std::vector<double> times;
  times.reserve(files.size());
  for (const NumberedFile& f : files) times.push_back(f.value());
  return times;
}

std::string folder_name(const std::filesystem::path& folder) {
  std::filesystem::path normal = std::filesystem::absolute(folder).lexically_normal();
  if (!normal.has_filename()) normal = normal.parent_path();
  return normal.filename().string();
}

}  // namespace sextant::detail
