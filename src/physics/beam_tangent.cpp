// The co-rotational beam's global tangent (beam.h addBeamTangent): after the
// block solve, the hottest loop of a dynamic step (every beam, every Newton
// iteration). Writing 3x3 pieces into the strided corners of 6x6 blocks cost
// twice the instructions of what is done here: K(a,a) filled entry by entry
// (round sections: no 3x3 products at all), and K(b,b), K(b,a) as K(a,a)
// with block signs flipped, element-wise products of whole 6x6 matrices that
// Eigen runs four-wide. (A hand-vectorised AVX2 version of the columns was
// tried and ran no fewer instructions: it spills registers.)
//
// With t, ey, ez the element's axes (the columns of R), the global blocks
// s T K T^T follow from the distinct entries of Przemieniecki's local K:
//   K(a,a) = [tt c; c^T rs],  K(b,a) = [-tt -c; c^T rc],  K(b,b) = [tt -c; -c^T rs],
//   tt, rs, rc = R diag(axial | rotSelf | rotCross) R^T,
//   c = shearY ey ez^T - shearZ ez ey^T   (bending-shear coupling).
// For a round section R diag(d) R^T = d1 1 + (d0 - d1) t t^T. With K(a,b) =
// K(b,a)^T, the element's K v for the dynamic step's right-hand side is
//   a: (tt du + c (wa + wb),     c^T du + rs wa + rc wb),   du = ua - ub,
//   b: (-(tt du + c (wa + wb)),  c^T du + rc wa + rs wb).
#include "physics/beam.h"

namespace coilsim {
namespace {

Mat6 blockSigns(double tl, double tr, double bl, double br) {
  Mat6 m;
  m << Mat3::Constant(tl), Mat3::Constant(tr), Mat3::Constant(bl), Mat3::Constant(br);
  return m;
}

// K(a,a) and rc, times s.
void fillBlocks(const BeamRest& r, const Mat3& R, double s, Mat6& ka, Mat3& rc) {
  const Vec3 t = R.col(0), ey = R.col(1), ez = R.col(2);
  const double sY = s * r.shearY, sZ = s * r.shearZ;
  if (r.axial[1] == r.axial[2] && r.rotSelf[1] == r.rotSelf[2] && r.rotCross[1] == r.rotCross[2]) {
    const double a1 = s * r.axial[1], da = s * r.axial[0] - a1;
    const double r1 = s * r.rotSelf[1], dr = s * r.rotSelf[0] - r1;
    const double c1 = s * r.rotCross[1], dc = s * r.rotCross[0] - c1;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        const double tij = t[i] * t[j], delta = i == j ? 1.0 : 0.0;
        ka(i, j) = da * tij + delta * a1;
        ka(i + 3, j + 3) = dr * tij + delta * r1;
        rc(i, j) = dc * tij + delta * c1;
        const double cij = sY * ey[i] * ez[j] - sZ * ez[i] * ey[j];
        ka(i, j + 3) = cij;
        ka(j + 3, i) = cij;
      }
    return;
  }
  const Mat3 c = sY * (ey * ez.transpose()) - sZ * (ez * ey.transpose());
  ka << R * (s * r.axial).asDiagonal() * R.transpose(), c, c.transpose(),
      R * (s * r.rotSelf).asDiagonal() * R.transpose();
  rc = R * (s * r.rotCross).asDiagonal() * R.transpose();
}

const Mat6 kSignsBB = blockSigns(1, -1, -1, 1), kSignsBA = blockSigns(-1, -1, 1, 1);

void addBlocks(const BeamRest& r, const Mat3& R, double s, Mat6& diagA, Mat6& lowerBA, Mat6& diagB,
               const Vec6* velocity, Vec6* product, double string) {
  Mat6 ka;
  Mat3 rc;
  fillBlocks(r, R, s, ka, rc);
  diagA += ka;
  diagB = ka.cwiseProduct(kSignsBB);
  lowerBA = ka.cwiseProduct(kSignsBA);
  lowerBA.bottomRightCorner<3, 3>() = rc;
  // A taut string's stiffness across its axis: string (1 - t t^T).
  Mat3 g = Mat3::Zero();
  if (string > 0) {
    const Vec3 t = R.col(0);
    g = string * (Mat3::Identity() - t * t.transpose());
    diagA.topLeftCorner<3, 3>() += g;
    diagB.topLeftCorner<3, 3>() += g;
    lowerBA.topLeftCorner<3, 3>() -= g;
  }
  if (!velocity) return;
  const Vec3 wa = velocity[0].tail<3>(), wb = velocity[1].tail<3>();
  Vec6 x;
  x << velocity[0].head<3>() - velocity[1].head<3>(), wa + wb;
  Vec3 pt = ka.topRows<3>() * x;
  if (string > 0) pt += g * x.head<3>();
  const Vec3 q = ka.bottomLeftCorner<3, 3>() * x.head<3>();
  const auto rs = ka.bottomRightCorner<3, 3>();
  product[0].head<3>() += pt;
  product[0].tail<3>() += q + rs * wa + rc * wb;
  product[1].head<3>() -= pt;
  product[1].tail<3>() += q + rc * wa + rs * wb;
}

}  // namespace

void addBeamTangent(const BeamRest& rest, const Mat3& rotation, double scale, Mat6& diagA, Mat6& lowerBA,
                    Mat6& diagB, const Vec6* velocity, Vec6* product, double string) {
  addBlocks(rest, rotation, scale, diagA, lowerBA, diagB, velocity, product, string);
}

}  // namespace coilsim
