// SPDX-License-Identifier: MIT
// STL meshes: ASCII and binary files read to the same triangles, and every malformed file —
// truncated, a coordinate that is not finite, a triangle of no area, no triangle, not STL at all —
// refused naming the file, the place and what is wrong.
#include "cases/mesh/stl_reader.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/text_file.hpp"

namespace stl_reader_test {

using Triangle = std::array<std::array<float, 3>, 3>;

/// A tetrahedron with corners at the origin and on the three axes (1, 2 and 0.5 m), outward faces.
const std::vector<Triangle> kTetrahedron{{{{0, 0, 0}, {0, 2, 0}, {1, 0, 0}}},
                                         {{{0, 0, 0}, {1, 0, 0}, {0, 0, 0.5F}}},
                                         {{{0, 0, 0}, {0, 0, 0.5F}, {0, 2, 0}}},
                                         {{{1, 0, 0}, {0, 2, 0}, {0, 0, 0.5F}}}};

std::string ascii(const std::vector<Triangle>& triangles, const std::string& name = "tetra") {
  std::string s = "solid " + name + "\n";
  for (const Triangle& t : triangles) {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for (const auto& v : t) s += "      vertex " + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + "\n";
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid " + name + "\n";
}

void put_u32(std::string& s, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) s += static_cast<char>((v >> (8 * k)) & 0xFFU);
}

/// Binary STL; the header starts with "solid" as some exporters write it.
std::string binary(const std::vector<Triangle>& triangles) {
  std::string s = "solid written by a binary exporter";
  s.resize(80, ' ');
  put_u32(s, static_cast<std::uint32_t>(triangles.size()));
  for (const Triangle& t : triangles) {
    for (int k = 0; k < 3; ++k) put_u32(s, std::bit_cast<std::uint32_t>(0.0F));  // a normal nobody reads
    for (const auto& v : t) {
      for (const float c : v) put_u32(s, std::bit_cast<std::uint32_t>(c));
    }
    s += std::string(2, '\0');
  }
  return s;
}

/// The StlError message of parsing `bytes`; fails the test when it parses.
std::string error_of(const std::string& bytes) {
  try {
    cases::parse_stl(bytes, "part.stl");
  } catch (const cases::StlError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected an StlError";
  return {};
}

TEST(StlReader, AsciiAndBinaryGiveTheSameTrianglesInFileOrder) {
  const cases::TriangleMesh a = cases::parse_stl(ascii(kTetrahedron), "a.stl");
  const cases::TriangleMesh b = cases::parse_stl(binary(kTetrahedron), "b.stl");
  EXPECT_EQ(a.name, "tetra");
  EXPECT_EQ(b.name, "");
  ASSERT_EQ(a.triangles.size(), 4U);
  ASSERT_EQ(b.triangles.size(), 4U);
  for (std::size_t t = 0; t < 4; ++t) {
    for (std::size_t v = 0; v < 3; ++v) {
      for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(a.triangles[t].vertex[v][k], static_cast<double>(kTetrahedron[t][v][k]));
        EXPECT_EQ(b.triangles[t].vertex[v][k], static_cast<double>(kTetrahedron[t][v][k]));
      }
    }
  }
}

TEST(StlReader, AcceptsAnyCaseExponentsSignsAndCarriageReturns) {
  const std::string text =
      "SOLID Part 7\r\nFacet Normal 0 0 1\r\nOuter Loop\r\nVertex 0 0 0\r\nVERTEX 1.5e-3 +0 0\r\nvertex 0 2E-3 -0.0\r\n"
      "EndLoop\r\nENDFACET\r\nendsolid Part 7\r\n";
  const cases::TriangleMesh m = cases::parse_stl(text, "part.stl");
  EXPECT_EQ(m.name, "Part 7");
  ASSERT_EQ(m.triangles.size(), 1U);
  EXPECT_EQ(m.triangles[0].vertex[1][0], 1.5e-3);
  EXPECT_EQ(m.triangles[0].vertex[2][1], 2e-3);
}

TEST(StlReader, ReadsAFileAndNamesAMissingOne) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "demwb-stl-reader";
  std::filesystem::create_directories(dir);
  support::write_file(dir / "tetra.stl", binary(kTetrahedron));
  EXPECT_EQ(cases::read_stl(dir / "tetra.stl").triangles.size(), 4U);
  try {
    cases::read_stl(dir / "absent.stl");
    ADD_FAILURE() << "expected an StlError";
  } catch (const cases::StlError& e) {
    EXPECT_NE(std::string(e.what()).find("absent.stl"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(StlReader, RefusesTruncatedFiles) {
  const std::string whole = binary(kTetrahedron);
  const std::string cut = error_of(whole.substr(0, whole.size() - 7));
  EXPECT_NE(cut.find("part.stl"), std::string::npos) << cut;
  EXPECT_NE(cut.find("promises 4 triangles, 284 bytes, where the file has 277"), std::string::npos) << cut;
  EXPECT_NE(error_of("STLB" + std::string(30, '\0')).find("shorter than a binary header"), std::string::npos);
  const std::string text = ascii(kTetrahedron);
  const std::string mid_facet = error_of(text.substr(0, text.find("endloop") - 3));
  EXPECT_NE(mid_facet.find("truncated?"), std::string::npos) << mid_facet;
  const std::string no_end = error_of(text.substr(0, text.find("endsolid")));
  EXPECT_NE(no_end.find("ends before 'endsolid'"), std::string::npos) << no_end;
}

TEST(StlReader, RefusesCoordinatesThatAreNotFiniteNumbers) {
  std::vector<Triangle> bad = kTetrahedron;
  bad[2][1][0] = std::numeric_limits<float>::quiet_NaN();
  const std::string nan_binary = error_of(binary(bad));
  EXPECT_NE(nan_binary.find("triangle 2: vertex 1 has a coordinate that is not a finite number"), std::string::npos)
      << nan_binary;
  bad[2][1][0] = std::numeric_limits<float>::infinity();
  EXPECT_NE(error_of(binary(bad)).find("not a finite number"), std::string::npos);
  std::string text = ascii(kTetrahedron);
  const std::string second = "vertex 0.000000 2.000000";
  text.replace(text.find(second), second.size(), "vertex nan 2.000000");
  EXPECT_NE(error_of(text).find("triangle 0: vertex 1 has a coordinate that is not a finite number"), std::string::npos);
  std::string word = ascii(kTetrahedron);
  word.replace(word.find("vertex 1.000000"), 15, "vertex one.0000");
  const std::string not_number = error_of(word);
  EXPECT_NE(not_number.find("line 6: expected a coordinate, found 'one.0000'"), std::string::npos) << not_number;
  std::string huge = ascii(kTetrahedron);
  huge.replace(huge.find("vertex 1.000000"), 15, "vertex 1e999   ");
  EXPECT_NE(error_of(huge).find("out of range"), std::string::npos);
}

TEST(StlReader, RefusesTrianglesOfNoArea) {
  std::vector<Triangle> repeated = kTetrahedron;
  repeated[3][2] = repeated[3][0];
  EXPECT_NE(error_of(binary(repeated)).find("triangle 3 has no area"), std::string::npos);
  std::vector<Triangle> collinear = kTetrahedron;
  collinear[1] = {{{0, 0, 0}, {1, 1, 1}, {3, 3, 3}}};
  EXPECT_NE(error_of(ascii(collinear)).find("triangle 1 has no area"), std::string::npos);
  std::vector<Triangle> point = kTetrahedron;
  point[0] = {{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}};
  EXPECT_NE(error_of(binary(point)).find("triangle 0 has no area"), std::string::npos);
  // Small is not degenerate: a 1 µm triangle far from the origin is kept.
  const std::vector<Triangle> tiny{{{{5, 5, 5}, {5.000001F, 5, 5}, {5, 5.000001F, 5}}}};
  EXPECT_EQ(cases::parse_stl(binary(tiny), "tiny.stl").triangles.size(), 1U);
}

TEST(StlReader, RefusesEmptyMeshesAndFilesThatAreNotStl) {
  EXPECT_NE(error_of("solid nothing\nendsolid nothing\n").find("no triangle"), std::string::npos);
  EXPECT_NE(error_of(binary({})).find("no triangle"), std::string::npos);
  EXPECT_NE(error_of("").find("not an STL file"), std::string::npos);
  const std::string obj = "# an OBJ file\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" + std::string(100, '#');
  EXPECT_NE(error_of(obj).find("does not start with 'solid'"), std::string::npos);
  const std::string stray = error_of("solid x\nfacet normal 0 0 1\nouter ring\n");
  EXPECT_NE(stray.find("line 3: expected 'loop', found 'ring'"), std::string::npos) << stray;
}

}  // namespace stl_reader_test
