// Best rigid motion of a soft grain; see rigid_fit.hpp.
#include "experiments/render/rigid_fit.hpp"

#include <Eigen/Geometry>

#include <stdexcept>

namespace rice::experiments {

RigidFit fit_rigid_motion(const grains::Vertices& rest, double swell, const grains::Vertices& x) {
  if (rest.rows() != x.rows() || rest.rows() < 3)
    throw std::invalid_argument("fit_rigid_motion: " + std::to_string(rest.rows()) + " rest vertices against " +
                                std::to_string(x.rows()) + " deformed ones");
  const Eigen::Matrix3Xd from = swell * rest.transpose();
  const Eigen::Matrix3Xd to = x.transpose();
  RigidFit fit;
  fit.place.matrix() = Eigen::umeyama(from, to, false);
  fit.place = fit.place * Eigen::Scaling(swell);
  fit.residual = ((fit.place * rest.transpose()) - to).colwise().norm().maxCoeff();
  return fit;
}

}  // namespace rice::experiments
