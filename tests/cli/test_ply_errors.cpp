// PLY reader: every malformed, truncated or absurd file gives a qd::common::Error with a precise
// message, and arbitrary truncation or corruption of a valid file never crashes.
#include <gtest/gtest.h>

#include <random>

#include "common/error.h"
#include "io/ply_reader.h"
#include "io/ply_writer.h"
#include "ply_test_util.h"

using namespace qd::io;
using namespace qd::io::test;

namespace {

using namespace qd::common;

const std::string kHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

struct BadCase {
  const char* name;
  std::string bytes;
  std::string message;  // expected part of the error message
};

std::string binary_header(const char* counts_and_props) {
  return std::string("ply\nformat binary_little_endian 1.0\n") + counts_and_props + "end_header\n";
}

std::vector<BadCase> bad_cases() {
  const std::string tri = serialize_ply_tables(sample_ply(), PlyFormat::BinaryLittleEndian);
  PlyTables faces_last = sample_ply();
  faces_last.elements.pop_back();
  const std::string lists = serialize_ply_tables(faces_last, PlyFormat::BinaryLittleEndian);
  return {
      {"empty", "", "does not start with 'ply'"},
      {"not_ply", "solid cube\n", "does not start with 'ply'"},
      {"header_only", "ply\nformat ascii 1.0\nelement vertex 3\n",
       "not terminated by 'end_header'"},
      {"no_format", "ply\nelement vertex 0\nend_header\n", "end_header before the format line"},
      {"bad_format", "ply\nformat binary_middle_endian 1.0\nend_header\n", "unknown format"},
      {"bad_type", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n",
       "header line 4: unknown property type 'quad'"},
      {"float_count",
       "ply\nformat ascii 1.0\nelement face 1\nproperty list float int v\nend_header\n",
       "list count type must be an integer type"},
      {"property_first", "ply\nformat ascii 1.0\nproperty float x\nend_header\n",
       "property before any element"},
      {"bad_count", "ply\nformat ascii 1.0\nelement vertex -3\nend_header\n",
       "element count '-3' is not a non-negative integer"},
      {"twice", "ply\nformat ascii 1.0\nelement vertex 0\nelement vertex 0\nend_header\n",
       "element 'vertex' appears twice"},
      {"unknown_keyword", "ply\nformat ascii 1.0\nelemnt vertex 0\nend_header\n",
       "unknown keyword 'elemnt'"},
      {"huge_count_binary",
       binary_header(
           "element vertex 1000000000000\nproperty float x\nproperty float y\nproperty float z\n") +
           std::string(40, '\0'),
       "declares 1000000000000 'vertex' elements, but only 40 bytes"},
      {"huge_count_ascii",
       "ply\nformat ascii 1.0\nelement vertex 99999999999\nproperty float x\nend_header\n1\n",
       "declares 99999999999 'vertex' elements"},
      {"truncated_fixed_size", tri.substr(0, tri.size() - 7),
       "the header declares 2 'edge' elements, but only 17 bytes of data remain"},
      {"truncated_lists", lists.substr(0, lists.size() - 2),
       // the last float (quality of the last face) starts 4 bytes before the end
       "truncated binary data at byte " + std::to_string(lists.size() - 4) +
           ": missing property 'quality' of face 2 (of 3)"},
      {"trailing_binary", tri + "junk", "4 unexpected bytes after the last element"},
      {"too_few_ascii", kHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n",
       "the data ends early (line 14): missing property 'vertex_indices' of face 0 (of 1)"},
      {"too_many_ascii", kHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n",
       "line 14: unexpected data after the last element"},
      {"bad_number", kHeader + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n",
       "line 11: 'zero' is not a valid float for property 'y' of vertex 1 (of 3)"},
      {"uchar_overflow", kHeader + "0 0 0\n1 0 0\n0 1 0\n300 0 1 2\n",
       "'300' is not a valid uchar"},
      {"fractional_index", kHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n",
       "'1.5' is not a valid int"},
      {"negative_list",
       binary_header("element face 1\nproperty list char int vertex_indices\n") +
           std::string("\xff", 1),
       "negative list length of property 'vertex_indices' of face 0"},
      {"list_past_end",
       binary_header("element face 1\nproperty list uint int vertex_indices\n") +
           std::string("\x00\x00\x00\x10", 4) + std::string(8, '\0'),
       "list length 268435456 of property 'vertex_indices' of face 0 (of 1) exceeds the remaining "
       "data"},
  };
}

TEST(PlyErrors, EachMalformedFileGivesItsMessage) {
  for (const BadCase& c : bad_cases()) {
    const std::string message = error_of([&] { parse_ply_tables(c.bytes); });
    EXPECT_NE(message.find(c.message), std::string::npos)
        << c.name << ": got '" << message << "', expected '" << c.message << "'";
    EXPECT_EQ(message.find('\n'), std::string::npos) << c.name << ": message must be one line";
  }
}

struct MeshCase {
  const char* name;
  std::string body;
  const char* message;
};

TEST(PlyErrors, UnusableMeshesGiveTheirMessage) {
  const std::vector<MeshCase> cases = {
      {"index_out_of_range", kHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
       "face 0 uses vertex index 3, out of range (the file has 3 vertices)"},
      {"negative_index", kHeader + "0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "uses vertex index -1"},
      {"two_corners", kHeader + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "face 0 has 2 vertices"},
      {"nan", kHeader + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "vertex 1 has a non-finite coordinate"},
      {"inf", kHeader + "0 0 0\n1 0 0\n0 1 -inf\n3 0 1 2\n",
       "vertex 2 has a non-finite coordinate"},
      {"no_faces",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
       "property float z\nend_header\n0 0 0\n",
       "no 'face' element"},
      {"no_z",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
       "element face 0\nproperty list uchar int vertex_indices\nend_header\n0 0\n",
       "the 'vertex' element has no 'z' property"},
      {"huge_quality",
       "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty "
       "float z\n"
       "element face 1\nproperty list uchar int vertex_indices\nproperty float "
       "quality\nend_header\n"
       "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 1e20\n",
       "face 0 has quality"},
  };
  for (const MeshCase& c : cases) {
    const std::string message = error_of([&] { mesh_of(c.body); });
    EXPECT_NE(message.find(c.message), std::string::npos)
        << c.name << ": got '" << message << "', expected '" << c.message << "'";
  }
}

// Every prefix and many random corruptions of a valid file either parse or throw qd::common::Error.
TEST(PlyErrors, TruncationAndCorruptionNeverCrash) {
  for (PlyFormat format :
       {PlyFormat::Ascii, PlyFormat::BinaryLittleEndian, PlyFormat::BinaryBigEndian}) {
    const std::string good = serialize_ply_tables(sample_ply(), format);
    int failures = 0;
    for (std::size_t n = 0; n < good.size(); ++n) {
      try {
        mesh_of(good.substr(0, n));
      } catch (const qd::common::Error&) {
        ++failures;
      }
    }
    // Binary prefixes all fail; an ascii prefix that cuts a number's last digits may still parse.
    if (format != PlyFormat::Ascii) {
      EXPECT_EQ(failures, static_cast<int>(good.size()));
    }
    std::mt19937 rng(7);
    for (int trial = 0; trial < 2000; ++trial) {
      std::string bad = good;
      const std::size_t at = std::uniform_int_distribution<std::size_t>(0, bad.size() - 1)(rng);
      bad[at] = static_cast<char>(std::uniform_int_distribution<int>(0, 255)(rng));
      try {
        mesh_of(bad);
      } catch (const qd::common::Error&) {
      }
    }
  }
}

}  // namespace
