// SPDX-License-Identifier: MIT
#include "dem/integrators/state_algebra.hpp"

namespace dem {

Derivative derivative_of(const KinematicState& state, const Accelerations& acc) {
  return {state.velocity, acc.linear, state.angular_velocity, acc.angular};
}

void add_scaled(Derivative& y, double c, const Derivative& x) {
  y.velocity += c * x.velocity;
  y.acceleration += c * x.acceleration;
  y.angular_velocity += c * x.angular_velocity;
  y.angular_acceleration += c * x.angular_acceleration;
}

Derivative scaled(double c, const Derivative& x) {
  return {c * x.velocity, c * x.acceleration, c * x.angular_velocity, c * x.angular_acceleration};
}

void advance(const KinematicState& base, double h, const Derivative& d, bool rotation,
             KinematicState& out) {
  out.time = base.time + h;
  out.position = base.position + h * d.velocity;
  out.velocity = base.velocity + h * d.acceleration;
  if (!rotation) {
    out.angular_velocity = base.angular_velocity;
    out.orientation = base.orientation;
    return;
  }
  out.angular_velocity = base.angular_velocity + h * d.angular_acceleration;
  out.orientation.resize(base.orientation.size());
  for (std::size_t i = 0; i < base.orientation.size(); ++i) {
    const Vec3 theta = h * d.angular_velocity.col(static_cast<Eigen::Index>(i));
    const double angle = theta.norm();
    if (angle > 0.0) {
      out.orientation[i] = (Quat(Eigen::AngleAxisd(angle, theta / angle)) * base.orientation[i])
                               .normalized();
    } else {
      out.orientation[i] = base.orientation[i];
    }
  }
}

double max_abs_difference(const Vec3Array& a, const Vec3Array& b) noexcept {
  if (a.size() == 0) return 0.0;
  return (a - b).cwiseAbs().maxCoeff();
}

Vec3Array orientation_rate(const std::vector<Quat>& from, const std::vector<Quat>& to, double h) {
  Vec3Array rate(3, static_cast<Eigen::Index>(from.size()));
  for (std::size_t i = 0; i < from.size(); ++i) {
    const Eigen::AngleAxisd turn(to[i] * from[i].conjugate());
    rate.col(static_cast<Eigen::Index>(i)) = turn.angle() * turn.axis() / h;
  }
  return rate;
}

}  // namespace dem
