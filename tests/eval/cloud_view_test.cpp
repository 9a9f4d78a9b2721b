// cloud_view: the page holds every cloud's points up to the cap (decoded back from the page and
// compared coordinate by coordinate), colours differ, nothing is loaded from the network, every
// text is escaped, states place the clouds by their poses, a missing three.js names its path and
// the package, and the page draws in headless Chromium (WebGL through SwiftShader).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "sextant/core/error.hpp"
#include "sextant/eval/cloud_view.hpp"
#include "sextant_test/run_view_page.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::size_t count_of(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

/// One cloud as the page's JSON holds it.
struct PageCloud {
  std::string color;
  std::size_t count = 0;
  std::string poses;                    ///< the JSON array text
  std::vector<Eigen::Vector3f> points;  ///< decoded from base64 float32 (little-endian)
};

std::string between(const std::string& text, const std::string& open, const std::string& close,
                    std::size_t from, std::size_t* end = nullptr) {
  const std::size_t a = text.find(open, from);
  if (a == std::string::npos) return "";
  const std::size_t b = text.find(close, a + open.size());
  if (end) *end = b;
  return text.substr(a + open.size(), b - a - open.size());
}

std::vector<PageCloud> clouds_of(const std::string& page) {
  const std::string json = between(page, "<script type=\"application/json\" id=\"sx-data\">", "</script>", 0);
  std::vector<PageCloud> out;
  for (std::size_t at = json.find("{\"color\":"); at != std::string::npos;
       at = json.find("{\"color\":", at + 1)) {
    PageCloud c;
    c.color = between(json, "\"color\":\"", "\"", at);
    c.count = std::stoul(between(json, "\"count\":", ",", at));
    c.poses = between(json, "\"poses\":[", "],\"points\"", at);
    c.points = test::page_points(between(json, "\"points\":\"", "\"", at));
    out.push_back(std::move(c));
  }
  return out;
}

/// A deterministic cloud of n points, each distinct (point i at (i, −i/2, i/7)).
PointCloud numbered(std::size_t n) {
  PointCloud cloud;
  for (std::size_t i = 0; i < n; ++i)
    cloud.push_back(
        Eigen::Vector3f(static_cast<float>(i), -0.5f * static_cast<float>(i), static_cast<float>(i) / 7.0f));
  return cloud;
}

/// Pages that load three.js from a relative URL do not need libjs-three.
CloudViewOptions referenced() {
  CloudViewOptions o;
  o.three_js_src = "three.min.js";
  return o;
}

bool three_js_installed() {
  return fs::is_regular_file(kThreeJsDir / "three.min.js");
}

TEST(CloudView, PageHoldsEveryCloudsPointsUpToTheCap) {
  CloudView view;
  view.max_points = 500;
  view.clouds.push_back({"big", numbered(700), "", {}, {}});
  view.clouds.push_back({"small", numbered(300), "", {}, {}});
  PointCloud holes = numbered(50);
  holes[3].x() = NAN, holes[10].y() = INFINITY, holes[49].z() = -NAN;
  view.clouds.push_back({"with non-finite points", holes, "", {}, {}});
  const std::string page = render_cloud_view(view, referenced());
  const std::vector<PageCloud> clouds = clouds_of(page);
  ASSERT_EQ(clouds.size(), 3u);
  // Over the cap: exactly 500 points, the i-th being point ⌊i·700/500⌋ of the cloud.
  ASSERT_EQ(clouds[0].points.size(), 500u);
  EXPECT_EQ(clouds[0].count, 500u);
  for (std::size_t i = 0; i < 500; ++i)
    ASSERT_EQ(clouds[0].points[i], view.clouds[0].points[i * 700 / 500]) << i;
  // Under the cap: every point, in order.
  ASSERT_EQ(clouds[1].points.size(), 300u);
  for (std::size_t i = 0; i < 300; ++i) ASSERT_EQ(clouds[1].points[i], view.clouds[1].points[i]) << i;
  // Non-finite points dropped, the others kept in order.
  ASSERT_EQ(clouds[2].points.size(), 47u);
  std::size_t k = 0;
  for (std::size_t i = 0; i < 50; ++i) {
    if (holes[i].allFinite()) {
      EXPECT_EQ(clouds[2].points[k++], holes[i]) << i;
    }
  }
  // The legend says what was kept of how many.
  EXPECT_NE(page.find("big <span class=\"sx-count\">500 of 700 points</span>"), std::string::npos);
  EXPECT_NE(page.find("small <span class=\"sx-count\">300 points</span>"), std::string::npos);
}

