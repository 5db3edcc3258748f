// SPDX-License-Identifier: MIT
#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace dem {

/// Error in the description of a model (a missing or invalid parameter), raised while a
/// simulation is set up, never inside the time loop. `key` names the offending parameter the
/// way a case file spells it (e.g. "normal_stiffness"), so the case loader can point at it.
class ModelError : public std::runtime_error {
 public:
  ModelError(std::string key, const std::string& message)
      : std::runtime_error(message), key_(std::move(key)) {}
  /// The case-file key the error is about.
  [[nodiscard]] const std::string& key() const noexcept { return key_; }

 private:
  std::string key_;
};

}  // namespace dem
