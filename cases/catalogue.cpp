// SPDX-License-Identifier: MIT
#include "cases/catalogue.hpp"

#include <algorithm>
#include <array>
#include <string>

namespace cases {
namespace {

constexpr std::array kMetrics{
    MetricInfo{"contact_duration", "s",
               "time between the overlap's sign changes, each located by linear interpolation", true, false},
    MetricInfo{"restitution", "-",
               "normal relative speed after / before the first contact of the compared pair", true, false},
    MetricInfo{"max_overlap", "m", "largest overlap of the compared pair (parabolic refinement)", true, false},
    MetricInfo{"max_force", "N",
               "largest normal force of the compared pair (parabolic refinement)", true, false},
    MetricInfo{"max_position", "m",
               "largest displacement of the subject along the collision axis, over the samples", false, true},
    MetricInfo{"amplitude_error", "-",
               "εx_amp, thesis eq 4.8: |max x_num − max x_analytic| over the same samples, "
               "divided by the analytic maximum overlap", true, true},
    MetricInfo{"tangential_restitution", "-",
               "−u_t,after·t̂/|u_t,before| of the contact-point tangential velocity (branch vectors at "
               "touch), first contact of the compared contact", true, true},
    MetricInfo{"rebound_angle", "deg",
               "angle between the relative velocity after the first contact and the contact normal", true, true},
    MetricInfo{"spin_after", "rad/s",
               "subject's angular velocity after the first contact about t̂ × n_in (t̂: slip direction "
               "before, n_in: into the partner)", true, true},
    MetricInfo{"velocity_after_x", "m/s", "subject's velocity, x component, at the first sample after its first contact with the compared partner ends", true, true},
    MetricInfo{"velocity_after_y", "m/s", "subject's velocity, y component, after the first contact (as velocity_after_x)", true, true},
    MetricInfo{"velocity_after_z", "m/s", "subject's velocity, z component, after the first contact (as velocity_after_x)", true, true},
    MetricInfo{"angular_velocity_after_x", "rad/s", "subject's angular velocity, x component, at the first sample after its first contact with the compared partner ends", true, true},
    MetricInfo{"angular_velocity_after_y", "rad/s", "subject's angular velocity, y component, after the first contact (as angular_velocity_after_x)", true, true},
    MetricInfo{"angular_velocity_after_z", "rad/s", "subject's angular velocity, z component, after the first contact (as angular_velocity_after_x)", true, true},
    MetricInfo{"tangential_force_max", "N",
               "largest tangential force of the subject's first contact with the compared partner "
               "(its traced force less its weight, projected on the contact plane; the scene must "
               "hold only the subject and its partner)", true, true},
    MetricInfo{"deceleration", "m/s²",
               "minus the least-squares slope of the subject's tangential speed while the compared "
               "contact slides (slip > 1 % of its initial value)", true, true},
    MetricInfo{"pulloff_force", "N",
               "largest tension −F_n of the compared contact over the trace (parabolic refinement)", true, false},
    MetricInfo{"rupture_separation", "m",
               "separation −δ at which the compared contact last breaks in tension (fold vertex or midpoint of the bracketing samples)", true, false},
    MetricInfo{"force_at_rupture", "N",
               "normal force of the compared contact just before it last breaks (negative: tension)", true, false},
    MetricInfo{"separation_work", "J",
               "work ∫F dℓ of the compared contact's force from its deepest overlap to rupture (appendix E)", true, false},
    MetricInfo{"equilibrium_overlap", "m", "overlap of the compared contact at the last sample", true, false},
    MetricInfo{"kappa_vol", "-",
               "κVOL, thesis eq 5.2: volume of the largest final fragment / volume of the formed agglomerate", false, false},
    MetricInfo{"kappa_damage", "-",
               "κDAMAGE: fraction of the formed agglomerate's body contacts that no longer touch at the end", false, false},
    MetricInfo{"fragments", "-", "fragments at the end (spheres joined while their law still acts; a lone sphere is one)", false, false},
    MetricInfo{"coordination_before", "-", "2 × body contacts / spheres of the formed agglomerate", false, false},
    MetricInfo{"coordination_after", "-", "2 × body contacts / spheres at the end", false, false},
    MetricInfo{"packing_fraction", "-",
               "volume of the mobile spheres inside the compare.packing region (each clipped at its faces) / the "
               "region's volume, at the last snapshot", false, false},
    MetricInfo{"packing_fraction_interior", "-",
               "packing_fraction of the region shrunk by compare.packing.interior_margin on every side (default "
               "two mean diameters), away from the walls' ordering", false, false},
    MetricInfo{"orf", "-",
               "obscured reservoir fraction, thesis appendix G: share of a grid over the region's y–z face covered "
               "by mobile spheres whose centres lie in the region, seen along x, at the last snapshot", false, false},
    MetricInfo{"dose_remaining", "-",
               "share of the mobile spheres whose centres lie in the compare.packing region, at the last snapshot",
               false, false},
    MetricInfo{"coordination_number", "-",
               "mean body contacts (overlap > 0) with other mobile spheres of the mobile spheres whose centres lie "
               "in the compare.packing region, at the last snapshot", false, false},
    MetricInfo{"fluidisation_time", "s",
               "first time the ORF in the compare.packing region falls to compare.packing.orf_threshold (default "
               "0.1), interpolated linearly between snapshots; missing when the bed never empties that far", false, false},
    MetricInfo{"orf_largest_drop", "-",
               "largest fall of the ORF between two consecutive snapshots: the biggest share of the reservoir cleared "
               "at once (large fragments make it large, a stream small)", false, false},
    MetricInfo{"largest_departed_fragment", "-",
               "largest fragment (spheres closer than 1.05 × the sum of their radii) of the mobile spheres whose centres "
               "have left the compare.packing region, as a share of the dose's volume, over all snapshots: a plug "
               "pushed out whole makes it large, a stream of single spheres small", false, false},
    MetricInfo{"mass_flow_rate", "kg/s",
               "steady discharge rate: least-squares slope of the mobile mass past the compare.discharge outlet "
               "against time, over the snapshots at which the share past it lies in compare.discharge.fit", false, false},
    MetricInfo{"discharged_fraction", "-",
               "share of the mobile mass past the compare.discharge outlet at the last snapshot", false, false},
    MetricInfo{"cohesive_work", "J",
               "work to separate two mean-size spheres from their force-free contact until cohesion ends (thesis fig. 5.15)", false, false},
};

constexpr std::array<std::string_view, 5> kEngines{"inhouse", "analytic", "lammps", "yade", "liggghts"};

}  // namespace

std::span<const MetricInfo> metric_catalogue() noexcept { return kMetrics; }

bool is_known_metric(std::string_view name) noexcept {
  return std::any_of(kMetrics.begin(), kMetrics.end(),
                     [&](const MetricInfo& m) { return m.name == name; });
}

const MetricInfo* find_metric(std::string_view name) noexcept {
  for (const auto& m : kMetrics) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

std::span<const std::string_view> engine_catalogue() noexcept { return kEngines; }

bool is_known_engine(std::string_view name) noexcept {
  return std::find(kEngines.begin(), kEngines.end(), name) != kEngines.end() ||
         !matched_code(name).empty();
}

std::string matched_engine_name(std::string_view code) { return "inhouse@" + std::string(code); }

std::string_view matched_code(std::string_view engine) noexcept {
  constexpr std::string_view kPrefix = "inhouse@";
  if (!engine.starts_with(kPrefix)) return {};
  const std::string_view code = engine.substr(kPrefix.size());
  return is_reference_code(code) ? code : std::string_view{};
}

std::span<const std::string_view> reference_codes() noexcept {
  static constexpr std::array<std::string_view, 3> kCodes{"lammps", "yade", "liggghts"};
  return kCodes;
}

bool is_reference_code(std::string_view name) noexcept {
  const auto codes = reference_codes();
  return std::find(codes.begin(), codes.end(), name) != codes.end();
}

}  // namespace cases