TEST(CloudView, DefaultCapIsSixtyThousandPointsPerCloud) {
  EXPECT_EQ(kCloudViewMaxPoints, 60000u);
  CloudView view;
  view.clouds.push_back({"large", numbered(150001), "", {}, {}});
  view.clouds.push_back({"at the cap", numbered(60000), "", {}, {}});
  const std::vector<PageCloud> clouds = clouds_of(render_cloud_view(view, referenced()));
  ASSERT_EQ(clouds.size(), 2u);
  ASSERT_EQ(clouds[0].points.size(), 60000u);
  EXPECT_EQ(clouds[0].points.front(), view.clouds[0].points[0]);
  EXPECT_EQ(clouds[0].points.back(), view.clouds[0].points[59999ull * 150001 / 60000]);
  EXPECT_EQ(clouds[1].points.size(), 60000u);
}

TEST(CloudView, SubsampleIsDeterministicAndSpreadOverTheCloud) {
  EXPECT_EQ(view_subsample(5, 10), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(view_subsample(10, 4), (std::vector<std::size_t>{0, 2, 5, 7}));
  const std::vector<std::size_t> a = view_subsample(1000003, 60000);
  ASSERT_EQ(a.size(), 60000u);
  EXPECT_EQ(a, view_subsample(1000003, 60000));
  for (std::size_t i = 1; i < a.size(); ++i) ASSERT_GT(a[i], a[i - 1]);
  EXPECT_EQ(a.front(), 0u);
  EXPECT_GE(a.back(), 1000003u - 1000003u / 60000u - 1u);  // reaches the end of the cloud
  EXPECT_TRUE(view_subsample(0, 10).empty());
}

int channel(const std::string& colour, int k) {
  return std::stoi(colour.substr(1 + 2 * static_cast<std::size_t>(k), 2), nullptr, 16);
}

double colour_distance(const std::string& a, const std::string& b) {
  double d = 0;
  for (int k = 0; k < 3; ++k) d += std::pow(channel(a, k) - channel(b, k), 2);
  return std::sqrt(d);
}

TEST(CloudView, EveryCloudGetsItsOwnColour) {
  CloudView view;
  for (int i = 0; i < 14; ++i) view.clouds.push_back({"c" + std::to_string(i), numbered(3), "", {}, {}});
  const std::string page = render_cloud_view(view, referenced());
  const std::vector<PageCloud> clouds = clouds_of(page);
  ASSERT_EQ(clouds.size(), 14u);
  std::set<std::string> distinct;
  for (const PageCloud& c : clouds) {
    ASSERT_EQ(c.color.size(), 7u) << c.color;
    distinct.insert(c.color);
    // The legend's swatch shows the colour the cloud is drawn in.
    EXPECT_NE(page.find("class=\"sx-swatch\" style=\"background:" + c.color + "\""), std::string::npos);
  }
  EXPECT_EQ(distinct.size(), 14u);
  // The first eight (the palette) are far apart, so a typical view's clouds are easy to tell apart.
  for (std::size_t a = 0; a < 8; ++a)
    for (std::size_t b = a + 1; b < 8; ++b)
      EXPECT_GT(colour_distance(clouds[a].color, clouds[b].color), 90.0)
          << clouds[a].color << " " << clouds[b].color;

  // A colour given explicitly is kept and not handed to another cloud.
  CloudView chosen;
  chosen.clouds.push_back({"given", numbered(2), "#3D8BFF", {}, {}});
  chosen.clouds.push_back({"default", numbered(2), "", {}, {}});
  const std::vector<PageCloud> c2 = clouds_of(render_cloud_view(chosen, referenced()));
  ASSERT_EQ(c2.size(), 2u);
  EXPECT_EQ(c2[0].color, "#3d8bff");  // the palette's first colour, lower case
  EXPECT_NE(c2[1].color, "#3d8bff");
  chosen.clouds[0].color = "red\" onload=\"x";
  EXPECT_THROW(render_cloud_view(chosen, referenced()), std::invalid_argument);
}

TEST(CloudView, PageLoadsNothingFromTheNetwork) {
  ASSERT_TRUE(three_js_installed()) << (kThreeJsDir / "three.min.js")
                                    << " is missing: install the Debian package libjs-three";
  CloudView view = registration_view(numbered(100), numbered(80), Eigen::Isometry3d::Identity(),
                                     Eigen::Isometry3d::Identity(), "offline");
  // Inlined: the library's exact bytes once, and no other script source or link.
  const std::string page = render_cloud_view(view);
  const std::string library = read_text(kThreeJsDir / "three.min.js");
  const std::size_t at = page.find(library);
  ASSERT_NE(at, std::string::npos);
  EXPECT_EQ(count_of(page, "<script"), 3u);  // three.js, the data, the viewer
  EXPECT_EQ(count_of(page, " src="), 0u);
  EXPECT_EQ(count_of(page, "href="), 0u);
  // three.min.js itself names the XHTML namespace and a paper in a shader comment (no requests);
  // everything else on the page is ours and must not name any URL.
  std::string ours = page;
  ours.erase(at, library.size());
  EXPECT_EQ(count_of(ours, "http://"), 0u);
  EXPECT_EQ(count_of(ours, "https://"), 0u);
  EXPECT_EQ(count_of(ours, "//cdn"), 0u);
  // three.js has loaders (fetch, XMLHttpRequest) that our script never calls.
  for (const std::string request : {"fetch(", "XMLHttpRequest", "import(", "@import", "Loader("})
    EXPECT_EQ(count_of(ours, request), 0u) << request;

  // Referenced: a relative file, no library on the page.
  CloudViewOptions shared;
  shared.three_js_src = "../three.min.js";
  const std::string small = render_cloud_view(view, shared);
  EXPECT_NE(small.find("<script src=\"../three.min.js\"></script>"), std::string::npos);
  EXPECT_EQ(small.find(library.substr(0, 200)), std::string::npos);
  EXPECT_EQ(count_of(small, "http://") + count_of(small, "https://"), 0u);
  // A remote library is refused.
  for (const std::string remote :
       {"https://cdn.example.org/three.min.js", "http://x/three.js", "//cdn.x/three.js"}) {
    shared.three_js_src = remote;
    EXPECT_THROW(render_cloud_view(view, shared), std::invalid_argument) << remote;
  }
}

TEST(CloudView, EscapesTitlesCaptionsStatesAndNames) {
  const std::string evil = "<script>alert(\"x\")</script> & 'q'";
  CloudView view;
  view.title = "T " + evil;
  view.caption = "C " + evil;
  view.states = {"S1 " + evil, "S2"};
  view.clouds.push_back({"N " + evil, numbered(4), "", {}, {}});
  const std::string page = render_cloud_view(view, referenced());
  EXPECT_EQ(page.find("<script>alert"), std::string::npos);
  EXPECT_EQ(count_of(page, "<script"), 3u);  // three.js (referenced), the data, the viewer
  const std::string escaped = "&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt; &amp; &#39;q&#39;";
  EXPECT_NE(page.find("<title>T " + escaped + "</title>"), std::string::npos);
  EXPECT_NE(page.find("<h1>T " + escaped + "</h1>"), std::string::npos);
  EXPECT_NE(page.find("C " + escaped), std::string::npos);
  EXPECT_NE(page.find("S1 " + escaped), std::string::npos);
  EXPECT_NE(page.find("N " + escaped), std::string::npos);
}

/// The 16 numbers of a pose in the page's JSON, column-major, or empty for null.
std::vector<double> pose_numbers(const std::string& poses, std::size_t state) {
  std::vector<std::string> items;
  std::size_t depth = 0, start = 0;
  for (std::size_t i = 0; i <= poses.size(); ++i) {
    const char c = i < poses.size() ? poses[i] : ',';
    if (c == '[') ++depth;
    if (c == ']') --depth;
    if (c == ',' && depth == 0) items.push_back(poses.substr(start, i - start)), start = i + 1;
  }
  std::vector<double> out;
  if (state >= items.size() || items[state] == "null") return out;
  std::istringstream in(items[state].substr(1, items[state].size() - 2));
  for (std::string number; std::getline(in, number, ',');) out.push_back(std::stod(number));
  return out;
}

void expect_pose(const std::vector<double>& numbers, const Eigen::Isometry3d& T) {
  ASSERT_EQ(numbers.size(), 16u);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      EXPECT_NEAR(numbers[static_cast<std::size_t>(4 * c + r)], T.matrix()(r, c), 1e-15);
}

TEST(CloudView, StatesPlaceEachCloudByItsPose) {
  Eigen::Isometry3d initial = Eigen::Isometry3d::Identity(), result = Eigen::Isometry3d::Identity();
  initial.translation() = Eigen::Vector3d(1.5, -2.0, 0.25);
  result.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, 0.1, 1.0).normalized()).toRotationMatrix();
  result.translation() = Eigen::Vector3d(0.1, 0.2, 0.3);
  const CloudView view = registration_view(numbered(10), numbered(20), initial, result, "pair");
  ASSERT_EQ(view.states.size(), 2u);
  const std::string page = render_cloud_view(view, referenced());
  const std::vector<PageCloud> clouds = clouds_of(page);
  ASSERT_EQ(clouds.size(), 2u);
  expect_pose(pose_numbers(clouds[0].poses, 0), Eigen::Isometry3d::Identity());
  expect_pose(pose_numbers(clouds[0].poses, 1), Eigen::Isometry3d::Identity());
  expect_pose(pose_numbers(clouds[1].poses, 0), initial);
  expect_pose(pose_numbers(clouds[1].poses, 1), result);
  EXPECT_NE(page.find(">before (initial guess)</button>"), std::string::npos);
  EXPECT_NE(page.find(">after (result)</button>"), std::string::npos);

  // A diverged result (non-finite pose) and a cloud left out of a state: null, not drawn there.
  CloudView odd = view;
  odd.clouds[1].poses[1].translation().x() = NAN;
  odd.clouds[0].in_states = {false, true};
  const std::vector<PageCloud> c2 = clouds_of(render_cloud_view(odd, referenced()));
  ASSERT_EQ(c2.size(), 2u);
  EXPECT_TRUE(pose_numbers(c2[0].poses, 0).empty());
  EXPECT_EQ(pose_numbers(c2[0].poses, 1).size(), 16u);
  EXPECT_TRUE(pose_numbers(c2[1].poses, 1).empty());

  // Counts that do not match the states are refused.
  CloudView bad = view;
  bad.clouds[1].poses.push_back(result);
  EXPECT_THROW(render_cloud_view(bad, referenced()), std::invalid_argument);
  bad = view;
  bad.clouds[0].in_states = {true};
  EXPECT_THROW(render_cloud_view(bad, referenced()), std::invalid_argument);
}

