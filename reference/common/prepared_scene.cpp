// SPDX-License-Identifier: MIT
#include "reference/common/prepared_scene.hpp"

namespace reference {

PreparedScene::PreparedScene(const cases::Scene& scene) : scene_(&scene) {
  try {
    table_ = std::make_shared<const dem::PairTable>(scene.materials, scene.mixing, scene.pair_overrides, scene.model);
  } catch (...) {
    table_error_ = std::current_exception();
  }
}

const std::shared_ptr<const dem::PairTable>& PreparedScene::shared_pair_table() const {
  if (table_error_) std::rethrow_exception(table_error_);
  return table_;
}

}  // namespace reference
