// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace dem {

/// A 3-vector in SI units (position [m], velocity [m/s], force [N], …).
using Vec3 = Eigen::Vector3d;
/// Orientation of a particle as a unit quaternion (thesis eq C.9 in quaternion form).
using Quat = Eigen::Quaterniond;
/// One 3-vector per particle, stored column-wise (structure of arrays).
using Vec3Array = Eigen::Matrix3Xd;
/// One scalar per particle.
using ScalarArray = Eigen::VectorXd;

}  // namespace dem
