// SPDX-License-Identifier: MIT
#include "dem/conversion/appendix_e.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include <boost/math/tools/toms748_solve.hpp>
#include <fmt/format.h>

namespace dem::conversion {
namespace {

/// Throws std::invalid_argument unless 0 < value < ∞.
void require_positive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(fmt::format("{} must be a finite number > 0, got {}", what, value));
  }
}

/// Throws std::invalid_argument unless the geometry is physical.
void check_pair(const PairGeometry& pair) {
  require_positive(pair.radius, "radius");
  require_positive(pair.effect_radius, "effect radius");
  require_positive(pair.max_overlap, "maximum overlap");
  if (pair.effect_radius < pair.radius) {
    throw std::invalid_argument(fmt::format("effect radius ({} m) must be >= radius ({} m)",
                                            pair.effect_radius, pair.radius));
  }
  if (pair.max_overlap >= pair.radius) {
    throw std::invalid_argument(fmt::format("maximum overlap ({} m) must be smaller than the radius ({} m)",
                                            pair.max_overlap, pair.radius));
  }
}

}  // namespace

double formula_radius(const PairGeometry& pair, Convention convention) noexcept {
  return convention == Convention::thesis ? pair.radius : 0.5 * pair.radius;
}

double formula_modulus(double youngs_modulus, double poisson_ratio, Convention convention) noexcept {
  if (convention == Convention::thesis) return youngs_modulus;
  return youngs_modulus / (2.0 * (1.0 - poisson_ratio * poisson_ratio));
}

double youngs_modulus(double modulus, double poisson_ratio, Convention convention) noexcept {
  if (convention == Convention::thesis) return modulus;
  return 2.0 * (1.0 - poisson_ratio * poisson_ratio) * modulus;
}

double stiffness_from_modulus(double modulus, double radius, double max_overlap) noexcept {
  return 16.0 / 15.0 * modulus * std::sqrt(radius * max_overlap);
}

double modulus_from_stiffness(double stiffness, double radius, double max_overlap) noexcept {
  return 15.0 * stiffness / (16.0 * std::sqrt(radius * max_overlap));
}

double max_effect_overlap(const PairGeometry& pair) noexcept {
  return 2.0 * (pair.effect_radius - pair.radius) + pair.max_overlap;
}

double linear_separation_work(const LinearModel& model, const PairGeometry& pair) noexcept {
  const double d = pair.max_overlap;
  const double e = max_effect_overlap(pair);
  return 0.5 * model.normal_stiffness * d * d - 0.5 * model.cohesive_stiffness * e * e;
}

double hertz_separation_work(double modulus, double radius, double max_overlap) noexcept {
  return 8.0 / 15.0 * modulus * std::sqrt(radius) * std::pow(max_overlap, 2.5);
}

double jkr_separation_work(const laws::JkrParameters& p, double max_overlap,
                           JkrRupture rupture) noexcept {
  const double end = rupture == JkrRupture::load ? laws::jkr_pulloff_radius(p)
                                                 : laws::jkr_critical_radius(p);
  return laws::jkr_energy(laws::jkr_contact_radius(max_overlap, p), p) - laws::jkr_energy(end, p);
}

double linear_cohesive_work(const LinearModel& model, double radius, double effect_radius) {
  if (!(model.normal_stiffness > model.cohesive_stiffness) || !(model.cohesive_stiffness >= 0.0)) {
    throw std::invalid_argument(fmt::format("linear cohesive work needs 0 <= k_c < k_e (k_e = {}, k_c = {})",
                                            model.normal_stiffness, model.cohesive_stiffness));
  }
  if (!(effect_radius >= radius) || !(radius > 0.0)) {
    throw std::invalid_argument(fmt::format("linear cohesive work needs 0 < r <= r̂ (r = {}, r̂ = {})", radius, effect_radius));
  }
  const double reach = 2.0 * (effect_radius - radius);
  const double equilibrium = model.cohesive_stiffness * reach / (model.normal_stiffness - model.cohesive_stiffness);
  return 0.5 * model.cohesive_stiffness * (equilibrium + reach) * (equilibrium + reach) -
         0.5 * model.normal_stiffness * equilibrium * equilibrium;
}