TEST(CloudView, MissingThreeJsNamesThePathAndThePackage) {
  CloudViewOptions options;
  options.three_js_dir = "/nonexistent/sextant/three";
  CloudView view;
  view.clouds.push_back({"a", numbered(3), "", {}, {}});
  try {
    render_cloud_view(view, options);
    FAIL() << "no error for a missing three.js";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("/nonexistent/sextant/three/three.min.js"), std::string::npos) << what;
    EXPECT_NE(what.find("libjs-three"), std::string::npos) << what;
  }
  EXPECT_THROW(write_three_js(fs::temp_directory_path(), options.three_js_dir), InputError);
  // A page that references the library does not need it at render time.
  options.three_js_src = "../three.min.js";
  EXPECT_NO_THROW(render_cloud_view(view, options));
}

TEST(CloudView, WriteThreeJsCopiesTheLibraryBesideThePages) {
  ASSERT_TRUE(three_js_installed()) << "install the Debian package libjs-three";
  const fs::path dir = fs::temp_directory_path() / "sextant_cloud_view_copy";
  fs::remove_all(dir);
  const fs::path copy = write_three_js(dir);
  EXPECT_EQ(copy, dir / "three.min.js");
  EXPECT_EQ(read_text(copy), read_text(kThreeJsDir / "three.min.js"));
  const auto stamp = fs::last_write_time(copy);
  EXPECT_EQ(write_three_js(dir), copy);  // already there and identical: left alone
  EXPECT_EQ(fs::last_write_time(copy), stamp);
  fs::remove_all(dir);
}

