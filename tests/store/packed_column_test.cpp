// SPDX-License-Identifier: MIT
// Packed trace columns: lossless for every bit pattern, small for smooth data, and a clear
// refusal (never a crash or a wrong column) for damaged text.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "store/packed_column.hpp"
#include "support/base64.hpp"

namespace packed_column_test {

/// True when `a` and `b` hold the same bit patterns (NaN payloads and signed zeros included).
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  }
  return true;
}

/// A damped oscillation sampled like a contact trace: what stored traces mostly hold.
std::vector<double> smooth_series(std::size_t n, double scale) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 1e-7 * static_cast<double>(i);
    v[i] = scale * std::exp(-3e3 * t) * std::sin(2e4 * t + 0.3);
  }
  return v;
}

TEST(Base64, MatchesTheRfc4648TestVectorsBothWays) {
  const std::vector<std::pair<std::string, std::string>> vectors = {
      {"", ""}, {"f", "Zg=="}, {"fo", "Zm8="}, {"foo", "Zm9v"},
      {"foob", "Zm9vYg=="}, {"fooba", "Zm9vYmE="}, {"foobar", "Zm9vYmFy"}};
  for (const auto& [plain, coded] : vectors) {
    EXPECT_EQ(support::base64_encode(plain), coded);
    ASSERT_TRUE(support::base64_decode(coded)) << coded;
    EXPECT_EQ(*support::base64_decode(coded), plain);
  }
}

TEST(Base64, RoundTripsEveryByteAndRefusesWhatIsNotCanonical) {
  std::string all;
  for (int c = 0; c < 256; ++c) all += static_cast<char>(c);
  for (std::size_t n = 0; n <= all.size(); n += 37) {
    const std::string part = all.substr(0, n);
    EXPECT_EQ(support::base64_decode(support::base64_encode(part)), part) << n;
  }
  for (const char* bad : {"Zg=", "Zg", "Z===", "Zh==", "Zm9=", "Zm9v Yg==", "Zm=v", "=m9v", "Zm9v\n", "Zm9-"}) {
    EXPECT_FALSE(support::base64_decode(bad)) << bad;
  }
}

TEST(PackedColumn, RoundTripsEveryBitPatternOnSeededRandomColumns) {
  std::mt19937_64 rng(20261203);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = rng() % 300;
    std::vector<double> v(n);
    const int kind = trial % 4;
    for (std::size_t i = 0; i < n; ++i) {
      if (kind == 0) {
        v[i] = std::bit_cast<double>(rng());  // any bits: NaNs, infinities, subnormals
      } else if (kind == 1) {
        v[i] = std::ldexp(static_cast<double>(rng() % 2000) - 1000.0, static_cast<int>(rng() % 40) - 60);
      } else {
        v[i] = (kind == 2 ? 1.0 : -1e-9) * (1.0 + 1e-3 * static_cast<double>(i * i));  // smooth
      }
    }
    const std::string text = store::pack_column(v);
    EXPECT_TRUE(same_bits(store::unpack_column(text, n), v)) << "trial " << trial;
  }
}

TEST(PackedColumn, KeepsSpecialValuesAndSignChangesExactly) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> v = {0.0, -0.0, 1.0, -1.0, inf, -inf, std::numeric_limits<double>::quiet_NaN(),
                                 std::bit_cast<double>(std::uint64_t{0x7FF0000000000123}),
                                 std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(),
                                 std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
                                 std::numeric_limits<double>::min(), 0.1 + 0.2, -0.0, 0.0};
  EXPECT_TRUE(same_bits(store::unpack_column(store::pack_column(v), v.size()), v));
  EXPECT_TRUE(store::unpack_column(store::pack_column(std::vector<double>{}), 0).empty());
}

TEST(PackedColumn, SmoothTracesPackToAFractionOfTheirJsonText) {
  // A contact trace written as JSON numbers takes ~20 characters a value; packed, the smooth
  // parts of it cost a few bytes. The residual against the quadratic extrapolation is what buys
  // it: without the prediction the same column packs only 2.4x and this fails.
  const std::vector<double> v = smooth_series(20000, 1e-4);
  const std::string text = store::pack_column(v);
  EXPECT_LT(text.size(), v.size() * 20 / 4) << text.size();
  // An arithmetic time column costs almost nothing.
  std::vector<double> time(20000);
  for (std::size_t i = 0; i < time.size(); ++i) time[i] = 1e-7 * static_cast<double>(i);
  EXPECT_LT(store::pack_column(time).size(), 20000U);
}

TEST(PackedColumn, RefusesDamagedTextWithAReasonNeverAWrongColumn) {
  const std::vector<double> v = smooth_series(500, 2.0);
  const std::string text = store::pack_column(v);
  const auto refusal = [](const std::string& t, std::size_t rows) -> std::string {
    try {
      static_cast<void>(store::unpack_column(t, rows));
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(refusal(text, 499).find("exactly 499 rows"), std::string::npos);
  EXPECT_NE(refusal(text, 501).find("exactly 501 rows"), std::string::npos);
  EXPECT_NE(refusal(text + "A", 500).find("Base64"), std::string::npos);
  EXPECT_NE(refusal(text.substr(0, text.size() / 2 / 4 * 4), 500).find("zlib"), std::string::npos);
  EXPECT_NE(refusal(support::base64_encode("not a zlib stream"), 500).find("zlib"), std::string::npos);
  // A row count no stream this short could hold is refused before anything is allocated.
  EXPECT_NE(refusal(text, std::size_t{1} << 60).find("cannot hold"), std::string::npos);
  EXPECT_NE(refusal(text, std::numeric_limits<std::size_t>::max()).find("cannot hold"), std::string::npos);
}

TEST(PackedColumn, EverySingleCharacterMutationIsRefusedOrDecodesToTheRightLength) {
  const std::vector<double> v = smooth_series(300, 1.0);
  const std::string text = store::pack_column(v);
  std::mt19937 rng(7);
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/=";
  int refused = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::string t = text;
    t[rng() % t.size()] = alphabet[rng() % alphabet.size()];
    if (t == text) continue;
    try {
      EXPECT_EQ(store::unpack_column(t, v.size()).size(), v.size());
    } catch (const std::runtime_error&) {
      ++refused;
    }
  }
  // zlib's Adler-32 catches nearly every change to the data it carries.
  EXPECT_GT(refused, 1900);
}

}  // namespace packed_column_test
