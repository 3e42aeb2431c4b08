#pragma once
// An independent discrete Cosserat rod for the validation tests. It shares no
// code with src/: positions at nodes, one material frame (unit quaternion) per
// edge on a staggered grid, finite stretch and shear, bend and twist strains
// from the relative rotation of neighbouring frames, and element energies
// differentiated exactly by forward-mode jets (jet.h). SI units throughout.
//
// Material coordinate u runs from the distal tip (u = 0) to the proximal end
// (u = L); arc length from the catheter tip outward is s = l - u at deployed
// length l. The rod is simulated in s: node 0 is the clamp (the catheter tip,
// or the fixed base of a compliant tube that ends at s = 0).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

namespace refrod {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;
using Triplets = std::vector<Eigen::Triplet<double>>;

// Stiffness and loads of one kind of cross-section.
struct Section {
  double EA = 0, GA = 0;            // N: stretch and (both) shear stiffness
  double EI1 = 0, EI2 = 0, GJ = 0;  // N m^2: bending about d1, d2 and twist
  double mu = 0;                    // kg/m: mass per length
  Vec3 weight = Vec3::Zero();       // N/m: gravity minus buoyancy, true gravity
  double radius = 0;                // m: outer radius (contact, drag)
};

// A solid circular wire of radius r (m), Young's modulus E (Pa), Poisson nu,
// density rho (kg/m^3) in a fluid of density rhoFluid, under gravity g.
// Shear uses the Timoshenko factor 0.9 of a circle.
Section wireSection(double r, double E, double nu, double rho, double rhoFluid, const Vec3& g);

// The free tube with the coil inside, as one composite section: stiffnesses
// and weights add (tube wall plus coil; both buoyant in the fluid).
Section tubeSection(double rOut, double rIn, double Et, double nut, double rhoT, const Section& coil,
                    double coilRadius, double coilRho, double rhoFluid, const Vec3& g);

// What does not change in a run (the Model).
struct RodSpec {
  double length = 0.1;           // m: coil length L
  int coilEdges = 200;           // material grid of the coil: h = L / coilEdges
  Section coil;
  Vec3 restDarboux = Vec3::Zero();  // 1/m: (kappa1, kappa2, tau) of the rest shape, constant
  // Optional compliant catheter tube ending at s = 0, clamped at s = -tubeLength.
  double tubeLength = 0;
  int tubeEdges = 0;
  Section tube;
  // Clamp: tip position, exit direction d3 and reference normal d1 (twist 0).
  Vec3 tip = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();
  Vec3 normal = Vec3::UnitZ();
  // Self-contact: smooth cubic repulsion between quadrature points of
  // non-adjacent edges (contact.cpp). Stiffness in N/m^2.
  bool contact = false;
  double contactStiffness = 1e7;
  // Resistive-force drag coefficients per length (N s/m^2), normal and tangential.
  double dragNormal = 0, dragTangent = 0;
  // A dead load F (N) at a point rigidly attached to the distal end's frame,
  // offset by endArm (m, in that frame): a force through the helix axis for
  // the spring test, or a plain tip load with a zero arm.
  Vec3 endForce = Vec3::Zero();
  Vec3 endArm = Vec3::Zero();

  double h() const { return length / coilEdges; }
  // Clamp frame at the given twist (rad) about the exit direction.
  Quat clampFrame(double twist) const;
};

// The discretised deployed rod at one deployed length (the State).
// Frame 0 is the clamp frame at node 0 (fixed); frame k >= 1 belongs to the
// edge from node k-1 to node k.
struct Rod {
  double deployed = 0, twist = 0;
  std::vector<double> s;     // per node: arc length from the catheter tip (m)
  std::vector<int> key;      // per node: coil material index j (u = j h), or -1 - k for tube node k
  std::vector<char> fixed;   // per node
  std::vector<int> section;  // per node k >= 1: section of edge k (0 coil, 1 tube)
  std::vector<Vec3> x, v, a;  // per node: position, velocity, acceleration
  std::vector<Quat> q;        // per frame (same count as nodes)
  int nodes() const { return int(s.size()); }
};

// Rest shape in clamp coordinates (d1, d2, d3 = x, y, z; the tube straight for s < 0).
Vec3 restPosition(const RodSpec& spec, double s);
Quat restFrame(const RodSpec& spec, double s);

// The rod at deployed length l (m, at least 1.5 h) and twist (rad) in its
// stress-free shape. Throws std::invalid_argument for l outside (1.5 h, L].
Rod initialRod(const RodSpec& spec, double l, double twist);

// Moves the deployment forward to l >= rod.deployed, releasing the coil nodes
// that have left the catheter (placed on the first edge by interpolation) and
// turning the clamp to the new twist. Throws std::invalid_argument if l
// decreases or exceeds L.
void setDeployment(const RodSpec& spec, Rod& rod, double l, double twist);

// Unknowns: 3 per free node (position), 3 per free frame (rotation increment).
struct Dofs {
  std::vector<int> node, frame;  // first unknown index, or -1 if fixed
  int count = 0;
};
Dofs numberDofs(const Rod& rod);

// Elastic plus gravity energy (J) of the rod; adds its gradient to *g and its
// Hessian to *H when given (both indexed by dofs).
double elasticEnergy(const RodSpec& spec, const Rod& rod, const Dofs& dofs, Eigen::VectorXd* g, Triplets* H);

// Self-contact energy (contact.cpp), same conventions; 0 if spec.contact is off.
double contactEnergy(const RodSpec& spec, const Rod& rod, const Dofs& dofs, Eigen::VectorXd* g, Triplets* H);

// Lumped node masses (kg) of the current layout: half of each adjacent edge.
std::vector<double> nodeMasses(const RodSpec& spec, const Rod& rod);

// Applies a step: positions += p, frames turned by the Cayley rotation of p.
void applyStep(Rod& rod, const Dofs& dofs, const Eigen::VectorXd& p, double alpha);

// Tip-outward centre line: node positions (m) and their arc lengths s, coil part only (s >= 0).
std::vector<Vec3> centerline(const Rod& rod, std::vector<double>* s = nullptr);

}  // namespace refrod
