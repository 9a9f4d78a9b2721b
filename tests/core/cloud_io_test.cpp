#include <gtest/gtest.h>

#include "sextant/core/io/cloud_io.hpp"
#include "test_util.hpp"

namespace sextant {
namespace {

using test::data_dir;
using test::expect_input_error;
using test::TempDir;
using test::write_text;

PointCloud sample_cloud(bool with_intensity) {
  PointCloud cloud;
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3f p(0.5f * i, -1.25f + i, 3.0f - 0.75f * i);
    if (with_intensity) {
      cloud.push_back(p, 0.1f * i);
    } else {
      cloud.push_back(p);
    }
  }
  return cloud;
}

void expect_same(const PointCloud& a, const PointCloud& b, float tolerance) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_LE((a[i] - b[i]).norm(), tolerance) << i;
}

class CloudRoundTrip : public ::testing::TestWithParam<const char*> {};

TEST_P(CloudRoundTrip, WriteThenReadGivesTheSameCloud) {
  TempDir dir;
  const std::string name = std::string("cloud") + GetParam();
  for (bool with_intensity : {false, true}) {
    const PointCloud cloud = sample_cloud(with_intensity);
    write_cloud(dir / name, cloud);
    const PointCloud back = read_cloud(dir / name);
    expect_same(cloud, back, 1e-5f);
    const bool keeps_intensity = name.find("xyz32") == std::string::npos;
    if (with_intensity && keeps_intensity) {
      ASSERT_TRUE(back.has_intensity()) << name;
      for (std::size_t i = 0; i < cloud.size(); ++i)
        EXPECT_NEAR(back.intensity()[i], cloud.intensity()[i], 1e-6f);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, CloudRoundTrip,
                         ::testing::Values(".3d", ".bin", ".xyz32.bin", ".pcd", ".ply", ".csv", ".xyz",
                                           ".txt"));

TEST(CloudIo, EmptyCloudIsWrittenButReadingItIsAnError) {
  TempDir dir;
  for (const char* ext : {".3d", ".bin", ".pcd", ".csv"}) {
    const auto file = dir / (std::string("empty") + ext);
    write_cloud(file, PointCloud());
    EXPECT_TRUE(std::filesystem::exists(file)) << ext;
    try {
      read_cloud(file);
      ADD_FAILURE() << ext;
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), file.string());
      EXPECT_NE(e.problem().find("no points"), std::string::npos) << e.what();
      EXPECT_EQ(e.where().rfind("byte ", 0), 0u) << e.what();
    }
  }
}

TEST(CloudIo, UnknownExtension) {
  TempDir dir;
  write_text(dir / "a.las", "x");
  expect_input_error([&] { read_cloud(dir / "a.las"); }, dir / "a.las", "",
                     "unknown point-cloud extension '.las'");
  expect_input_error([&] { write_cloud(dir / "b.foo", PointCloud()); }, dir / "b.foo", "", "unknown");
}

TEST(CloudIo, MissingFile) {
  TempDir dir;
  expect_input_error([&] { read_cloud(dir / "none.pcd"); }, dir / "none.pcd", "", "cannot open");
  expect_input_error([&] { read_cloud(dir / "none.3d"); }, dir / "none.3d", "", "cannot open");
}

TEST(CloudIo, CsvHeaderNonFiniteAndMalformed) {
  TempDir dir;
  write_text(dir / "a.csv", "x,y,z\n1,2,3\nnan,2,3\n4,5,6\n");
  ScanLoadReport report;
  EXPECT_EQ(read_cloud(dir / "a.csv", &report).size(), 2u);
  EXPECT_EQ(report.non_finite_dropped, 1u);
  EXPECT_EQ(report.header_lines_skipped, 1u);
  write_text(dir / "b.csv", "1,2,3\n4,5,6\n7,8,1.2.3\n");
  expect_input_error([&] { read_cloud(dir / "b.csv"); }, dir / "b.csv", "line 3", "'1.2.3'");
}