// The page in a real browser: its script decodes every cloud and WebGL draws (SwiftShader).
TEST(CloudView, DrawsInHeadlessChromium) {
  ASSERT_EQ(std::system("command -v chromium >/dev/null 2>&1"), 0)
      << "chromium is not installed: scripts/test.sh installs it (apt-get install chromium)";
  ASSERT_TRUE(three_js_installed()) << "install the Debian package libjs-three";
  const fs::path dir = fs::temp_directory_path() / "sextant_cloud_view_chromium";
  fs::remove_all(dir);
  fs::create_directories(dir);
  Eigen::Isometry3d initial = Eigen::Isometry3d::Identity();
  initial.translation() = Eigen::Vector3d(5, 0, 0);
  write_registration_view(dir / "pair.html", numbered(70000), numbered(1234), initial,
                          Eigen::Isometry3d::Identity(), "Chromium check");
  const std::string command =
      "timeout 120 chromium --headless --no-sandbox --disable-gpu --use-gl=swiftshader "
      "--enable-unsafe-swiftshader --no-first-run --disable-background-networking --user-data-dir='" +
      (dir / "profile").string() + "' --virtual-time-budget=10000 --dump-dom 'file://" +
      (dir / "pair.html").string() + "' > '" + (dir / "dom.html").string() + "' 2>/dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const std::string dom = read_text(dir / "dom.html");
  EXPECT_NE(dom.find("data-sx-decoded=\"60000,1234\""), std::string::npos) << dom.substr(0, 2000);
  EXPECT_NE(dom.find("data-sx-webgl=\"ok\""), std::string::npos) << dom.substr(0, 2000);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace sextant
