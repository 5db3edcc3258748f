// SPDX-License-Identifier: MIT
#include "store/packed_column.hpp"

#include <bit>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include <zlib.h>

#include "support/base64.hpp"

namespace store {
namespace {

constexpr std::uint64_t kSignBit = std::uint64_t{1} << 63;

/// A key that orders like the double it comes from (negative values have their bits
/// inverted, the others their sign bit set), so that smooth data gives smooth keys.
std::uint64_t order_key(double v) {
  const auto bits = std::bit_cast<std::uint64_t>(v);
  return (bits & kSignBit) != 0 ? ~bits : bits | kSignBit;
}

/// The inverse of order_key.
double from_order_key(std::uint64_t key) {
  return std::bit_cast<double>((key & kSignBit) != 0 ? key & ~kSignBit : ~key);
}

/// The key expected at `i` from the keys before it: 0, the previous one, the linear and then
/// the quadratic extrapolation. Unsigned arithmetic wraps, so the prediction is exact and the
/// same on every machine; only the residual's size depends on how good it is.
std::uint64_t predicted(const std::vector<std::uint64_t>& keys, std::size_t i) {
  if (i == 0) return 0;
  if (i == 1) return keys[0];
  if (i == 2) return 2 * keys[1] - keys[0];
  return 3 * keys[i - 1] - 3 * keys[i - 2] + keys[i - 3];
}

/// Small residuals of either sign become small unsigned numbers: 0, -1, 1, -2 → 0, 1, 2, 3.
std::uint64_t zigzag(std::uint64_t residual) { return (residual << 1) ^ (std::uint64_t{0} - (residual >> 63)); }
std::uint64_t unzigzag(std::uint64_t z) { return (z >> 1) ^ (std::uint64_t{0} - (z & 1)); }

/// zlib's worst-case expansion bound is far below this; its best compression ratio is about
/// 1032:1, so a claim of more rows than this allows is refused before anything is allocated.
constexpr std::size_t kMaxInflationRatio = 1100;

}  // namespace

std::string pack_column(std::span<const double> values) {
  const std::size_t n = values.size();
  std::vector<std::uint64_t> keys(n);
  for (std::size_t i = 0; i < n; ++i) keys[i] = order_key(values[i]);
  std::string planes(n * 8, '\0');
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t z = zigzag(keys[i] - predicted(keys, i));
    for (std::size_t b = 0; b < 8; ++b) planes[b * n + i] = static_cast<char>((z >> (8 * b)) & 0xFFU);
  }
  uLongf size = compressBound(static_cast<uLong>(planes.size()));
  std::string deflated(size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(deflated.data()), &size, reinterpret_cast<const Bytef*>(planes.data()),
                static_cast<uLong>(planes.size()), Z_BEST_COMPRESSION) != Z_OK) {
    throw std::runtime_error("zlib could not compress a trace column");
  }
  deflated.resize(size);
  return support::base64_encode(deflated);
}

std::vector<double> unpack_column(std::string_view text, std::size_t rows) {
  const auto deflated = support::base64_decode(text);
  if (!deflated) throw std::runtime_error("packed column is not canonical Base64");
  if (rows > (deflated->size() + 64) * kMaxInflationRatio / 8) {
    throw std::runtime_error("packed column of " + std::to_string(deflated->size()) + " bytes cannot hold " +
                             std::to_string(rows) + " rows");
  }
  std::string planes(rows * 8 + 1, '\0');  // one spare byte: a longer stream fills it
  uLongf size = static_cast<uLongf>(planes.size());
  const int status = uncompress(reinterpret_cast<Bytef*>(planes.data()), &size,
                                reinterpret_cast<const Bytef*>(deflated->data()), static_cast<uLong>(deflated->size()));
  if (status != Z_OK && status != Z_BUF_ERROR) throw std::runtime_error("packed column is not a zlib stream");
  if (status == Z_BUF_ERROR || size != rows * 8) {
    throw std::runtime_error("packed column does not hold exactly " + std::to_string(rows) + " rows");
  }
  std::vector<std::uint64_t> keys(rows);
  std::vector<double> values(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    std::uint64_t z = 0;
    for (std::size_t b = 0; b < 8; ++b) z |= std::uint64_t{static_cast<unsigned char>(planes[b * rows + i])} << (8 * b);
    keys[i] = predicted(keys, i) + unzigzag(z);
    values[i] = from_order_key(keys[i]);
  }
  return values;
}

}  // namespace store
