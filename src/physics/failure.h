#pragma once
// One type for every way the physics core says no: a definition it will not
// build, a step it refuses, a static solve that does not converge, a device
// command the device does not allow. Each names where (the rod and its node
// or beam, or the effect, obstacle, mesh or deployment), the quantity with
// its value and limit where there are numbers, and for a running failure the
// simulated time. Front ends print message() (or describe()) and choose an
// exit code by kind; none parses the text.
#include <cmath>
#include <stdexcept>
#include <string>

namespace coilsim {

enum class FailureKind {
  BadDefinition,  // compileModel (and the definitions it checks) refused its input: nothing was built
  BlowUp,         // a step's result was non-finite, too fast or too strained (checkHealth)
  SolverFailure,  // a step's implicit matrix could not be factorised
  MissedContact,  // a step outran its contact detection (Effect::endStep); smaller substeps follow
  NotConverged,   // a static solve did not reach equilibrium
  DeviceRefusal,  // a command the device does not allow (command(), a detach)
};

struct Failure {
  FailureKind kind = FailureKind::BadDefinition;
  std::string rod;           // the rod's name when a rod is at fault
  int node = -1, beam = -1;  // of that rod, when one is at fault
  std::string subject;       // else what is, as messages name it ("effect 'drag'", "deployment of 'coil'"); may be empty
  std::string quantity;      // what was measured or checked ("speed", "axial strain", "Young's modulus"); may be empty
  double value = NAN, limit = NAN;  // the quantity's value and the bound it broke, SI (NaN: none)
  double time = NAN;         // s of simulated time when a running failure happened (NaN: not running)
  std::string text;          // what is wrong, after where: "speed 60 m/s exceeds 50 m/s (numerical blow-up)"

  // "rod 'coil' node 3", "rod 'coil' beam 2", "rod 'coil'", the subject, or "".
  std::string where() const;
  // where + ": " + text (the text alone when there is no where).
  std::string message() const;
  bool running() const { return kind != FailureKind::BadDefinition; }
};

// The one line a front end shows for a failure: a refused step says when
// ("step refused at t = 0.500000 s: " + message()), a static solve that it did
// not converge, a device refusal that it was refused; a bad definition is its
// message.
std::string describe(const Failure& f);

// Failure of a definition (kind BadDefinition) about a rod, or about a subject.
Failure badRod(const std::string& rod, std::string text);
Failure badDefinition(std::string subject, std::string text);

// What compileModel and the definitions it checks throw: a std::invalid_argument
// (so callers that catch that still do) whose what() is the failure's message().
class PhysicsError : public std::invalid_argument {
 public:
  explicit PhysicsError(Failure failure);
  const Failure& failure() const { return failure_; }

 private:
  Failure failure_;
};

}  // namespace coilsim
