#pragma once
// One output folder, one run, all or nothing. A command that writes a folder of results
// (`odometry --out`, `synth --out`, a report) writes them into a staging folder beside the target
// and swaps it in when the run has finished, so that
//   - a rerun replaces the whole set: no file of an earlier run is left beside the new ones;
//   - a killed run leaves the earlier set as it was (and the next run removes its staging folder);
//   - two runs into one folder at once are refused: the second one fails at its start, naming the
//     folder, instead of mixing the two file sets.
// The swap is one renameat2(RENAME_EXCHANGE); where the filesystem lacks it, two renames.
// A folder is replaced only when it is empty or sextant wrote it (its marker file, kMarkerFile):
// files sextant did not write are never deleted.
#include <filesystem>
#include <string>

namespace sextant {

class OutputFolder {
 public:
  /// Takes the target's lock (<parent>/.<name>.lock) and creates the staging folder. InputError
  /// naming `target` when it is a file, a non-empty folder without sextant's marker, not writable,
  /// or another process writes it now. `command` (e.g. "sextant odometry") goes into the marker.
  OutputFolder(const std::filesystem::path& target, const std::string& command);
  /// Without commit(): removes the staging folder; the target is left as it was.
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  /// Where this run writes its files.
  const std::filesystem::path& staging() const { return staging_; }
  /// The folder the files appear in after commit(), as the user named it.
  const std::filesystem::path& target() const { return target_; }

  /// Swaps the staging folder in for the target and removes the earlier run's files.
  void commit();

 private:
  void release();  ///< removes an uncommitted staging folder, releases the lock

  std::filesystem::path target_, resolved_, staging_;
  int lock_fd_ = -1;
  bool committed_ = false;
};

/// The file that marks a folder as a sextant output folder.
inline constexpr const char* kMarkerFile = ".sextant-output";

}  // namespace sextant
