#pragma once
// Physics bugs found by these tests and not fixed yet. A test that cannot
// pass until a bug is fixed starts with SKIP_IF_OPEN(bug): it is reported as
// skipped with the summary below instead of failing CI for everyone. Whoever
// fixes a bug sets its `open` to false, and the tests that guard it run again.
#include <gtest/gtest.h>

namespace coilsim::test {

struct KnownBug {
  bool open;
  const char* summary;
};

// evalBeam takes the element frame from node a (R_e = R_a Q) and node a's
// moment from the linear stiffness, whose moment arm is the rest chord L0 e_x.
// Once the chord turns away from node a's frame (u_y, u_z != 0 in that frame)
// the element's nodal forces no longer balance moments: the resultant of the
// internal moments, sum(x_i x f_i + m_i), is of order u_y N per element. In
// large deflection this error is first order in the element length: the
// elastica and the 45-degree bend converge at order 1, not 2 (errors 2.6e-3
// rad at n = 32 for PL^2/EI = 2, 60 times those of a chord-aligned frame).
inline constexpr KnownBug kElementMomentImbalance{
    false,
    "known bug: co-rotational element frame attached to node a gives internal moments that do not balance "
    "(beam.cpp evalBeam), so large-deflection results converge at first order; see tests/support/known_bugs.h"};

// solveStatic iterates with the material tangent only (no geometric
// stiffness). For an end-loaded cantilever the iteration diverges from
// PL^2/EI ~ 2.95 on, whatever the mesh and however small the increment (ten
// bisections fail), although the equilibrium exists: damped dynamics reaches
// it. PL^2/EI = 5 and 10 and the 45-degree bend at P = 450, 600 fail.
inline constexpr KnownBug kStaticTangentLacksGeometricStiffness{
    false,
    "known bug: solveStatic uses the tangent without geometric stiffness and diverges beyond PL^2/EI ~ 3 "
    "(statics.cpp); see tests/support/known_bugs.h"};

// resample() in rest_shape.cpp shifts the resampled points by out.front()
// while overwriting it: the first point becomes the origin, the others keep
// their coordinates. Any polyline that does not start at the origin, and
// every bird-cage (whose generator is centred on the sphere), gets a first
// beam from the sphere centre to the second sample (4 mm instead of 0.5 mm).
inline constexpr KnownBug kPolylineResampleShift{
    false,
    "known bug: makePolyline's resample() subtracts out.front() after overwriting it, so polylines not "
    "starting at the origin (all bird-cages) get a wrong first node (rest_shape.cpp); see tests/support/known_bugs.h"};

// makePolyline takes one-sided (chord) tangents at the two end nodes: the end
// frames are turned by half the end beam's turning angle from the curve's
// tangent, so the first and last beams store half the rest curvature, and a
// coil clamped at node 0 leaves the catheter kappa ds / 2 off its direction
// (4 degrees for 7 mm loops and 0.5 mm beams).
inline constexpr KnownBug kPolylineEndTangents{
    false,
    "known bug: makePolyline uses chord tangents at the end nodes, halving the end beams' rest curvature "
    "(rest_shape.cpp nodeTangents); see tests/support/known_bugs.h"};

// step() undoes a refused step's target motion with advanceTargets(-dt)
// instead of restoring the saved targets: p + v dt - v dt and
// exp(-w dt) exp(w dt) q are not bit-exact, so a refused step shifts moving
// constraint targets by round-off and the run afterwards differs from one
// without the refused step (integrator.h promises the State is restored).
inline constexpr KnownBug kRefusedStepMovesTargets{
    false,
    "known bug: a refused step moves constraint targets back by -dt instead of restoring them, so the State "
    "is not restored bit for bit (dynamics.cpp step); see tests/support/known_bugs.h"};

// The drag effect adds its force -D v to RodForces::force and D to
// RodForces::damping (the derivative, for the implicit matrix), as effect.h
// asks; stepRod then subtracts effectD * v from the right-hand side again,
// treating it like Rayleigh damping, which is not in the force. Drag acts
// twice: a falling rod reaches half the Gray-Hancock terminal velocity.
inline constexpr KnownBug kEffectDampingCountedTwice{
    false,
    "known bug: stepRod subtracts effectD * v from the right-hand side although the effect's force already "
    "holds it, so drag acts twice (dynamics.cpp); see tests/support/known_bugs.h"};

// evalBeam (after the chord-frame fix) turns node a's frame onto the chord,
// so the element's roll about its axis is node a's. For a curved rod under
// bending and torsion the roll of the two nodes differs by O(h) per element and
// the asymmetric choice leaves an error of that order: the 45-degree bend
// converges at order 1 (tip at P = 600, n = 8, 16, 32, 64: x 47.162, 47.030,
// 46.963, 46.930; y 15.052, 15.277, 15.411, 15.484). Taking the mean of the
// two nodes' frames, R_m = R_a Q exp(log((R_a Q)^T R_b P^T) / 2), before
// turning it onto the chord gives order 2 and converges to (46.897, 15.560,
// 53.606), an independent geometrically exact result being (46.90, 15.56, 53.60).
inline constexpr KnownBug kElementRollFromNodeA{
    false,
    "known bug: the element frame takes its roll from node a only, so curved rods under torsion converge at "
    "first order (beam.cpp evalBeam); see tests/support/known_bugs.h"};

// Fixed: a soft wound coil (sidewall-7mm.json: B = 0.003 N mm2) pushed
// straight into the 7 mm phantom had its step refused (axial strain 0.5-1.3,
// Newton diverging over its 3 iterations) after 19-22 mm. Instrumented, the
// refused steps started with wall contacts 0.18-0.41 mm "deep" carrying
// 9-49 N at segments that were clear of the wall (nearest feature 31-45 um
// away, or 0.19 mm inside the sac sphere), on the neck rim where the sac
// meets the vessel: the side of an edge or vertex was
// taken from one of its triangles' normals (wrong at that sharp ridge), and
// the planes of concave neighbour faces were used past those faces' edges,
// where they cut the free space of a saddle (docs/contact.md). The full
// 60 mm of push-sidewall-7mm.json now runs with no refused step.
inline constexpr KnownBug kSoftCoilHeadOnWallContact{
    false,
    "known bug: a soft wound coil pushed head-on into a sac dome at 10 mm/s is refused (axial strain) by the "
    "current wall-contact law, which is validated on the paper's stiff wire only; see tests/support/known_bugs.h"};

// Not a bug (closed): the soft coil's loops cross the neck plane in the
// 30 mm scene tests (tests/app/scenes_test.cpp) of the default and
// bifurcation scenes: lowest node 0.16-0.35 mm below it, no wall
// penetration anywhere (nearest node centre 0.160 mm inside the wall,
// r = 0.152 mm), 2.3 mm of coil beyond the plane by planning's measure. The
// test asked for no node below the plane, which the physics does not
// promise: the 7 mm loops are larger than the 6.7 mm sphere their centre
// line can reach in the 7 mm sac, so they press outward everywhere and bulge
// where a loop crosses the open neck. Such a loop can sag at most as deep as
// an arc of the largest curvature the wall imposes spanning the opening,
// 0.49 mm (sidewall, 3.5 mm neck) and 0.66 mm (bifurcation); the measured
// depths are within that, and which loop crosses the neck (hence the
// round-off sensitivity: +0.61 to -0.16 mm across arithmetic changes) is
// decided by a chaotic deployment. The test now asserts that bound, and that
// planning's measure agrees with the nodes.
inline constexpr KnownBug kLoopBelowNeckPlane{
    false,
    "not a bug: an oversized loop bulges through the open neck, within the analytic sag bound; see "
    "tests/support/known_bugs.h"};

// Fixed: coil-coil contact (rod_contact) yielded when a pushed coil was
// aimed at a detached one (tests/physics/contact_rod_test.cpp): closest
// centre lines 187 um against r1 + r2 = 300 um, whatever the stiffness. The
// second coil's tip rested against the first (gap 0-15 um, not closing) and
// whipped from rest to 0.13-0.34 m/s within one step, so the pair was not in
// that step's implicit solve (or not even found) and went 110 um in. A step
// that carries a pair deeper than 5 % of r1 + r2 outside its contacts is now
// taken again in substeps (Effect::endStep): 285 um at 50-2000 N/mm.
inline constexpr KnownBug kCoilCoilContactYields{
    false,
    "known bug: a coil pushed at a detached coil passes 40-70 % of a wire diameter into it (rod_contact penalty "
    "yields); see tests/support/known_bugs.h"};

// Fixed: solveStatic did not converge once a self_contact pair pressed: a
// right-handed 8 mm helix (pitch 0.3 mm, wire 0.2 mm, 80 mm) leaving the
// catheter with its loops horizontal, winding upwards, so that gravity lays
// each loop on the one below, was refused at the first touch (26 mm
// pushed). Four causes, each measured on that bench: (1) the pair's
// stiffness sat on the two segments' diagonal blocks only, so a Newton step
// moved two loops in contact as if each leant on a fixed wall and a stack
// could not sag together (now the exact pair Jacobian, -d f_i / d x_j =
// k w_i w_j n n^T, in a sparse LU); (2) detection ran once before the solve,
// so each loop pushed against where the other had been (now before every
// iteration); (3) a push squeezed its 2 mm into the first beam, a 117 N
// imbalance whose Newton steps had to be held back wherever loops could pass
// through each other (now the coil slides along its shape:
// slideDeployment); (4) the penalty's kink made Newton cycle between a loop
// pressing and lifted off (2- and 3-cycles over 60 iterations; now smoothed
// over 0.2 um for statics). The bench now reaches 75 mm in 0.2 s, 412 Newton
// iterations.
inline constexpr KnownBug kStaticSelfContactDiverges{
    false,
    "known bug: solveStatic does not converge once loops of one coil press on each other (self_contact); "
    "see tests/support/known_bugs.h"};

// Fixed: the validation workbench could not use dynamic stages in which
// loops land on one another. On tests/data/reference/self-contact-dynamic
// (pitch = wire diameter, a 60 mm/s push in water) no candidate was
// significant: refitted with self_contact, the static stages fell to 0.0033
// / 0.0021 and the dynamic one rose to 0.0111 (true model 0.0025 / 0.0017 /
// 0.0016). At the truth (true E, water's buoyancy and drag) coilsim's
// dynamic stage reached 0.0322: (1) the effect's default Coulomb friction
// (0.15 / 0.1) acted in the dynamic stage while the static ones are solved
// frictionless (frictionless: 0.0052); (2) the 50 N/mm penalty at the 1 ms
// step gave another answer than shorter steps (0.0031 at 0.5 ms, 0.0022 at
// 0.25 ms), where 1-5 N/mm at 1 ms gives 0.0021; (3) the candidate's refit
// started from E at the band's edge (10.8 GPa), where the regularised
// baseline had held the 27.9 GPa the free fit absorbed, and stayed there;
// (4) sigma came from a 1e-3 finite difference across contacts switching
// (E +- 0.0015 GPa). Now the workbench holds self_contact frictionless at
// 5 N/mm (Diagnosable::held), refits start implausible values from their
// nominal, and the Jacobian's step grows until it is a derivative: it is
// found first (80 %), every stage within 1.5x of the true model.
inline constexpr KnownBug kRefitStallsWithContacts{
    false,
    "known bug: dynamic stages in which loops land on one another are chaotic and the validation fit cannot "
    "follow them; see tests/support/known_bugs.h"};

// Fixed: wall penetration during a deployment, not only at its end. The
// scene runs record the deepest wall penetration of the wire at every
// detection of a step, its substeps' too (result.json
// stats.max_wall_penetration_*, a warning past 10 % of r). Pushing 30 mm at
// 10 mm/s the default, sidewall and bifurcation scenes reached 13.2, 17.3
// and 8.0 um (9, 11, 5 % of r = 0.152 mm; the record then missed the first
// detection of substepped steps and read 9.9 um for the default scene).
// Instrumented (forces on the node by source, the Newton iterates one by
// one, the mesh's own signed distance), none of it was the penalty's
// balance or the axial push: (1) a node at rest against the wall, neither
// touching nor closing at the step's start, that the first Newton iterate
// carried in switched the contact on and off between iterates (in, pushed
// out to the surface, no longer touching so left out, in again) and the
// third iterate ended 17 um in with 3.8 N unbalanced; (2) a node's planes
// were tangent at the segment's nearest point, on a curved wall 20-70 um
// off at the far node (the free tip has no other segment) or tilted 38 deg
// from the wall under a node sliding along them (17-44 um in by the mesh
// while the planes said clear); (3) a node plane's side was decided without
// a face sharing the nearest edge, lost to round-off, and pushed a node into
// the wall with 16 N. A node carried in now stays in the step's solve, each
// node gets its own nearest feature's plane where the segment's planes do
// not agree with it, the end-of-step check judges each node by the planes
// that pressed it from the start, and ties are kept: 0.5, 2.5 and 0.4 um
// (0.3, 1.6, 0.3 % of r), and at most 2.5 um over push speeds of 5-15 mm/s
// and 3-5 Newton iterations (docs/contact.md).
inline constexpr KnownBug kTransientWallPenetration{
    false,
    "known bug: the soft coil's distal tip rests 17 um (11 % of r) in the wall for a few steps of the sidewall "
    "scene's deployment; see tests/support/known_bugs.h"};

#define SKIP_IF_OPEN(bug) \
  if ((bug).open) GTEST_SKIP() << (bug).summary

}  // namespace coilsim::test
