// Test-only: writes a long recording with known scans, or reads every scan of one, for measuring peak
// memory (docs/formats.md, "Recordings: memory"):
//   sextant_recording_tool write long.mcap 18000 [points per scan]   (or long.bag)
//   /usr/bin/time -v sextant_recording_tool read long.mcap
// and the fuzzers' seeds (fuzz/seeds/): sextant_recording_tool seeds fuzz/seeds
#include <cstdlib>
#include <iostream>
#include <string>

#include "bag_writer.hpp"
#include "known_scans.hpp"
#include "mcap_writer.hpp"
#include "recording_dataset.hpp"
#include "sextant/recordings/recording.hpp"

int main(int argc, char** argv) {
  using namespace sextant;
  if (argc < 3) {
    std::cerr << "usage: " << argv[0] << " write FILE.mcap|FILE.bag SCANS [POINTS] | read RECORDING\n";
    return 2;
  }
  const std::string command = argv[1];
  const std::filesystem::path path = argv[2];
  if (command == "write" && argc >= 4) {
    const std::size_t scans = std::stoul(argv[3]), points = argc > 4 ? std::stoul(argv[4]) : 256;
    const bool bag = path.extension() == ".bag";
    std::vector<test::TestMessage> messages;
    for (std::size_t k = 0; k < scans; ++k)
      messages.push_back(test::known_message(k, bag, "/points", points));
    if (bag) {
      test::write_bag(path, messages, test::bag_options("lz4", 50, true, false));
    } else {
      test::McapOptions o;
      o.compression = "zstd";
      o.messages_per_chunk = 50;
      test::write_mcap(path, messages, o);
    }
    std::cout << "wrote " << scans << " scans of " << points << " points to " << path.string() << "\n";
    return 0;
  }
  if (command == "seeds") {  // two scans of 3 points and a String message between them, small
    const auto messages = [](bool ros1) {
      std::vector<test::TestMessage> m = test::known_messages(2, ros1, "/points", 3);
      return m;
    };
    test::BagOptions bag = test::bag_options("none", 3);
    bag.header_bytes = 128;
    test::write_bag(path / "small.bag", messages(true), bag);
    bag.compression = "lz4";
    test::write_bag(path / "small_lz4.bag", messages(true), bag);
    test::McapOptions mcap;
    mcap.messages_per_chunk = 3;
    test::write_mcap(path / "small.mcap", messages(false), mcap);
    mcap.compression = "zstd";
    test::write_mcap(path / "small_zstd.mcap", messages(false), mcap);
    std::cout << "wrote small.bag, small_lz4.bag, small.mcap, small_zstd.mcap to " << path.string() << "\n";
    return 0;
  }
  if (command == "read") {
    const std::unique_ptr<Dataset> opened = open_recording(path);
    const auto& d = dynamic_cast<const recordings_detail::RecordingDataset&>(*opened);
    std::size_t points = 0;
    for (std::size_t i = 0; i < d.size(); ++i) points += d.scan(i).size();
    std::cout << "read " << d.size() << " scans, " << points << " points; index " << d.index_bytes()
              << " bytes; chunks decompressed " << d.cache().loads() << ", at most "
              << d.cache().largest_size() << " held\n";
    return 0;
  }
  std::cerr << "unknown command " << command << "\n";
  return 2;
}
