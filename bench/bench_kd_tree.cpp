// ICP's k-d tree (matchers/src/icp/kd_tree.hpp) against nanoflann (Debian's libnanoflann-dev), on real
// scans at the sizes ICP uses (docs/design.md, "Libraries we use and code we keep"):
//   - build over a whole reference scan (set_reference),
//   - the nearest reference point within max_correspondence_distance = 1 m of each point of the
//     next scan (the correspondences of one ICP iteration),
//   - the 10 nearest reference points of each reference point (the PCA normals of icp_p2l).
// Both trees get the finite points of the same scan, leaves of 8 points (ours' default; nanoflann's
// leaf_max_size). The query sets are every 4th point (nearest) and every 8th (k nearest). Run:
//   build/bench/bench_kd_tree --benchmark_repetitions=7 --benchmark_report_aggregates_only=true
//       --benchmark_enable_random_interleaving=true
// Argument 0 is the KITTI pair (124,668 points), 1 the Velodyne pair (69,088).
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include <nanoflann.hpp>

#include "icp/kd_tree.hpp"
#include "sextant/core/io/cloud_io.hpp"

namespace sextant {
namespace {

constexpr float kMaxSquaredDistance = 1.0f;  // ICP's default max_correspondence_distance, squared
constexpr std::size_t kNormalNeighbours = 10;
constexpr int kLeafSize = 8;

struct Pair {
  std::vector<Eigen::Vector3f> reference, next;  // finite points only
};

std::vector<Eigen::Vector3f> finite_points(const PointCloud& cloud) {
  std::vector<Eigen::Vector3f> out;
  out.reserve(cloud.size());
  for (const Eigen::Vector3f& p : cloud.points())
    if (p.allFinite()) out.push_back(p);
  return out;
}

const Pair& scan_pair(int which) {
  static const std::array<Pair, 2> pairs = [] {
    const std::string d = SEXTANT_DATA_DIR;
    std::array<Pair, 2> p;
    p[0] = {finite_points(read_cloud(d + "/kitti00_pair/000000.xyz32.bin")),
            finite_points(read_cloud(d + "/kitti00_pair/000001.xyz32.bin"))};
    p[1] = {finite_points(read_cloud(d + "/velodyne_pair/fast_gicp_251370668.pcd")),
            finite_points(read_cloud(d + "/velodyne_pair/fast_gicp_251371071.pcd"))};
    return p;
  }();
  return pairs[static_cast<std::size_t>(which)];
}

std::vector<Eigen::Vector3f> every(const std::vector<Eigen::Vector3f>& points, std::size_t stride) {
  std::vector<Eigen::Vector3f> out;
  for (std::size_t i = 0; i < points.size(); i += stride) out.push_back(points[i]);
  return out;
}

/// nanoflann's view of a point vector.
struct Points {
  const std::vector<Eigen::Vector3f>* points;
  std::size_t kdtree_get_point_count() const { return points->size(); }
  float kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*points)[i][static_cast<int>(dim)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};
using NanoTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, Points>, Points, 3,
                                                     std::uint32_t>;

/// The nearest point within a radius, as KdTree::nearest: the radius bounds the search from the
/// start (nanoflann's KNNResultSet would start from +∞ and filter afterwards).
class NearestWithin {
 public:
  explicit NearestWithin(float max_squared_distance) : worst_(max_squared_distance) {}
  bool addPoint(float d2, std::uint32_t index) {
    if (d2 <= worst_) {
      worst_ = d2;
      index_ = index;
      found_ = true;
    }
    return true;
  }
  float worstDist() const { return worst_; }
  bool full() const { return found_; }
  bool found() const { return found_; }

 private:
  float worst_;
  std::uint32_t index_ = 0;
  bool found_ = false;
};

void BM_BuildOurs(benchmark::State& state) {
  const Pair& pair = scan_pair(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    KdTree tree(pair.reference, kLeafSize);
    benchmark::DoNotOptimize(tree.size());
  }
  state.counters["points"] = static_cast<double>(pair.reference.size());
}

void BM_BuildNanoflann(benchmark::State& state) {
  const Pair& pair = scan_pair(static_cast<int>(state.range(0)));
  const Points points{&pair.reference};  // nanoflann keeps a reference to it
  for (auto _ : state) {
    NanoTree tree(3, points, nanoflann::KDTreeSingleIndexAdaptorParams(kLeafSize));
    benchmark::DoNotOptimize(tree.root_node);
  }
  state.counters["points"] = static_cast<double>(pair.reference.size());
}

void BM_NearestOurs(benchmark::State& state) {
  const Pair& pair = scan_pair(static_cast<int>(state.range(0)));
  const KdTree tree(pair.reference, kLeafSize);
  const std::vector<Eigen::Vector3f> queries = every(pair.next, 4);
  std::size_t found = 0;
  for (auto _ : state) {
    found = 0;
    KdTree::Neighbour n;
    for (const Eigen::Vector3f& q : queries) found += tree.nearest(q, kMaxSquaredDistance, &n);
    benchmark::DoNotOptimize(found);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * queries.size()));
  state.counters["found"] = static_cast<double>(found);
}

void BM_NearestNanoflann(benchmark::State& state) {
  const Pair& pair = scan_pair(static_cast<int>(state.range(0)));
  const Points points{&pair.reference};  // nanoflann keeps a reference to it
  const NanoTree tree(3, points, nanoflann::KDTreeSingleIndexAdaptorParams(kLeafSize));
  const std::vector<Eigen::Vector3f> queries = every(pair.next, 4);
  std::size_t found = 0;
  for (auto _ : state) {
    found = 0;
    for (const Eigen::Vector3f& q : queries) {
      NearestWithin result(kMaxSquaredDistance);
      tree.findNeighbors(result, q.data(), nanoflann::SearchParams());
      found += result.found();
    }
    benchmark::DoNotOptimize(found);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * queries.size()));
  state.counters["found"] = static_cast<double>(found);
}

void BM_KNearestOurs(benchmark::State& state) {
  const Pair& pair = scan_pair(static_cast<int>(state.range(0)));
  const KdTree tree(pair.reference, kLeafSize);
  const std::vector<Eigen::Vector3f> queries = every(pair.reference, 8);
  std::vector<KdTree::Neighbour> out;
  for (auto _ : state) {
    for (const Eigen::Vector3f& q : queries) {
      tree.k_nearest(q, kNormalNeighbours, out);
      benchmark::DoNotOptimize(out.data());
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * queries.size()));
}

void BM_KNearestNanoflann(benchmark::State& state) {
  const Pair& pair = scan_pair(static_cast<int>(state.range(0)));
  const Points points{&pair.reference};  // nanoflann keeps a reference to it
  const NanoTree tree(3, points, nanoflann::KDTreeSingleIndexAdaptorParams(kLeafSize));
  const std::vector<Eigen::Vector3f> queries = every(pair.reference, 8);
  std::array<std::uint32_t, kNormalNeighbours> index{};
  std::array<float, kNormalNeighbours> d2{};
  for (auto _ : state) {
    for (const Eigen::Vector3f& q : queries) {
      benchmark::DoNotOptimize(tree.knnSearch(q.data(), kNormalNeighbours, index.data(), d2.data()));
      benchmark::DoNotOptimize(index.data());
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * queries.size()));
}

BENCHMARK(BM_BuildOurs)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BuildNanoflann)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NearestOurs)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_NearestNanoflann)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_KNearestOurs)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_KNearestNanoflann)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sextant

BENCHMARK_MAIN();
