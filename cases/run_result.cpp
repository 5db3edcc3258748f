// SPDX-License-Identifier: MIT
#include "cases/run_result.hpp"

namespace cases {

std::string_view to_string(RunStatus status) noexcept {
  switch (status) {
    case RunStatus::ok: return "ok";
    case RunStatus::error: return "error";
    case RunStatus::missing: return "missing";
    case RunStatus::not_applicable: return "n/a";
  }
  return "error";
}

}  // namespace cases
