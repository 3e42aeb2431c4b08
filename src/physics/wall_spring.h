#pragma once
// One wall node's normal spring as a coupled step's last Newton iterate
// built it (response.cpp), kept for the force the step's solve applied
// (reportSolvedWallForces, physics/pair_contact_set.h).
#include "physics/math.h"

namespace coilsim {

struct WallSpring {
  int node = 0;
  int contact = 0, end = 0;            // its line contact in RodContacts::wall, and which of its nodes
  Vec3 normal = Vec3::UnitZ();         // pushes the node
  Vec3 anchor = Vec3::Zero();          // a point of the wall's plane
  Vec3 otherVelocity = Vec3::Zero();   // the wall's velocity there
  double radius = 0;                   // clearance the node keeps from the plane, m
  // At the iterate the rows were built at: the node's penetration (m), its
  // approach speed along -normal (m/s) and the normal force applied there
  // (N, damping included); and the stiffness and damping the matrix holds
  // for it (N/m, N s/m).
  double penetration = 0, approach = 0, force = 0;
  double stiffness = 0, damping = 0;
};

}  // namespace coilsim
