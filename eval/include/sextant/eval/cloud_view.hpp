#pragma once
// An interactive 3D view of point clouds as one offline HTML page (three.js, WebGL): each cloud in
// its own colour with a legend entry and a show/hide toggle, mouse rotate/zoom/pan, and optional
// states (e.g. "before" and "after" a registration) between which the page switches. A cloud's
// points are stored once; each state places it by its own pose (or leaves it out).
//
//   CloudView view;
//   view.title = "Pair 12 → 13";
//   view.states = {"before (initial guess)", "after (result)"};
//   view.clouds.push_back({"reference", reference, "", {}, {}});
//   view.clouds.push_back({"input", input, "", {T_initial, T_result}, {}});
//   write_cloud_view(view, "pair.html");  // three.js inlined: one self-contained file
//
// three.js comes from Debian's libjs-three (/usr/share/javascript/three/three.min.js), read at run
// time; nothing on the page loads from the network. A page either inlines three.min.js (≈ 0.85 MB,
// one file to hand around) or loads it from a relative URL, for a folder of many pages that shares
// one copy (write_three_js).
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "sextant/core/point_cloud.hpp"

namespace sextant {

/// Points kept per cloud by default: 60 000 (720 kB of float32 coordinates, ≈ 1 MB on the page).
constexpr std::size_t kCloudViewMaxPoints = 60000;

/// Where Debian's libjs-three installs three.js.
inline const std::filesystem::path kThreeJsDir = "/usr/share/javascript/three";

struct ViewCloud {
  std::string name;   ///< legend entry
  PointCloud points;  ///< in the cloud's own frame; non-finite points are dropped
  std::string color;  ///< "#rrggbb"; empty = the first palette colour no other cloud uses
  /// World ← cloud, one per state of the view (or one when the view has no states); empty = the
  /// identity in every state. A state whose pose is not finite leaves the cloud out.
  std::vector<Eigen::Isometry3d> poses;
  /// Whether the cloud is part of each state; empty = of every state.
  std::vector<bool> in_states;
};

struct CloudView {
  std::string title;
  std::string caption;              ///< a line of text below the title (escaped)
  std::vector<std::string> states;  ///< names of the states the page switches between; empty = one
  std::vector<ViewCloud> clouds;
  std::size_t max_points = kCloudViewMaxPoints;  ///< per cloud
};

struct CloudViewOptions {
  /// Folder holding three.min.js (read when the library is inlined).
  std::filesystem::path three_js_dir = kThreeJsDir;
  /// Empty: three.min.js is inlined. Otherwise the URL the page loads it from, relative to the page
  /// (e.g. "../three.min.js", written there by write_three_js); must not be an http(s) URL.
  std::string three_js_src;
};

/// Indices of the points a view keeps of `n` (finite) points: all of them up to `cap`, else `cap`
/// evenly strided ones, ⌊i·n/cap⌋ for i = 0 … cap−1 (deterministic, spread over the whole cloud).
std::vector<std::size_t> view_subsample(std::size_t n, std::size_t cap);

/// The page. Throws std::invalid_argument for an inconsistent view (pose or state counts, a bad
/// colour, an http(s) three_js_src) and InputError naming the path and the package libjs-three when
/// three.js is to be inlined but missing.
std::string render_cloud_view(const CloudView& view, const CloudViewOptions& options = {});
/// Renders and writes atomically.
void write_cloud_view(const CloudView& view, const std::filesystem::path& path,
                      const CloudViewOptions& options = {});

/// `dir`/three.min.js if it is a file; InputError naming that path and libjs-three otherwise.
std::filesystem::path find_three_js(const std::filesystem::path& dir = kThreeJsDir);
/// Copies three.min.js into `folder` (atomically; left alone when already identical) and returns
/// the copy's path; pages beside it use CloudViewOptions::three_js_src = "three.min.js".
std::filesystem::path write_three_js(const std::filesystem::path& folder,
                                     const std::filesystem::path& dir = kThreeJsDir);

/// A registration as two states: the reference, and the input placed by the initial guess
/// ("before") and by the result ("after"); T maps input → reference.
CloudView registration_view(const PointCloud& reference, const PointCloud& input,
                            const Eigen::Isometry3d& T_initial, const Eigen::Isometry3d& T_result,
                            const std::string& title);
/// registration_view written as one self-contained page (three.js inlined), e.g. for
/// `sextant match --view pair.html`.
void write_registration_view(const std::filesystem::path& path, const PointCloud& reference,
                             const PointCloud& input, const Eigen::Isometry3d& T_initial,
                             const Eigen::Isometry3d& T_result, const std::string& title);

}  // namespace sextant
