#include "physics/beam.h"

namespace coilsim {

Mat12 localBeamStiffness(double L, const Material& m, const Section& s) {
  const double E = m.youngModulus, G = m.shearModulus;
  // Shear flexibility ratio Phi = 12 E I / (kappa G A L^2) per bending plane.
  const double kGA = s.shearFactor > 0 ? s.shearFactor * G * s.area : 0.0;
  const double phiY = kGA > 0 ? 12.0 * E * s.iz / (kGA * L * L) : 0.0;  // bending in x-y (uses Iz)
  const double phiZ = kGA > 0 ? 12.0 * E * s.iy / (kGA * L * L) : 0.0;  // bending in x-z (uses Iy)
  Mat12 k = Mat12::Zero();
  const double L2 = L * L, L3 = L2 * L;
  k(0, 0) = k(6, 6) = E * s.area / L;
  k(0, 6) = -k(0, 0);
  k(3, 3) = k(9, 9) = G * s.torsion / L;
  k(3, 9) = -k(3, 3);
  // x-y plane: uy with theta_z.
  {
    const double c = E * s.iz / (1.0 + phiY);
    k(1, 1) = k(7, 7) = 12 * c / L3;
    k(1, 7) = -12 * c / L3;
    k(1, 5) = k(1, 11) = 6 * c / L2;
    k(5, 7) = k(7, 11) = -6 * c / L2;
    k(5, 5) = k(11, 11) = (4 + phiY) * c / L;
    k(5, 11) = (2 - phiY) * c / L;
  }
  // x-z plane: uz with theta_y (positive theta_y turns x towards -z).
  {
    const double c = E * s.iy / (1.0 + phiZ);
    k(2, 2) = k(8, 8) = 12 * c / L3;
    k(2, 8) = -12 * c / L3;
    k(2, 4) = k(2, 10) = -6 * c / L2;
    k(4, 8) = k(8, 10) = 6 * c / L2;
    k(4, 4) = k(10, 10) = (4 + phiZ) * c / L;
    k(4, 10) = (2 - phiZ) * c / L;
  }
  return k.selfadjointView<Eigen::Upper>();
}

BeamRest makeBeamRest(const Vec3& xa, const Quat& qa, const Vec3& xb, const Quat& qb,
                      const Material& material, const Section& section) {
  BeamRest r;
  const Vec3 chord = xb - xa;
  r.length = chord.norm();
  // Rest element frame: node a's frame turned (least angle) so x follows the chord.
  const Vec3 tangentA = qa * Vec3::UnitX();
  const Quat elementFrame = (minimalRotation(tangentA, chord / r.length) * qa).normalized();
  r.nodeToElement = (qa.conjugate() * elementFrame).normalized();
  r.restRelative = (elementFrame.conjugate() * qb).normalized();
  r.stiffness = localBeamStiffness(r.length, material, section);
  return r;
}

namespace {
// Global 6x6 block from a local one: each 3x3 sub-block becomes R K R^T.
inline void rotateBlock(const Mat3& R, const Mat12& k, int r0, int c0, Mat6& out) {
  for (int bi = 0; bi < 2; ++bi)
    for (int bj = 0; bj < 2; ++bj)
      out.block<3, 3>(3 * bi, 3 * bj).noalias() = R * k.block<3, 3>(r0 + 3 * bi, c0 + 3 * bj) * R.transpose();
}
}  // namespace

void evalBeam(const BeamRest& rest, const Vec3& xa, const Quat& qa, const Vec3& xb, const Quat& qb,
              bool withTangent, BeamEval& out) {
  out.frame = qa * rest.nodeToElement;
  const Mat3 R = out.frame.toRotationMatrix();
  out.deformation.head<3>() = R.transpose() * (xb - xa) - Vec3(rest.length, 0, 0);
  out.deformation.tail<3>() = quatLog(out.frame.conjugate() * qb * rest.restRelative.conjugate());
  // Holding forces of the local element for node a fixed: K(:, b) d_b.
  const Eigen::Matrix<double, 12, 1> f = rest.stiffness.rightCols<6>() * out.deformation;
  out.energy = 0.5 * out.deformation.dot(f.tail<6>());
  out.forceA.head<3>() = -(R * f.segment<3>(0));
  out.forceA.tail<3>() = -(R * f.segment<3>(3));
  out.forceB.head<3>() = -(R * f.segment<3>(6));
  out.forceB.tail<3>() = -(R * f.segment<3>(9));
  if (withTangent) {
    rotateBlock(R, rest.stiffness, 0, 0, out.kaa);
    rotateBlock(R, rest.stiffness, 6, 0, out.kba);
    rotateBlock(R, rest.stiffness, 6, 6, out.kbb);
  }
}

}  // namespace coilsim
