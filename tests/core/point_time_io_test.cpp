// Per-point time through the PCD and PLY readers and writers: files written here byte by byte, one per
// driver's name and type of point_time.hpp's table and per encoding, read back with the times put in.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "sextant/core/io/cloud_io.hpp"
#include "test_util.hpp"

namespace sextant {
namespace {

using test::TempDir;

/// A time field as a driver writes it: its name, PCD type letter and size, and the raw values.
struct TimeField {
  std::string name;
  char type;  ///< 'U', 'I' or 'F'
  int size;
  std::vector<double> raw;     ///< one per point
  std::vector<float> seconds;  ///< what the reader must give (from the stamp, or the earliest point)
};

constexpr double kEpoch = 1565943695.25;  // a stamp in 2019, exact in binary

std::vector<TimeField> drivers_fields() {
  return {
      {"t", 'U', 4, {0, 25'000'000, 50'000'000, 99'951'172}, {0.0f, 0.025f, 0.05f, 0.099951172f}},  // Ouster
      {"time", 'F', 4, {-0.1, -0.05, -0.025, 0.0}, {-0.1f, -0.05f, -0.025f, 0.0f}},  // Velodyne
      {"timestamp",
       'F',
       8,
       {kEpoch + 0.0, kEpoch + 0.03125, kEpoch + 0.0625, kEpoch + 0.09375},
       {0.0f, 0.03125f, 0.0625f, 0.09375f}},  // Hesai / Robosense: seconds since the epoch
      // livox_ros_driver2: nanoseconds since the epoch (1.5e18 ns, in 2017, and 2^21 ns steps: exact)
      {"timestamp",
       'F',
       8,
       {1.5e18, 1.5e18 + 2097152, 1.5e18 + 4194304, 1.5e18 + 8388608},
       {0.0f, 0.002097152f, 0.004194304f, 0.008388608f}},
      {"offset_time", 'U', 4, {0, 1'000'000, 2'000'000, 3'000'000}, {0.0f, 0.001f, 0.002f, 0.003f}},  // Livox
      {"time_offset", 'U', 4, {0, 40'000, 80'000, 120'000}, {0.0f, 4e-5f, 8e-5f, 1.2e-4f}},
      {"ts", 'F', 4, {0.0, 0.01, 0.02, 0.03}, {0.0f, 0.01f, 0.02f, 0.03f}},
      {"t", 'I', 8, {3, 1'000'003, 2'000'003, 5'000'003}, {3e-9f, 0.001000003f, 0.002000003f, 0.005000003f}},
  };
}

const float kXyz[4][3] = {
    {1.0f, 2.0f, 3.0f}, {-4.5f, 0.25f, 1.5f}, {10.0f, -3.0f, 0.5f}, {0.0f, 7.0f, -1.0f}};

void put(std::string& bytes, double v, char type, int size) {
  unsigned char b[8];
  if (type == 'F' && size == 4) {
    const float f = static_cast<float>(v);
    std::memcpy(b, &f, 4);
  } else if (type == 'F') {
    std::memcpy(b, &v, 8);
  } else if (type == 'U' && size == 4) {
    const auto u = static_cast<std::uint32_t>(v);
    std::memcpy(b, &u, 4);
  } else {
    const auto i = static_cast<std::int64_t>(v);
    std::memcpy(b, &i, 8);
  }
  bytes.append(reinterpret_cast<const char*>(b), static_cast<std::size_t>(size));
}

std::string number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

/// A PCD file: x y z, a `ring` field the reader ignores, then the time field; `encoding` ascii,
/// binary or binary_compressed (LZF made of literal runs only, which is valid LZF).
void write_pcd(const std::filesystem::path& file, const TimeField& f, const std::string& encoding) {
  std::string out = "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z ring " + f.name + "\nSIZE 4 4 4 2 " +
                    std::to_string(f.size) + "\nTYPE F F F U " + f.type +
                    "\nCOUNT 1 1 1 1 1\nWIDTH 4\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\nDATA " +
                    encoding + "\n";
  std::string data;
  if (encoding == "ascii") {
    for (int i = 0; i < 4; ++i)
      out += number(kXyz[i][0]) + " " + number(kXyz[i][1]) + " " + number(kXyz[i][2]) + " 7 " +
             number(f.raw[static_cast<std::size_t>(i)]) + "\n";
  } else if (encoding == "binary") {
    for (int i = 0; i < 4; ++i) {
      for (int k = 0; k < 3; ++k) put(data, kXyz[i][k], 'F', 4);
      data += std::string("\x07\x00", 2);
      put(data, f.raw[static_cast<std::size_t>(i)], f.type, f.size);
    }
    out += data;
  } else {  // field-major: every x, every y, …
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 4; ++i) put(data, kXyz[i][k], 'F', 4);
    for (int i = 0; i < 4; ++i) data += std::string("\x07\x00", 2);
    for (double v : f.raw) put(data, v, f.type, f.size);
    std::string lzf;
    for (std::size_t at = 0; at < data.size(); at += 32) {
      const std::size_t n = std::min<std::size_t>(32, data.size() - at);
      lzf += static_cast<char>(n - 1);
      lzf += data.substr(at, n);
    }
    const std::uint32_t sizes[2] = {static_cast<std::uint32_t>(lzf.size()),
                                    static_cast<std::uint32_t>(data.size())};
    out.append(reinterpret_cast<const char*>(sizes), 8);
    out += lzf;
  }
  std::ofstream(file, std::ios::binary) << out;
}

/// PLY's names of PCD's types.
std::string ply_type(char type, int size) {
  if (type == 'F') return size == 4 ? "float" : "double";
  if (type == 'U') return size == 4 ? "uint" : "uint64";  // PLY has no 64-bit integers: not written
  return size == 4 ? "int" : "int64";
}

/// A PLY file: x y z, the time property, an intensity; ascii or binary_big_endian (reversed bytes).
void write_ply(const std::filesystem::path& file, const TimeField& f, bool big_endian) {
  std::string out =
      std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "ascii") +
      " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nproperty " +
      ply_type(f.type, f.size) + " " + f.name + "\nproperty float intensity\nend_header\n";
  for (int i = 0; i < 4; ++i) {
    if (!big_endian) {
      out += number(kXyz[i][0]) + " " + number(kXyz[i][1]) + " " + number(kXyz[i][2]) + " " +
             number(f.raw[static_cast<std::size_t>(i)]) + " 0.5\n";
      continue;
    }
    const auto reversed = [&](double v, char type, int size) {
      std::string b;
      put(b, v, type, size);
      out.append(b.rbegin(), b.rend());
    };
    for (int k = 0; k < 3; ++k) reversed(kXyz[i][k], 'F', 4);
    reversed(f.raw[static_cast<std::size_t>(i)], f.type, f.size);
    reversed(0.5, 'F', 4);
  }
  std::ofstream(file, std::ios::binary) << out;
}

void expect_times(const PointCloud& cloud, const TimeField& f, const std::string& what) {
  ASSERT_EQ(cloud.size(), 4u) << what;
  ASSERT_TRUE(cloud.has_time()) << what;
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(cloud[i], Eigen::Vector3f(kXyz[i][0], kXyz[i][1], kXyz[i][2])) << what;
    EXPECT_NEAR(cloud.time()[i], f.seconds[i], 2e-7f) << what << ", point " << i;
  }
}

TEST(PointTimeFiles, PcdKeepsEveryDriversTimeInEveryEncoding) {
  TempDir dir;
  for (const TimeField& f : drivers_fields())
    for (const char* encoding : {"ascii", "binary", "binary_compressed"}) {
      const std::string what = f.name + " " + f.type + std::to_string(f.size) + " " + encoding;
      const auto file = dir / "scan.pcd";
      write_pcd(file, f, encoding);
      expect_times(read_cloud(file), f, what);
    }
}

TEST(PointTimeFiles, PlyKeepsEveryDriversTimeAsciiAndBinary) {
  TempDir dir;
  for (const TimeField& f : drivers_fields()) {
    if (f.type != 'F' && f.size == 8) continue;  // PLY has no 64-bit integer type
    for (bool big_endian : {false, true}) {
      const std::string what = f.name + " " + ply_type(f.type, f.size) + (big_endian ? " binary" : " ascii");
      const auto file = dir / "scan.ply";
      write_ply(file, f, big_endian);
      const PointCloud cloud = read_cloud(file);
      expect_times(cloud, f, what);
      ASSERT_TRUE(cloud.has_intensity()) << what;
      EXPECT_FLOAT_EQ(cloud.intensity()[3], 0.5f) << what;
    }
  }
}

TEST(PointTimeFiles, AFileWithoutATimeFieldHasNone) {
  TempDir dir;
  TimeField other = drivers_fields()[1];
  other.name = "times";  // no driver's name
  write_pcd(dir / "scan.pcd", other, "binary");
  EXPECT_FALSE(read_cloud(dir / "scan.pcd").has_time());
  write_ply(dir / "scan.ply", other, false);
  EXPECT_FALSE(read_cloud(dir / "scan.ply").has_time());
}

TEST(PointTimeFiles, APointWithANonFiniteTimeIsDroppedAndCounted) {
  TempDir dir;
  TimeField f = drivers_fields()[1];
  f.raw[2] = std::nan("");
  write_pcd(dir / "scan.pcd", f, "ascii");
  ScanLoadReport report;
  const PointCloud cloud = read_cloud(dir / "scan.pcd", &report);
  EXPECT_EQ(report.points_read, 4u);
  EXPECT_EQ(report.non_finite_dropped, 1u);
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_FLOAT_EQ(cloud.time()[2], 0.0f);  // the fourth point's
}

TEST(PointTimeFiles, WrittenCloudsKeepTheirTimesThroughPcdAndPly) {
  TempDir dir;
  for (bool with_intensity : {false, true}) {
    PointCloud cloud;
    std::vector<float> time;
    for (int i = 0; i < 5; ++i) {
      const Eigen::Vector3f p(0.5f * i, -1.25f + i, 3.0f - 0.75f * i);
      if (with_intensity)
        cloud.push_back(p, 0.1f * i);
      else
        cloud.push_back(p);
      time.push_back(-0.1f + 0.0237f * i);
    }
    cloud.set_time(time);
    for (const char* name : {"timed.pcd", "timed.ply"}) {
      write_cloud(dir / name, cloud);
      const PointCloud back = read_cloud(dir / name);
      ASSERT_TRUE(back.has_time()) << name;
      EXPECT_EQ(back.time(), time) << name;
      EXPECT_EQ(back.points(), cloud.points()) << name;
      EXPECT_EQ(back.has_intensity(), with_intensity) << name;
      if (with_intensity) {
        EXPECT_EQ(back.intensity(), cloud.intensity()) << name;
      }
    }
  }
}

TEST(PointTimeFiles, AFormatWithoutTimesSaysTheyAreNotWritten) {
  TempDir dir;
  PointCloud cloud(std::vector<Eigen::Vector3f>(3, Eigen::Vector3f(1.0f, 2.0f, 3.0f)));
  cloud.set_time({0.0f, 0.05f, 0.1f});
  const CloudWriteReport bin = write_cloud(dir / "timed.bin", cloud);
  EXPECT_TRUE(bin.times_dropped);
  EXPECT_NE(dropped_on_reading_note(dir / "timed.bin", bin).find("times are not written"), std::string::npos);
  const CloudWriteReport pcd = write_cloud(dir / "timed.pcd", cloud);
  EXPECT_FALSE(pcd.times_dropped);
  EXPECT_EQ(dropped_on_reading_note(dir / "timed.pcd", pcd), "");
  cloud.set_time({});
  EXPECT_FALSE(write_cloud(dir / "plain.bin", cloud).times_dropped);
}

}  // namespace
}  // namespace sextant
