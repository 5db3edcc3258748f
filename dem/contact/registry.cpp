// SPDX-License-Identifier: MIT
#include "dem/contact/registry.hpp"

#include <array>

#include "dem/contact/contact_model.hpp"

namespace dem {
namespace {

template <class Model>
SubModelInfo info() {
  return {Model::kKeyword, Model::kDescription,
          std::vector<std::string_view>(Model::kProperties.begin(), Model::kProperties.end()),
          Model::kLammps, Model::kYade, Model::kLiggghts};
}

template <class Variant, std::size_t... I>
std::vector<SubModelInfo> infos_of(std::index_sequence<I...>) {
  return {info<std::variant_alternative_t<I, Variant>>()...};
}

/// Rows of a slot, one per alternative of its variant: adding an alternative adds a row.
template <class Variant>
std::vector<SubModelInfo> rows_of() {
  return infos_of<Variant>(std::make_index_sequence<std::variant_size_v<Variant>>{});
}

constexpr std::array kSlots{Slot::normal, Slot::damping, Slot::tangential, Slot::cohesion,
                            Slot::rolling};

}  // namespace

std::span<const Slot> all_slots() noexcept { return kSlots; }

std::string_view to_string(Slot slot) noexcept {
  switch (slot) {
    case Slot::normal: return "normal";
    case Slot::damping: return "damping";
    case Slot::tangential: return "tangential";
    case Slot::cohesion: return "cohesion";
    case Slot::rolling: return "rolling";
  }
  return "?";
}

std::span<const SubModelInfo> sub_models(Slot slot) {
  static const std::vector<SubModelInfo> normal = rows_of<NormalModel>();
  static const std::vector<SubModelInfo> damping = rows_of<DampingModel>();
  static const std::vector<SubModelInfo> tangential = rows_of<TangentialModel>();
  static const std::vector<SubModelInfo> cohesion = rows_of<CohesionModel>();
  static const std::vector<SubModelInfo> rolling = rows_of<RollingModel>();
  switch (slot) {
    case Slot::normal: return normal;
    case Slot::damping: return damping;
    case Slot::tangential: return tangential;
    case Slot::cohesion: return cohesion;
    case Slot::rolling: return rolling;
  }
  return {};
}

const SubModelInfo* find_sub_model(Slot slot, std::string_view keyword) {
  for (const auto& row : sub_models(slot)) {
    if (row.keyword == keyword) return &row;
  }
  return nullptr;
}

std::string sub_model_keywords(Slot slot) {
  std::string out;
  for (const auto& row : sub_models(slot)) {
    if (!out.empty()) out += ", ";
    out += row.keyword;
  }
  return out;
}

}  // namespace dem
