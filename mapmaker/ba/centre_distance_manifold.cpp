#include "mapmaker/ba/centre_distance_manifold.hpp"

#include <cmath>

#include <ceres/autodiff_manifold.h>

#include "core/lie/manifolds.hpp"
#include "core/lie/se3.hpp"
#include "core/util/error.hpp"

namespace facadeslam {
namespace {

// Plus/Minus templated for ceres::AutoDiffManifold, which differentiates
// them for PlusJacobian/MinusJacobian (only used once per solve and
// iteration for one block, so auto-diff costs nothing noticeable).
class CentreOnSphere {
 public:
  CentreOnSphere(const Eigen::Vector3d& anchor, double radius) : anchor_(anchor), radius_(radius) {}

  template <class T>
  bool Plus(const T* x, const T* delta, T* x_plus_delta) const {
    using Vector3 = Eigen::Matrix<T, 3, 1>;
    const SE3<T> pose = se3_from_params(x);
    const Vector3 v = centre(pose) - anchor_.cast<T>();
    Vector3 e1, e2;
    tangent_basis(v, e1, e2);
    const Vector3 moved = v + delta[0] * e1 + delta[1] * e2;
    const Vector3 c_new = anchor_.cast<T>() + moved * (T(radius_) / moved.norm());
    const SO3<T> r_new = SO3<T>::exp(Vector3(delta[2], delta[3], delta[4])) * pose.so3();
    se3_to_params(SE3<T>(r_new, -(r_new * c_new)), x_plus_delta);
    return true;
  }

  template <class T>
  bool Minus(const T* y, const T* x, T* y_minus_x) const {
    using Vector3 = Eigen::Matrix<T, 3, 1>;
    const SE3<T> pose_x = se3_from_params(x);
    const SE3<T> pose_y = se3_from_params(y);
    const Vector3 v = centre(pose_x) - anchor_.cast<T>();
    const Vector3 w = centre(pose_y) - anchor_.cast<T>();
    Vector3 e1, e2;
    tangent_basis(v, e1, e2);
    // The (a, b) that Plus maps onto w's direction: v + U parallel to w with
    // U orthogonal to v, i.e. U = w |v|^2 / (w . v) - v.
    const Vector3 u = w * (v.squaredNorm() / w.dot(v)) - v;
    const Vector3 omega = (pose_y.so3() * pose_x.so3().inverse()).log();
    y_minus_x[0] = u.dot(e1);
    y_minus_x[1] = u.dot(e2);
    y_minus_x[2] = omega.x();
    y_minus_x[3] = omega.y();
    y_minus_x[4] = omega.z();
    return true;
  }

 private:
  template <class T>
  static Eigen::Matrix<T, 3, 1> centre(const SE3<T>& T_c_w) {
    return -(T_c_w.so3().inverse() * T_c_w.translation());
  }

  // Orthonormal basis of the plane orthogonal to v, built from the world
  // axis least aligned with v (a deterministic, well-conditioned choice).
  template <class T>
  static void tangent_basis(const Eigen::Matrix<T, 3, 1>& v, Eigen::Matrix<T, 3, 1>& e1, Eigen::Matrix<T, 3, 1>& e2) {
    using std::abs;
    using Vector3 = Eigen::Matrix<T, 3, 1>;
    const Vector3 n = v / v.norm();
    Vector3 axis = Vector3::Zero();
    if (abs(n.x()) <= abs(n.y()) && abs(n.x()) <= abs(n.z()))
      axis.x() = T(1);
    else if (abs(n.y()) <= abs(n.z()))
      axis.y() = T(1);
    else
      axis.z() = T(1);
    e1 = n.cross(axis);
    e1 /= e1.norm();
    e2 = n.cross(e1);
  }

  Eigen::Vector3d anchor_;
  double radius_;
};

}  // namespace

std::unique_ptr<ceres::Manifold> make_centre_distance_manifold(const Eigen::Vector3d& anchor, double radius) {
  if (!anchor.allFinite() || !std::isfinite(radius) || !(radius > 0.0))
    throw Error("bundle adjustment: the scale anchor needs a finite centre and a radius > 0");
  return std::make_unique<ceres::AutoDiffManifold<CentreOnSphere, kSe3ParamSize, 5>>(
      new CentreOnSphere(anchor, radius));
}

}  // namespace facadeslam
