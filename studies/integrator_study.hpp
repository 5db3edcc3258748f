// SPDX-License-Identifier: MIT
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dem/integrators/scheme_id.hpp"

// The integrator-accuracy study of thesis chapter 4: the canonical single collision and
// sandwich cases, run by the in-house core with each appendix-D scheme and by the analytic
// engine at the same time points, swept over time step, N_FM, stiffness and velocity.
namespace studies {

/// What to sweep. Defaults follow thesis §4.4.
struct IntegratorStudyOptions {
  std::vector<double> timesteps;    ///< [s] global-order sweep (default 5e-7 … 5e-5, 13 points)
  std::vector<double> stiffnesses;  ///< [N/m] fig 4.17/4.18 (default 1e1 … 1e5, 9 points)
  std::vector<double> velocities;   ///< [m/s] fig 4.19/4.20 (default 0.1 … 100, 7 points)
  std::vector<double> nfm_values;   ///< fig 4.6–4.8 (default 0 … 2 by 0.05)
  double base_timestep = 5e-5;      ///< [s] thesis table 4.2
  double fit_floor = 1e-11;         ///< amplitude errors below this are round-off, not fitted
  unsigned threads = 0;             ///< 0: one per core
  std::string suite = "canonical";  ///< where single_collision.toml and sandwich.toml live
};

/// Options with every default filled in.
IntegratorStudyOptions default_options();

/// One measured amplitude error εx_amp (thesis eq 4.8) at one value of the swept parameter.
struct ErrorPoint {
  double x;
  std::optional<double> amplitude_error;  ///< empty when the run failed (see problem)
  std::string problem;
};

/// Amplitude errors of one scheme over one sweep, and the fitted slope of log ε vs log x.
struct SchemeSweep {
  dem::SchemeId scheme;
  std::vector<ErrorPoint> points;
  std::optional<double> slope;  ///< least-squares slope over points above the fit floor
  double slope_error = 0.0;     ///< standard error of the slope (scatter about the line)
  std::size_t fitted_points = 0;
};

/// A sweep of every thesis scheme over one parameter in one configuration.
struct Sweep {
  std::string key;          ///< e.g. "dt_nfm_10", "dt_sandwich", "k_nfm_10_5"
  std::string title;
  std::string parameter;    ///< axis label, with unit
  std::vector<SchemeSweep> schemes;
};

/// The thesis' practical comparison (§4.4.3): RK2 at 20 steps per collision against AB2 and BD2
/// at 40, at N_FM = 10.5.
struct ResolutionComparison {
  double rk2_at_20;
  double ab2_at_40;
  double bd2_at_40;
};

/// Everything the study measured.
struct IntegratorStudy {
  IntegratorStudyOptions options;
  std::vector<Sweep> sweeps;
  std::optional<ResolutionComparison> resolution;
  std::vector<std::string> problems;  ///< failed runs, each described
};

/// Runs the study. Throws std::runtime_error when the canonical cases cannot be loaded.
IntegratorStudy run_integrator_study(const IntegratorStudyOptions& options);

/// The sweep with `key`, or nullptr.
const Sweep* find_sweep(const IntegratorStudy& study, const std::string& key);
/// Fitted slope of `scheme` in sweep `key`, or empty.
std::optional<double> fitted_order(const IntegratorStudy& study, const std::string& key,
                                   dem::SchemeId scheme);

/// Global orders as a markdown table (scheme × configuration, with the thesis' expectation).
std::string orders_table(const IntegratorStudy& study);

/// Writes report.md (tables and PNG plots), orders.json, study_data.csv and command.txt to dir.
void write_integrator_study(const IntegratorStudy& study, const std::filesystem::path& dir,
                            int argc, const char* const* argv);

}  // namespace studies
