// SPDX-License-Identifier: MIT
#include "reference/yade/restitution_calibration.hpp"

#include <charconv>
#include <cmath>
#include <iterator>

#include <fmt/format.h>

#include "dem/contact/laws/linear_dashpot.hpp"
#include "reference/common/wall_state.hpp"
#include "reference/yade/output_parser.hpp"
#include "reference/yade/python_literals.hpp"

namespace reference::yade {
namespace {

/// Parses one number of a calibration row, or throws naming file and line.
double number(std::string_view field, std::size_t line) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (ec != std::errc{} || end != field.data() + field.size() || !std::isfinite(value)) {
    throw YadeOutputError(fmt::format("{}:{}: '{}' is not a finite number", kCalibrationFile,
                                      line, field));
  }
  return value;
}

}  // namespace

std::optional<YadeCalibrationPlan> plan_calibration(const cases::Scene& scene,
                                                    const YadeModelMapping& model,
                                                    std::uint64_t max_steps) {
  if (model.law != YadeLaw::frict_visco || scene.model.damping != "restitution") return std::nullopt;
  if (model.python_cohesion) return std::nullopt;  // the two-body rebound would need the cohesion too
  YadeCalibrationPlan plan;
  std::size_t partner_material = 0;
  const auto& ps = scene.particles;
  std::array<double, 3> n{};
  cases::Vector3 partner_velocity{};  // a wall is immobile
  if (const auto& wc = scene.compare.wall_contact) {
    if (wc->first >= ps.size() || wc->second >= scene.walls.size()) return std::nullopt;
    if (!wall_in_run(scene.walls[wc->second])) return std::nullopt;  // never met in the run
    plan.particle = wc->first;
    plan.partner_wall = wc->second;
    plan.partner_wall_entry = run_wall_index(scene, wc->second);
    partner_material = scene.walls[wc->second].material;
    n = scene.walls[wc->second].normal;
  } else if (const auto& pair = scene.compare.pair) {
    if (pair->first >= ps.size() || pair->second >= ps.size()) return std::nullopt;
    const bool first_moves = !ps[pair->first].fixed;
    plan.particle = first_moves ? pair->first : pair->second;
    plan.partner_particle = first_moves ? pair->second : pair->first;
    partner_material = ps[*plan.partner_particle].material;
    partner_velocity = ps[*plan.partner_particle].velocity;
    double norm = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      n[k] = ps[plan.particle].position[k] - ps[*plan.partner_particle].position[k];
      norm += n[k] * n[k];
    }
    if (norm == 0.0) return std::nullopt;
    for (auto& c : n) c /= std::sqrt(norm);
  } else {
    return std::nullopt;
  }
  double approach = 0.0;  // (u_p − u_q)·n < 0: the two bodies close in
  for (std::size_t k = 0; k < 3; ++k) {
    approach += (ps[plan.particle].velocity[k] - partner_velocity[k]) * n[k];
  }
  if (!(approach < 0.0)) return std::nullopt;
  plan.material = ps[plan.particle].material;
  if (partner_material != plan.material) return std::nullopt;
  const auto& mat = scene.materials[plan.material];
  if (!mat.restitution) return std::nullopt;
  plan.target = *mat.restitution;
  plan.start = 0.5 * dem::laws::restitution_damping_factor(plan.target);
  plan.normal = n;
  plan.max_steps = max_steps;
  for (const auto& pair : model.pairs) plan.pairs.emplace_back(pair.material_a, pair.material_b);
  plan.description = fmt::format(
      "YADE FrictViscoMat.betan of material '{}' (two-body run: particle {} against {})",
      mat.name, plan.particle,
      plan.partner_wall ? fmt::format("wall {}", *plan.partner_wall)
                        : fmt::format("particle {}", *plan.partner_particle));
  return plan;
}

