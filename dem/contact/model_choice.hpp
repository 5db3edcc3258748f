// SPDX-License-Identifier: MIT
#pragma once

#include <string>

namespace dem {

/// Keywords of the sub-model chosen for each slot, as a case file names them.
struct ModelChoice {
  std::string normal = "linear";
  std::string damping = "none";
  std::string tangential = "none";
  std::string cohesion = "none";
  std::string rolling = "none";
};

}  // namespace dem
