// SPDX-License-Identifier: MIT
#include "cases/mesh/stl_reader.hpp"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

#include <fmt/format.h>

#include "support/text_file.hpp"

namespace cases {
namespace {

constexpr std::size_t kBinaryHeader = 84;  // 80 bytes of text, then the triangle count
constexpr std::size_t kBinaryRecord = 50;  // normal, three vertices (12 float32) and a 2-byte attribute

/// Little-endian unsigned 32-bit integer at `p`.
std::uint32_t read_u32(const char* p) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(p[k]);
  return v;
}

/// Little-endian IEEE binary32 at `p`, widened.
double read_f32(const char* p) { return static_cast<double>(std::bit_cast<float>(read_u32(p))); }

/// Throws StlError when triangle `index` has a coordinate that is not finite or no area.
void check_triangle(const MeshTriangle& t, std::size_t index, const std::string& source) {
  for (std::size_t v = 0; v < 3; ++v) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (!std::isfinite(t.vertex[v][k])) {
        throw StlError(fmt::format("{}: triangle {}: vertex {} has a coordinate that is not a finite number ({})", source,
                                   index, v, t.vertex[v][k]));
      }
    }
  }
  std::array<double, 3> a{};
  std::array<double, 3> b{};
  double longest = 0.0;
  for (std::size_t k = 0; k < 3; ++k) {
    a[k] = t.vertex[1][k] - t.vertex[0][k];
    b[k] = t.vertex[2][k] - t.vertex[0][k];
  }
  for (std::size_t e = 0; e < 3; ++e) {
    double len2 = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      const double d = t.vertex[(e + 1) % 3][k] - t.vertex[e][k];
      len2 += d * d;
    }
    longest = std::max(longest, len2);
  }
  const double cx = a[1] * b[2] - a[2] * b[1];
  const double cy = a[2] * b[0] - a[0] * b[2];
  const double cz = a[0] * b[1] - a[1] * b[0];
  const double twice_area = std::sqrt(cx * cx + cy * cy + cz * cz);
  if (!(twice_area > 2e-12 * longest) || !(longest > 0.0)) {
    throw StlError(fmt::format("{}: triangle {} has no area (its vertices coincide or lie on one line)", source, index));
  }
}

TriangleMesh parse_binary(std::string_view bytes, std::uint32_t count, const std::string& source) {
  TriangleMesh mesh;
  mesh.triangles.reserve(count);
  for (std::size_t t = 0; t < count; ++t) {
    const char* record = bytes.data() + kBinaryHeader + t * kBinaryRecord;
    MeshTriangle tri;
    for (std::size_t v = 0; v < 3; ++v) {
      for (std::size_t k = 0; k < 3; ++k) tri.vertex[v][k] = read_f32(record + 12 + 12 * v + 4 * k);
    }
    check_triangle(tri, t, source);
    mesh.triangles.push_back(tri);
  }
  return mesh;
}

/// Whitespace-separated words of ASCII STL text with their line numbers.
class Words {
 public:
  Words(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  /// The next word; empty at the end of the text.
  std::string_view next() {
    while (at_ < text_.size() && is_space(text_[at_])) {
      if (text_[at_] == '\n') ++line_;
      ++at_;
    }
    const std::size_t start = at_;
    while (at_ < text_.size() && !is_space(text_[at_])) ++at_;
    return text_.substr(start, at_ - start);
  }
  /// The rest of the current line (the solid's name), trimmed.
  std::string rest_of_line() {
    const std::size_t end = std::min(text_.find('\n', at_), text_.size());
    std::string_view s = text_.substr(at_, end - at_);
    at_ = end;
    while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
    return std::string(s);
  }
  /// Throws unless the next word is `word` (any case).
  void expect(std::string_view word) {
    const std::string_view got = next();
    if (!same(got, word)) fail(fmt::format("expected '{}', found {}", word, shown(got)));
  }
  /// The next word as a number.
  double number() {
    const std::string_view w = next();
    if (w.empty()) fail("expected a coordinate, found the end of the file (truncated?)");
    double v = 0.0;
    const char* first = w.data();
    const char* last = w.data() + w.size();
    if (*first == '+') ++first;
    const auto [ptr, ec] = std::from_chars(first, last, v);
    if (ptr != last || (ec != std::errc() && ec != std::errc::result_out_of_range)) {
      fail(fmt::format("expected a coordinate, found {}", shown(w)));
    }
    if (ec == std::errc::result_out_of_range) {
      fail(fmt::format("the coordinate {} is out of range of a double", shown(w)));
    }
    return v;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw StlError(fmt::format("{}: line {}: {}", source_, line_, what));
  }
  static bool same(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
             return (x >= 'A' && x <= 'Z' ? static_cast<char>(x - 'A' + 'a') : x) == y;
           });
  }

 private:
  static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v'; }
  static std::string shown(std::string_view w) {
    if (w.empty()) return "the end of the file (truncated?)";
    return fmt::format("'{}'", w.substr(0, 40));
  }
  std::string_view text_;
  const std::string& source_;
  std::size_t at_ = 0;
  std::size_t line_ = 1;
};