std::string write_calibration_block(const YadeCalibrationPlan& plan) {
  std::string s;
  auto out = std::back_inserter(s);
  s += "# Restitution calibration (issue 4 section 4): FrictViscoMat.betan of one material is chosen so that\n"
       "# the case's compared contact alone (same bodies, velocities and DT; no gravity, friction or\n"
       "# rotation) rebounds with the case's restitution. Secant iterations on YADE's own runs.\n";
  fmt::format_to(out,
                 "CALIBRATION = dict(material={}, target={}, start={}, particle={}, partner_particle={}, "
                 "partner_wall={}, normal={}, max_steps={})\n",
                 plan.material, py_float(plan.target), py_float(plan.start), plan.particle,
                 plan.partner_particle ? std::to_string(*plan.partner_particle) : "None",
                 plan.partner_wall ? std::to_string(plan.partner_wall_entry) : "None",
                 py_vector3(plan.normal), plan.max_steps);
  s += "CAL_PAIRS = (";
  for (const auto& [a, b] : plan.pairs) fmt::format_to(out, "({}, {}), ", a, b);
  s += ")\n";
  s += R"PY(
def _calibration_rebound(betan):
    """Restitution of the two-body YADE run with FrictViscoMat.betan = betan for the material."""
    c = CALIBRATION
    O.reset()
    label, density, young, poisson, _ = MATERIALS[c['material']]
    MATERIALS[c['material']] = (label, density, young, poisson, betan)
    _append_materials()
    radius, material, pos, vel, angvel, fixed, mass, inertia = PARTICLES[c['particle']]
    p = utils.sphere(pos, radius, material=material)
    p.state.mass = mass
    p.state.vel = vel
    p.state.blockedDOFs = 'XYZ'
    ids = [O.bodies.append(p)]
    if c['partner_wall'] is not None:
        position, axis, sense, wmat = WALLS[c['partner_wall']]
        ids.append(O.bodies.append(utils.wall(position, axis=axis, sense=sense, material=wmat)))
        partner_vel = Vector3(0, 0, 0)
    else:
        radius, material, pos, qvel, angvel, fixed, mass, inertia = PARTICLES[c['partner_particle']]
        q = utils.sphere(pos, radius, fixed=fixed, material=material)
        q.state.mass = mass
        if not fixed:
            q.state.vel = qvel
            q.state.blockedDOFs = 'XYZ'
        partner_vel = q.state.vel
        ids.append(O.bodies.append(q))
    n = c['normal']
    before = (O.bodies[ids[0]].state.vel - partner_vel).dot(n)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Wall_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Wall_Sphere_ScGeom()],
                                 [Ip2_FrictViscoMat_FrictViscoMat_FrictViscoPhys(kn=KN, kRatio=CAL_KRATIO)],
                                 [Law2_ScGeom_FrictViscoPhys_CundallStrackVisco()]),
                 NewtonIntegrator(damping=0.0, gravity=Vector3(0, 0, 0))]
    O.dt = DT
    touched = False
    for _ in range(c['max_steps']):
        O.step()
        real = O.interactions.has(ids[0], ids[1]) and O.interactions[ids[0], ids[1]].isReal
        touched = touched or real
        if touched and not real:
            break
    else:
        raise RuntimeError('calibration: the two-body run did not separate within %d steps' % c['max_steps'])
    after = (O.bodies[ids[0]].state.vel - O.bodies[ids[1]].state.vel).dot(n)
    return -after / before

CAL_KRATIO = MatchMaker(matches=tuple((a, b, 0.0) for a, b in CAL_PAIRS), algo='val', val=float('nan'))
_samples = []
_b0 = CALIBRATION['start']
_e0 = _calibration_rebound(_b0); _samples.append((_b0, _e0))
_b1 = _b0 * (1.0 + 2.0 * (_e0 - CALIBRATION['target']))
for _ in range(20):
    _e1 = _calibration_rebound(_b1); _samples.append((_b1, _e1))
    if abs(_e1 - CALIBRATION['target']) <= 1e-12 or _e1 == _e0:
        break
    _b0, _e0, _b1 = _b1, _e1, _b1 - (_e1 - CALIBRATION['target']) * (_b1 - _b0) / (_e1 - _e0)
_chosen = min(_samples, key=lambda s: abs(s[1] - CALIBRATION['target']))
with open()PY";
  s += py_string(kCalibrationFile);
  s += R"PY(, 'w') as _f:
    _f.write('betan,restitution\n')
    for b, e in _samples + [_chosen]:
        _f.write('%.17g,%.17g\n' % (b, e))
label, density, young, poisson, _ = MATERIALS[CALIBRATION['material']]
MATERIALS[CALIBRATION['material']] = (label, density, young, poisson, _chosen[0])
O.reset()
_append_materials()
_append_particles()
_append_walls()

)PY";
  return s;
}

cases::Calibration parse_calibration_csv(std::string_view text, const YadeCalibrationPlan& plan) {
  cases::Calibration c;
  c.parameter = plan.description;
  c.target = plan.target;
  std::size_t line = 0;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view row = text.substr(begin, end - begin);
    begin = end + 1;
    ++line;
    if (line == 1 || row.empty()) continue;
    const std::size_t comma = row.find(',');
    if (comma == std::string_view::npos) {
      throw YadeOutputError(fmt::format("{}:{}: expected 'betan,restitution'", kCalibrationFile, line));
    }
    c.samples.emplace_back(number(row.substr(0, comma), line), number(row.substr(comma + 1), line));
  }
  if (c.samples.size() < 2) {
    throw YadeOutputError(fmt::format("{}: no calibration runs", kCalibrationFile));
  }
  c.chosen = c.samples.back().first;
  c.samples.pop_back();
  c.method = fmt::format(
      "secant on two-body YADE runs (the compared contact alone: same radii, masses, velocities "
      "and Δt; no gravity, friction or rotation), starting from the textbook betan = β(ε)/2 = "
      "{:.9g}; stops at |e − ε| ≤ 1e-12 or after 21 runs; the run closest to ε is chosen",
      plan.start);
  return c;
}

}  // namespace reference::yade
