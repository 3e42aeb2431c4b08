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
  const Mat12& k = r.stiffness;
  r.axial = Vec3(k(0, 0), k(1, 1), k(2, 2));
  r.rotSelf = Vec3(k(3, 3), k(4, 4), k(5, 5));
  r.rotCross = Vec3(k(3, 9), k(4, 10), k(5, 11));
  r.shearY = k(1, 5);
  r.shearZ = -k(2, 4);
  return r;
}

namespace {

// The least rotation taking the x axis of unit quaternion q onto unit vector
// b: q' = (1 + a.b, a x b) normalised, a = q e_x read off the rotation
// matrix's first column. minimalRotation() without its norms, which are 1
// here, and without rotating a vector by a quaternion: every beam, every step.
inline Quat turnOntoChord(const Quat& q, const Vec3& b) {
  const double w = q.w(), x = q.x(), y = q.y(), z = q.z();
  const Vec3 a(1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y));
  const double c = a.dot(b);
  if (c < -1.0 + 1e-12) return minimalRotation(a, b);
  const Vec3 axis = a.cross(b);
  return Quat(1 + c, axis.x(), axis.y(), axis.z()).normalized();
}

}  // namespace

void evalBeam(const BeamRest& rest, const Vec3& xa, const Quat& qa, const Vec3& xb, const Quat& qb,
              bool withTangent, BeamEval& out) {
  const Quat carried = qa * rest.nodeToElement;  // node a's frame turned by the rest offset
  const Quat carriedB = qb * rest.restRelative.conjugate();  // the same frame as node b carries it
  // Mean of the two carried frames, halfway along the relative rotation:
  // for unit quaternions in one hemisphere that is exactly their normalised sum.
  const double side = carried.coeffs().dot(carriedB.coeffs()) < 0 ? -1.0 : 1.0;
  Quat mean;
  mean.coeffs() = (carried.coeffs() + side * carriedB.coeffs()).normalized();
  const Vec3 chord = xb - xa;
  const double length = chord.norm();
  out.frame = (turnOntoChord(mean, chord / length) * mean).normalized();
  out.rotation = out.frame.toRotationMatrix();
  const Mat3& R = out.rotation;
  out.rotationA = quatLog(out.frame.conjugate() * carried);
  out.deformation << length - rest.length, 0, 0, quatLog(out.frame.conjugate() * carriedB);
  // Holding forces of the local element, K d, from the distinct entries of
  // K: d has the stretch and the two end rotations only. The transverse end
  // forces are then taken from the end moments over the current length, so
  // that the element balances moments exactly when it is stretched too.
  const double u = out.deformation[0];
  const Vec3& ta = out.rotationA;
  const Vec3 tb = out.deformation.tail<3>();
  Eigen::Matrix<double, 12, 1> f;
  const Vec3 ma = rest.rotSelf.cwiseProduct(ta) + rest.rotCross.cwiseProduct(tb);
  const Vec3 mb = rest.rotCross.cwiseProduct(ta) + rest.rotSelf.cwiseProduct(tb);
  f[6] = rest.axial[0] * u;
  f[0] = -f[6];
  f.segment<3>(3) = ma;
  f.segment<3>(9) = mb;
  out.energy = 0.5 * (u * f[6] + ta.dot(ma) + tb.dot(mb));
  f[7] = -(f[5] + f[11]) / length;
  f[8] = (f[4] + f[10]) / length;
  f[1] = -f[7];
  f[2] = -f[8];
  out.forceA.head<3>() = -(R * f.segment<3>(0));
  out.forceA.tail<3>() = -(R * f.segment<3>(3));
  out.forceB.head<3>() = -(R * f.segment<3>(6));
  out.forceB.tail<3>() = -(R * f.segment<3>(9));
  if (withTangent) {
    out.kaa.setZero();
    addBeamTangent(rest, R, 1.0, out.kaa, out.kba, out.kbb);
  }
}

}  // namespace coilsim