// Issue 64, class 3: a conversion that cannot keep a point says so. A .3d reader takes a point at or
// beyond 32.75 m for the SICK's "no return" and drops it; every reader drops a non-finite one. The
// writer counts exactly what reading the file back drops.
TEST(CloudIo, WritingCountsThePointsReadingBackDrops) {
  TempDir dir;
  PointCloud cloud;
  cloud.push_back(Eigen::Vector3f(1, 2, 3));
  cloud.push_back(Eigen::Vector3f(32.8f, 0, 0));  // beyond the range .3d keeps
  cloud.push_back(Eigen::Vector3f(20, 20, 20));   // 34.6 m: also beyond
  cloud.push_back(Eigen::Vector3f(32.7f, 0, 0));  // within
  cloud.push_back(Eigen::Vector3f(NAN, 0, 0));
  for (const char* name : {"far.3d", "far.pcd", "far.bin"}) {
    const CloudWriteReport written = write_cloud(dir / name, cloud);
    ScanLoadReport read;
    const PointCloud back = read_cloud(dir / name, &read);
    EXPECT_EQ(written.points, 5u) << name;
    EXPECT_EQ(written.non_finite, read.non_finite_dropped) << name;
    EXPECT_EQ(written.beyond_no_return_range, read.no_return_dropped) << name;
    EXPECT_EQ(back.size() + written.dropped_on_reading(), 5u) << name;
  }
  const CloudWriteReport uos = write_cloud(dir / "far.3d", cloud);
  EXPECT_EQ(uos.beyond_no_return_range, 2u);
  EXPECT_EQ(dropped_on_reading_note(dir / "far.3d", uos),
            "2 of 5 points written to " + (dir / "far.3d").string() +
                " lie at or beyond 32.75 m: a .3d reader takes them for the SICK's \"no return\" and drops "
                "them (write .pcd, .ply or .bin to keep them); 1 has a non-finite coordinate, which every "
                "reader drops");
  EXPECT_EQ(dropped_on_reading_note(dir / "a.pcd", write_cloud(dir / "a.pcd", cloud.subset({0, 1}))), "");
}

// Issue 26: a CSV with the header x,y,z,nx,ny,nz was refused ("expected 3 or 4 numbers"). Columns
// are found by the header's names, in any order; the columns not read are named in a warning.
TEST(CloudIo, CsvColumnsByName) {
  TempDir dir;
  write_text(dir / "normals.csv", "x,y,z,nx,ny,nz\n1,2,3,0,0,1\n4,5,6,0,1,0\n");
  ScanLoadReport report;
  const PointCloud normals = read_cloud(dir / "normals.csv", &report);
  ASSERT_EQ(normals.size(), 2u);
  EXPECT_EQ(normals[1], Eigen::Vector3f(4, 5, 6));
  EXPECT_FALSE(normals.has_intensity());
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0], "columns not read (no point field of Sextant's): nx, ny, nz");

  // CloudCompare's header, reordered axes, quotes and a reflectance column.
  write_text(dir / "cc.txt", "//Z,\"Y\",X,Reflectance,R\n3,2,1,0.5,255\n6,5,4,0.25,0\n");
  const PointCloud reordered = read_cloud(dir / "cc.txt");
  ASSERT_EQ(reordered.size(), 2u);
  EXPECT_EQ(reordered[0], Eigen::Vector3f(1, 2, 3));
  ASSERT_TRUE(reordered.has_intensity());
  EXPECT_FLOAT_EQ(reordered.intensity()[1], 0.25f);

  write_text(dir / "nameless.csv", "a,b,c\n1,2,3\n");
  expect_input_error([&] { read_cloud(dir / "nameless.csv"); }, dir / "nameless.csv", "line 1",
                     "the header names no 'x' column (columns: a, b, c)");
  write_text(dir / "short.csv", "x,y,z,nx\n1,2,3,0\n1,2,3\n");
  expect_input_error([&] { read_cloud(dir / "short.csv"); }, dir / "short.csv", "line 3",
                     "found 3 numbers, but the header names 4");
}

TEST(CloudIo, AllNonFiniteIsAnError) {
  TempDir dir;
  write_text(dir / "n.xyz", "nan 1 2\ninf 1 2\n");
  expect_input_error([&] { read_cloud(dir / "n.xyz"); }, dir / "n.xyz", "byte 16", "2 non-finite");
}

TEST(CloudIo, SharedPcdSamples) {
  const PointCloud room = read_cloud(data_dir() / "pcl_room_scan" / "room_scan1.pcd");  // binary_compressed
  EXPECT_EQ(room.size(), 112586u);
  const PointCloud velodyne = read_cloud(data_dir() / "velodyne_pair" / "fast_gicp_251370668.pcd");
  EXPECT_EQ(velodyne.size(), 69088u);
  EXPECT_TRUE(velodyne.has_intensity());
}

TEST(CloudIo, TruncatedPcd) {
  TempDir dir;
  write_text(dir / "t.pcd",
             "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 10\nHEIGHT 1\n"
             "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 10\nDATA binary\nabc");
  expect_input_error([&] { read_cloud(dir / "t.pcd"); }, dir / "t.pcd", "byte 123", "only 3 bytes follow");
}

}  // namespace
}  // namespace sextant
