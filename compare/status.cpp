// SPDX-License-Identifier: MIT
#include "compare/status.hpp"

#include <array>
#include <utility>

namespace comparison {
namespace {

constexpr std::array<std::pair<Status, std::string_view>, 5> kNames{{
    {Status::pass, "pass"},
    {Status::fail, "fail"},
    {Status::error, "error"},
    {Status::missing, "missing"},
    {Status::not_applicable, "n/a"},
}};

}  // namespace

std::string_view to_string(Status status) noexcept {
  for (const auto& [s, name] : kNames) {
    if (s == status) return name;
  }
  return "error";
}

std::optional<Status> parse_status(std::string_view name) noexcept {
  for (const auto& [s, n] : kNames) {
    if (n == name) return s;
  }
  return std::nullopt;
}

}  // namespace comparison
