// The built-in synthetic campus as a command-line dataset (commands.hpp): `sextant odometry campus`,
// `sextant info campus`.
#include "commands.hpp"
#include "sextant/synth/campus.hpp"

namespace sextant::cli {

bool names_builtin_campus(const std::string& dataset) {
  return dataset == "campus" || dataset == "synthetic";
}

std::unique_ptr<Dataset> open_builtin_campus(std::uint64_t seed) {
  return std::make_unique<synth::CampusDataset>(synth::generate_campus(synth::CampusSettings{}, seed));
}

}  // namespace sextant::cli
