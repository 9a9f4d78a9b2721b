// The matchers' traits by name (matcher_traits.hpp): one row per matcher that has any.
#include "sextant/matchers/matcher_traits.hpp"

namespace sextant {
namespace {

struct Row {
  const char* name;
  MatcherTraits traits;  ///< judges itself, presets, wide basin, layer pyramid, common view by default
};

constexpr Row kRows[] = {
    {"mlndt", {true, true, true, true, true}}, {"fbmlndt", {true, true, true, true, false}},
    // ndt, icp_p2p, icp_p2l, pcl_ndt, pcl_icp, pcl_gicp: none
};

}  // namespace

MatcherTraits matcher_traits(const std::string& name) {
  for (const Row& row : kRows)
    if (name == row.name) return row.traits;
  return {};
}

}  // namespace sextant
