// SPDX-License-Identifier: MIT
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace store {

/// One trace column as compact lossless text, for stored results (docs/results-format.md,
/// "Packed traces"): each double's bits mapped to an order key, the residual against the
/// quadratic extrapolation of the three keys before it (integer arithmetic, so every build
/// decodes the same bits), zigzag-coded, split into byte planes, zlib-deflated, Base64.
/// Every bit pattern survives, NaN payloads and signed zeros included.
std::string pack_column(std::span<const double> values);

/// The `rows` values a pack_column text stands for, bit for bit; throws std::runtime_error
/// saying what is wrong (not Base64, not a zlib stream, or a length other than `rows`).
std::vector<double> unpack_column(std::string_view text, std::size_t rows);

}  // namespace store
