// SPDX-License-Identifier: MIT
#pragma once

namespace dem {

/// What a normal sub-model returns: the elastic force and its local stiffness.
struct NormalResponse {
  double force;      ///< elastic normal force [N], repulsive positive
  double stiffness;  ///< dF/dδ at this overlap [N/m], used by damping sub-models
  double energy;     ///< elastic energy stored in the contact [J]
};

}  // namespace dem
