// sensor_msgs/PointCloud2 decoded from both serializations: every datatype, both byte orders of the
// point data and of the CDR message, organised clouds with padding, dropped points counted, per-point
// time in the drivers' conventions, and malformed messages refused with the byte they break at.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "cloud_writer.hpp"
#include "point_cloud2.hpp"
#include "sextant/core/error.hpp"

namespace sextant {
namespace {

using namespace recordings_detail;
using test::TestCloud;
using test::TestField;

const Place kPlace{"cloud.bag", 1000, "", " of the test message"};

PointCloud decode(const test::Bytes& bytes, MessageEncoding encoding, ScanLoadReport* report = nullptr) {
  const PointCloud2Message m = parse_point_cloud2(bytes, encoding, kPlace);
  return point_cloud2_points(m, bytes, kPlace, report);
}

std::string problem(const test::Bytes& bytes, MessageEncoding encoding) {
  try {
    decode(bytes, encoding);
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "cloud.bag");
    EXPECT_NE(e.where().find("byte "), std::string::npos) << e.where();
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

TEST(PointCloud2, EveryDatatypeOfIntensityAndBothByteOrders) {
  for (bool big : {false, true}) {
    for (std::uint8_t type = 1; type <= 8; ++type) {
      const TestCloud c = test::make_test_cloud({{"x", 8}, {"y", 8}, {"z", 7}, {"intensity", type}},
                                                {{1.5, -2.25, 3.0, 100.0}, {-4.0, 5.5, -6.125, 7.0}}, 1, big);
      for (bool ros1 : {true, false}) {
        const PointCloud cloud = decode(ros1 ? test::serialize_ros1(c) : test::serialize_cdr(c, big),
                                        ros1 ? MessageEncoding::ros1 : MessageEncoding::cdr);
        ASSERT_EQ(cloud.size(), 2u);
        EXPECT_EQ(cloud[0], Eigen::Vector3f(1.5f, -2.25f, 3.0f)) << int(type) << big;
        EXPECT_EQ(cloud[1], Eigen::Vector3f(-4.0f, 5.5f, -6.125f));
        EXPECT_EQ(cloud.intensity()[0], 100.0f) << int(type);
        EXPECT_EQ(cloud.intensity()[1], 7.0f);
        EXPECT_FALSE(cloud.has_time());
      }
    }
  }
}

TEST(PointCloud2, AnOrganisedCloudWithPaddingAndItsDroppedPoints) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  // 2 rows × 3: a NaN, an Inf and an empty cell (0, 0, 0) among them; 3 bytes after each point, 5 after each
  // row.
  const TestCloud c = test::make_test_cloud(
      {{"x", 7}, {"y", 7}, {"z", 7}},
      {{1, 2, 3}, {nan, 0, 0}, {4, 5, 6}, {0, 0, 0}, {7, inf, 9}, {10, 11, 12}}, 2, false, 3, 5);
  ASSERT_EQ(c.point_step, 15u);
  ASSERT_EQ(c.row_step, 50u);
  ScanLoadReport report;
  const PointCloud cloud = decode(test::serialize_cdr(c), MessageEncoding::cdr, &report);
  ASSERT_EQ(cloud.size(), 3u);
  EXPECT_EQ(cloud[0], Eigen::Vector3f(1, 2, 3));
  EXPECT_EQ(cloud[1], Eigen::Vector3f(4, 5, 6));
  EXPECT_EQ(cloud[2], Eigen::Vector3f(10, 11, 12));
  EXPECT_EQ(report.points_read, 6u);
  EXPECT_EQ(report.non_finite_dropped, 2u);
  EXPECT_EQ(report.no_return_dropped, 1u);
  EXPECT_FALSE(cloud.has_intensity());
}

TEST(PointCloud2, PerPointTimeInTheDriversConventions) {
  struct Case {
    TestField field;
    std::vector<double> raw;
    std::vector<float> seconds;
  };
  const double stamp = 1700000000.5;
  const std::vector<Case> cases{
      {{"t", 6}, {0, 50e6, 99e6}, {0.0f, 0.05f, 0.099f}},                             // Ouster: u32 ns
      {{"time", 7}, {-0.1, 0.0, 0.02}, {-0.1f, 0.0f, 0.02f}},                         // Velodyne: f32 s
      {{"timestamp", 8}, {stamp, stamp + 0.03, stamp + 0.06}, {0.0f, 0.03f, 0.06f}},  // Hesai: f64 epoch s
      {{"offset_time", 6}, {1000, 2000, 3000}, {1e-6f, 2e-6f, 3e-6f}},                // Livox: u32 ns
  };
  for (const Case& k : cases) {
    std::vector<std::vector<double>> values;
    for (std::size_t i = 0; i < 3; ++i) values.push_back({1.0 + i, 2.0, 3.0, k.raw[i]});
    TestCloud c = test::make_test_cloud({{"x", 7}, {"y", 7}, {"z", 7}, k.field}, values);
    c.sec = 1700000000;
    c.nsec = 500000000;
    const PointCloud cloud = decode(test::serialize_ros1(c), MessageEncoding::ros1);
    ASSERT_TRUE(cloud.has_time()) << k.field.name;
    for (std::size_t i = 0; i < 3; ++i)
      EXPECT_NEAR(cloud.time()[i], k.seconds[i], 2e-6) << k.field.name << " " << i;
  }
}

TEST(PointCloud2, TheStampAloneFromTheFirstBytes) {
  TestCloud c = test::make_test_cloud({{"x", 7}, {"y", 7}, {"z", 7}}, {{1, 2, 3}});
  c.sec = 1600000000;
  c.nsec = 250000000;
  for (bool big : {false, true}) {
    const test::Bytes cdr = test::serialize_cdr(c, big);
    EXPECT_DOUBLE_EQ(
        point_cloud2_stamp(test::Bytes(cdr.begin(), cdr.begin() + 16), MessageEncoding::cdr, kPlace),
        1600000000.25);
    EXPECT_DOUBLE_EQ(parse_point_cloud2(cdr, MessageEncoding::cdr, kPlace).stamp, 1600000000.25);
  }
  const test::Bytes ros1 = test::serialize_ros1(c);
  EXPECT_DOUBLE_EQ(point_cloud2_stamp(ros1, MessageEncoding::ros1, kPlace), 1600000000.25);
  EXPECT_EQ(parse_point_cloud2(ros1, MessageEncoding::ros1, kPlace).frame_id, "lidar");
  EXPECT_EQ(parse_point_cloud2(test::serialize_cdr(c), MessageEncoding::cdr, kPlace).frame_id, "lidar");
}

TEST(PointCloud2, MalformedMessagesAreRefusedAtTheirByte) {
  const TestCloud good = test::make_test_cloud({{"x", 7}, {"y", 7}, {"z", 7}}, {{1, 2, 3}, {4, 5, 6}});
  test::Bytes truncated = test::serialize_ros1(good);
  truncated.resize(truncated.size() - 10);
  EXPECT_NE(problem(truncated, MessageEncoding::ros1).find("claim"), std::string::npos);
  test::Bytes cut = test::serialize_cdr(good);
  cut.resize(20);
  EXPECT_NE(problem(cut, MessageEncoding::cdr).find("header frame_id claims 6 bytes, only 4 follow"),
            std::string::npos);

  TestCloud outside = good;
  outside.offsets[2] = 10;  // z's float32 at 10 of a 12-byte point
  EXPECT_NE(problem(test::serialize_ros1(outside), MessageEncoding::ros1).find("lies outside point_step 12"),
            std::string::npos);
  TestCloud short_data = good;
  short_data.data.resize(20);
  EXPECT_NE(problem(test::serialize_ros1(short_data), MessageEncoding::ros1).find("height × row_step is 24"),
            std::string::npos);
  TestCloud short_rows = good;
  short_rows.row_step = 12;
  EXPECT_NE(
      problem(test::serialize_cdr(short_rows), MessageEncoding::cdr).find("shorter than width × point_step"),
      std::string::npos);
  TestCloud unknown = good;
  unknown.fields[1].datatype = 9;
  EXPECT_NE(problem(test::serialize_ros1(unknown), MessageEncoding::ros1).find("datatype 9"),
            std::string::npos);

  const TestCloud no_z = test::make_test_cloud({{"x", 7}, {"y", 7}, {"intensity", 7}}, {{1, 2, 3}});
  EXPECT_NE(problem(test::serialize_ros1(no_z), MessageEncoding::ros1)
                .find("without the field 'z' (fields: x y intensity)"),
            std::string::npos);
  const TestCloud integer_x = test::make_test_cloud({{"x", 5}, {"y", 7}, {"z", 7}}, {{1, 2, 3}});
  EXPECT_NE(problem(test::serialize_ros1(integer_x), MessageEncoding::ros1).find("field 'x' is int32"),
            std::string::npos);
  test::Bytes xcdr2_delimited = test::serialize_cdr(good);
  xcdr2_delimited[1] = 0x09;
  EXPECT_NE(problem(xcdr2_delimited, MessageEncoding::cdr).find("CDR representation 0x0009 is not read"),
            std::string::npos);
}

}  // namespace
}  // namespace sextant