TriangleMesh parse_ascii(std::string_view text, const std::string& source) {
  Words words(text, source);
  words.expect("solid");
  TriangleMesh mesh;
  mesh.name = words.rest_of_line();
  for (;;) {
    const std::string_view w = words.next();
    if (w.empty()) words.fail("the file ends before 'endsolid' (truncated?)");
    if (Words::same(w, "endsolid")) break;
    if (!Words::same(w, "facet")) words.fail(fmt::format("expected 'facet' or 'endsolid', found '{}'", w.substr(0, 40)));
    if (mesh.triangles.size() == kMaxMeshTriangles) {
      words.fail(fmt::format("more than {} triangles", kMaxMeshTriangles));
    }
    words.expect("normal");
    for (int k = 0; k < 3; ++k) static_cast<void>(words.number());  // the vertex order orients it
    words.expect("outer");
    words.expect("loop");
    MeshTriangle tri;
    for (std::size_t v = 0; v < 3; ++v) {
      words.expect("vertex");
      for (std::size_t k = 0; k < 3; ++k) tri.vertex[v][k] = words.number();
    }
    words.expect("endloop");
    words.expect("endfacet");
    check_triangle(tri, mesh.triangles.size(), source);
    mesh.triangles.push_back(tri);
  }
  return mesh;
}

}  // namespace

TriangleMesh parse_stl(std::string_view bytes, const std::string& source) {
  TriangleMesh mesh;
  const bool sized_as_binary = bytes.size() >= kBinaryHeader &&
                               bytes.size() == kBinaryHeader + kBinaryRecord * std::size_t{read_u32(bytes.data() + 80)};
  std::string_view lead = bytes.substr(0, 512);
  while (!lead.empty() && (lead.front() == ' ' || lead.front() == '\t' || lead.front() == '\r' || lead.front() == '\n')) {
    lead.remove_prefix(1);
  }
  // Some exporters begin binary headers with "solid" too: text never holds a NUL byte.
  const bool says_solid = lead.size() >= 5 && Words::same(lead.substr(0, 5), "solid") &&
                          bytes.find('\0') == std::string_view::npos;
  if (sized_as_binary) {
    const std::uint32_t count = read_u32(bytes.data() + 80);
    if (count > kMaxMeshTriangles) {
      throw StlError(fmt::format("{}: {} triangles, more than the limit of {}", source, count, kMaxMeshTriangles));
    }
    mesh = parse_binary(bytes, count, source);
  } else if (says_solid) {
    mesh = parse_ascii(bytes, source);
  } else if (bytes.size() >= kBinaryHeader) {
    const std::uint32_t count = read_u32(bytes.data() + 80);
    throw StlError(fmt::format("{}: not an STL file: it does not start with 'solid' (ASCII), and as binary STL its "
                               "header promises {} triangles, {} bytes, where the file has {} (truncated?)",
                               source, count, kBinaryHeader + kBinaryRecord * std::size_t{count}, bytes.size()));
  } else {
    throw StlError(fmt::format("{}: not an STL file: {} bytes, shorter than a binary header (84) and not starting "
                               "with 'solid'",
                               source, bytes.size()));
  }
  if (mesh.triangles.empty()) throw StlError(fmt::format("{}: the mesh has no triangle", source));
  return mesh;
}

TriangleMesh read_stl(const std::filesystem::path& path) {
  std::string bytes;
  try {
    bytes = support::read_file(path);
  } catch (const std::exception& e) {
    throw StlError(e.what());
  }
  return parse_stl(bytes, path.string());
}

}  // namespace cases
