// The fast global tangent of evalBeam (outer products of the element axes)
// must equal the textbook co-rotational tangent T K T^T, T = diag(R, R, R, R),
// computed here independently by dense 12x12 products.
#include <gtest/gtest.h>

#include "physics/beam.h"

namespace coilsim {
namespace {

TEST(BeamTangent, EqualsRotatedLocalStiffness) {
  Material mat{7.5e9, shearModulusOf(7.5e9, 0.39), 21450};
  Section sec = circularSection(0.3e-3, 0.39);
  sec.iz *= 1.7;  // unequal bending stiffness: exercises both shear terms separately
  const Quat qa = Quat(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()));
  const Quat qb = Quat(Eigen::AngleAxisd(0.35, Vec3(1, 2.2, 3).normalized()));
  const Vec3 xa(0.001, -0.002, 0.0005), xb = xa + qa * Vec3(0.0005, 0.00002, -0.00001);
  const BeamRest rest = makeBeamRest(xa, qa, xb, qb, mat, sec);
  // Deform: rotate and move node b a little, rotate the whole element a lot.
  const Quat big(Eigen::AngleAxisd(2.0, Vec3(-1, 0.5, 0.2).normalized()));
  BeamEval ev;
  evalBeam(rest, big * xa, big * qa, big * (xb + Vec3(1e-5, 2e-5, -1e-5)), big * quatExp(Vec3(0.01, -0.02, 0.03)) * qb,
           true, ev);
  const Mat3 R = ev.frame.toRotationMatrix();
  Mat12 T = Mat12::Zero();
  for (int k = 0; k < 4; ++k) T.block<3, 3>(3 * k, 3 * k) = R;
  const Mat12 K = T * rest.stiffness * T.transpose();
  const double scale = K.cwiseAbs().maxCoeff();
  EXPECT_LT((ev.kaa - K.block<6, 6>(0, 0)).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_LT((ev.kba - K.block<6, 6>(6, 0)).cwiseAbs().maxCoeff(), 1e-12 * scale);
  EXPECT_LT((ev.kbb - K.block<6, 6>(6, 6)).cwiseAbs().maxCoeff(), 1e-12 * scale);
}

}  // namespace
}  // namespace coilsim
