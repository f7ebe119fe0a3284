// ScalarColumn: values held in their PLY type; the PLY reader keeps each property's type.
#include <gtest/gtest.h>

#include <cstdint>
#include <type_traits>

#include "common/error.h"
#include "io/ply_reader.h"
#include "io/scalar_column.h"

using namespace qd::io;

TEST(ScalarColumn, KeepsItsTypeAndValues) {
  const ScalarColumn c(ScalarType::UInt8, {0, 7, 255});
  EXPECT_EQ(c.type(), ScalarType::UInt8);
  EXPECT_EQ(c.size(), 3u);
  EXPECT_EQ(c.to_doubles(), (std::vector<double>{0, 7, 255}));
  EXPECT_FALSE(c == ScalarColumn(ScalarType::Int32, {0, 7, 255}));  // same values, other type
}

TEST(ScalarColumn, RefusesAValueItsTypeCannotHold) {
  ScalarColumn c(ScalarType::UInt8);
  EXPECT_THROW(c.push_back(256), qd::common::Error);
  EXPECT_THROW(c.push_back(0.5), qd::common::Error);
  ScalarColumn f(ScalarType::Float32);
  f.push_back(0.1);
  EXPECT_EQ(f[0], static_cast<double>(0.1f));  // rounded to the nearest float on the way in
}

TEST(ScalarColumn, TheReaderStoresEachPropertyInItsFileType) {
  const PlyTables ply = parse_ply_tables(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty uchar red\n"
      "property int id\nproperty double w\nend_header\n0.5 200 -3 0.25\n");
  const PlyElement& v = ply.elements[0];
  EXPECT_EQ(v.properties[0].type(), ScalarType::Float32);
  EXPECT_EQ(v.properties[1].type(), ScalarType::UInt8);
  EXPECT_EQ(v.properties[2].type(), ScalarType::Int32);
  EXPECT_EQ(v.properties[3].type(), ScalarType::Float64);
  EXPECT_EQ(v.properties[1].values[0], 200);
  EXPECT_EQ(v.properties[2].values[0], -3);
}

TEST(ScalarColumn, VisitHandsOverTheTypedVector) {
  ScalarColumn c(ScalarType::Int16, {-2, 9});
  c.visit([](auto& values) { values.push_back(values[0] + values[1]); });
  const bool is_int16 = c.visit(
      [](const auto& values) { return std::is_same_v<decltype(values[0]), const std::int16_t&>; });
  EXPECT_TRUE(is_int16);
  EXPECT_EQ(c.to_doubles(), (std::vector<double>{-2, 9, 7}));
  EXPECT_EQ(ScalarColumn(std::vector<float>{1.5f}).type(), ScalarType::Float32);
}

TEST(ScalarColumn, TheBulkConstructorRefusesAValueItsTypeCannotHold) {
  EXPECT_THROW(ScalarColumn(ScalarType::Int8, {1, 128}), qd::common::Error);
  EXPECT_THROW(ScalarColumn(ScalarType::UInt32, {-1}), qd::common::Error);
  EXPECT_NO_THROW(ScalarColumn(ScalarType::Float32, {1e30, -1e30}));
  EXPECT_THROW(ScalarColumn(ScalarType::Float32, {1e39}), qd::common::Error);
}

TEST(ScalarColumn, EveryTypeMapsToItsCxxTypeAndBack) {
  for (int t = 0; t <= static_cast<int>(ScalarType::Float64); ++t) {
    const auto type = static_cast<ScalarType>(t);
    const ScalarType back =
        with_scalar_type(type, [](auto value) { return scalar_type_of<decltype(value)>(); });
    EXPECT_EQ(back, type);
    EXPECT_EQ(with_scalar_type(type, [](auto value) { return sizeof value; }),
              scalar_type_size(type));
    EXPECT_EQ(ScalarColumn(type).type(), type);
  }
}
