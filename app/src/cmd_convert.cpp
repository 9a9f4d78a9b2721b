// `sextant convert <in> <out>`: any point-cloud format to any other (formats by extension).
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "sextant/core/io/cloud_io.hpp"

namespace sextant::cli {

void add_convert_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "convert",
      "Convert a point cloud between formats (.3d .bin .xyz32.bin .pcd .ply .csv .xyz .txt); "
      "uos .3d files are converted between centimetres/left-handed and metres/right-handed");
  auto in = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  cmd->add_option("in", *in, "Input cloud file")->required();
  cmd->add_option("out", *out, "Output cloud file (written atomically)")->required();
  cmd->callback([&exit_code, in, out] {
    exit_code = guarded([in, out] {
      cloud_format(*out);  // an unknown output extension fails before the input is read
      ScanLoadReport report;
      const PointCloud cloud = read_cloud(*in, &report);
      const CloudWriteReport written = write_cloud(*out, cloud);
      std::cout << "wrote " << cloud.size() << " points to " << *out << " (" << report.non_finite_dropped
                << " non-finite and " << report.no_return_dropped << " no-return points of " << *in
                << " dropped)\n";
      // A format that cannot keep a point (a .3d file and far points) says so.
      if (const std::string note = dropped_on_reading_note(*out, written); !note.empty())
        std::cerr << "warning: " << note << "\n";
      return 0;
    });
  });
}

}  // namespace sextant::cli