double jkr_cohesive_work(const laws::JkrParameters& p, JkrRupture rupture) noexcept {
  const double end = rupture == JkrRupture::load ? laws::jkr_pulloff_radius(p) : laws::jkr_critical_radius(p);
  return laws::jkr_energy(end, p) - laws::jkr_energy(laws::jkr_zero_load_radius(p), p);
}

double surface_energy_for_work(double work, double modulus, double radius, double max_overlap,
                               JkrRupture rupture) {
  require_positive(modulus, "modulus");
  require_positive(radius, "radius");
  require_positive(max_overlap, "maximum overlap");
  if (!std::isfinite(work)) throw std::invalid_argument(fmt::format("work must be finite, got {}", work));
  const double hertz = hertz_separation_work(modulus, radius, max_overlap);
  if (!(work < hertz)) {
    throw std::domain_error(fmt::format(
        "no surface energy > 0 matches: the target work {:.6g} J is not below the work of Hertz "
        "repulsion alone, {:.6g} J (the cohesion is too weak or the stiffness too high)",
        work, hertz));
  }
  // h(t) = W(γ = e^t) − work decreases in t. The scale E* δ_max [J/m²] starts the bracket.
  const auto h = [&](double t) {
    return jkr_separation_work({modulus, radius, std::exp(t)}, max_overlap, rupture) - work;
  };
  const double start = std::log(modulus * max_overlap);
  double lo = start - 2.0;
  double hi = start;
  for (int k = 0; k < 200 && !(h(lo) > 0.0); ++k) lo -= 2.0;
  for (int k = 0; k < 200 && !(h(hi) < 0.0); ++k) hi += 2.0;
  if (!(h(lo) > 0.0) || !(h(hi) < 0.0)) {
    throw std::domain_error(fmt::format("no surface energy matches the work {:.6g} J", work));
  }
  std::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(
      h, lo, hi, boost::math::tools::eps_tolerance<double>(std::numeric_limits<double>::digits - 3),
      iterations);
  return std::exp(0.5 * (bracket.first + bracket.second));
}

JkrModel linear_to_jkr(const LinearModel& model, const PairGeometry& pair, Convention convention,
                       JkrRupture rupture) {
  check_pair(pair);
  require_positive(model.normal_stiffness, "elastic stiffness k_e");
  if (!(model.cohesive_stiffness >= 0.0) || !std::isfinite(model.cohesive_stiffness)) {
    throw std::invalid_argument(
        fmt::format("cohesive stiffness k_c must be finite and >= 0, got {}", model.cohesive_stiffness));
  }
  const double radius = formula_radius(pair, convention);
  const double modulus = modulus_from_stiffness(model.normal_stiffness, radius, pair.max_overlap);
  const double work = linear_separation_work(model, pair);
  if (model.cohesive_stiffness == 0.0) return {modulus, 0.0};
  return {modulus, surface_energy_for_work(work, modulus, radius, pair.max_overlap, rupture)};
}

LinearModel jkr_to_linear(const JkrModel& model, const PairGeometry& pair, Convention convention,
                          JkrRupture rupture) {
  check_pair(pair);
  require_positive(model.modulus, "modulus");
  if (!(model.surface_energy >= 0.0) || !std::isfinite(model.surface_energy)) {
    throw std::invalid_argument(
        fmt::format("surface energy must be finite and >= 0, got {}", model.surface_energy));
  }
  const double radius = formula_radius(pair, convention);
  const double k_e = stiffness_from_modulus(model.modulus, radius, pair.max_overlap);
  if (model.surface_energy == 0.0) return {k_e, 0.0};
  const double work = jkr_separation_work({model.modulus, radius, model.surface_energy},
                                          pair.max_overlap, rupture);
  const double e = max_effect_overlap(pair);
  if (!(e > 0.0)) {
    throw std::domain_error("effect radius equals the radius and δ_max = 0: no cohesion range to match");
  }
  const double k_c = (k_e * pair.max_overlap * pair.max_overlap - 2.0 * work) / (e * e);
  if (!(k_c >= 0.0)) {
    throw std::domain_error(fmt::format("equal work needs a negative cohesive stiffness ({:.6g} N/m)", k_c));
  }
  return {k_e, k_c};
}

}  // namespace dem::conversion
