// SPDX-License-Identifier: MIT
#include "dem/integrators/state_algebra.hpp"

namespace dem {

void derivative_of(const KinematicState& state, const Accelerations& acc, Derivative& out) {
  out.velocity = state.velocity;
  out.acceleration = acc.linear;
  out.angular_velocity = state.angular_velocity;
  out.angular_acceleration = acc.angular;
}

void add_scaled(Derivative& y, double c, const Derivative& x) {
  y.velocity += c * x.velocity;
  y.acceleration += c * x.acceleration;
  y.angular_velocity += c * x.angular_velocity;
  y.angular_acceleration += c * x.angular_acceleration;
}

void scale(double c, const Derivative& x, Derivative& out) {
  out.velocity = c * x.velocity;
  out.acceleration = c * x.acceleration;
  out.angular_velocity = c * x.angular_velocity;
  out.angular_acceleration = c * x.angular_acceleration;
}

void turn_orientations(std::vector<Quat>& orientation, double h, const Vec3Array& angular_velocity) {
  for (std::size_t i = 0; i < orientation.size(); ++i) {
    const Vec3 theta = h * angular_velocity.col(static_cast<Eigen::Index>(i));
    const double angle = theta.norm();
    if (angle > 0.0) {
      orientation[i] = (Quat(Eigen::AngleAxisd(angle, theta / angle)) * orientation[i]).normalized();
    }
  }
}

void advance(const KinematicState& base, double h, const Derivative& d, bool rotation,
             KinematicState& out, bool orientation) {
  out.time = base.time + h;
  out.position = base.position + h * d.velocity;
  out.velocity = base.velocity + h * d.acceleration;
  out.orientation = base.orientation;
  if (!rotation) {
    out.angular_velocity = base.angular_velocity;
    return;
  }
  out.angular_velocity = base.angular_velocity + h * d.angular_acceleration;
  if (orientation) turn_orientations(out.orientation, h, d.angular_velocity);
}

double max_abs_difference(const Vec3Array& a, const Vec3Array& b) noexcept {
  if (a.size() == 0) return 0.0;
  return (a - b).cwiseAbs().maxCoeff();
}

void orientation_rate(const std::vector<Quat>& from, const std::vector<Quat>& to, double h,
                      Vec3Array& out) {
  out.resize(3, static_cast<Eigen::Index>(from.size()));
  for (std::size_t i = 0; i < from.size(); ++i) {
    const Eigen::AngleAxisd turn(to[i] * from[i].conjugate());
    out.col(static_cast<Eigen::Index>(i)) = turn.angle() * turn.axis() / h;
  }
}

}  // namespace dem
