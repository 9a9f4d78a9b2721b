#include "scan_files.hpp"

#include <algorithm>
#include <cctype>
#include <map>

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

/// The last run of digits in `stem`; false when there is none.
bool last_digits(const std::string& stem, std::string& digits) {
  const auto end = stem.find_last_of("0123456789");
  if (end == std::string::npos) return false;
  std::size_t begin = end;
  while (begin > 0 && std::isdigit(static_cast<unsigned char>(stem[begin - 1]))) --begin;
  digits = stem.substr(begin, end - begin + 1);
  return true;
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
    std::string digits;
    const std::string stem = name.substr(prefix.size(), name.size() - prefix.size() - extension.size());
    if (!last_digits(stem, digits)) {
      listing.left_out.push_back(name + " (no number in its name, which orders the scans)");
      continue;
    }
    const auto first = digits.find_first_not_of('0');
    const std::string significant = first == std::string::npos ? "0" : digits.substr(first);
    if (significant.size() > 19)
      throw InputError(entry.path().string(), "", "the number in the name has more than 19 digits");
    listing.files.push_back({std::stoull(significant), entry.path(), extension});
  }
  std::sort(listing.files.begin(), listing.files.end(), [](const NumberedFile& a, const NumberedFile& b) {
    return a.number != b.number ? a.number < b.number : a.path < b.path;
  });
  for (std::size_t i = 1; i < listing.files.size(); ++i) {
    if (listing.files[i].number == listing.files[i - 1].number)
      throw InputError(folder.string(), "",
                       "ambiguous scan order: " + listing.files[i - 1].path.filename().string() + " and " +
                           listing.files[i].path.filename().string() + " both carry the number " +
                           std::to_string(listing.files[i].number) + "; remove or rename one");
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

std::string folder_name(const std::filesystem::path& folder) {
  std::filesystem::path normal = std::filesystem::absolute(folder).lexically_normal();
  if (!normal.has_filename()) normal = normal.parent_path();
  return normal.filename().string();
}

}  // namespace sextant::detail
