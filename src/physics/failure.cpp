#include "physics/failure.h"

namespace coilsim {

std::string Failure::where() const {
  if (rod.empty()) return subject;
  std::string w = "rod '" + rod + "'";
  if (node >= 0) w += " node " + std::to_string(node);
  else if (beam >= 0) w += " beam " + std::to_string(beam);
  return w;
}

std::string Failure::message() const {
  const std::string w = where();
  return w.empty() ? text : w + ": " + text;
}

std::string describe(const Failure& f) {
  switch (f.kind) {
    case FailureKind::BadDefinition: return f.message();
    case FailureKind::BlowUp:
    case FailureKind::SolverFailure:
    case FailureKind::MissedContact:
      return std::isnan(f.time) ? "step refused: " + f.message()
                                : "step refused at t = " + std::to_string(f.time) + " s: " + f.message();
    case FailureKind::NotConverged: return "static solve did not converge: " + f.message();
    case FailureKind::DeviceRefusal: return "refused: " + f.message();
  }
  return f.message();
}

Failure badRod(const std::string& rod, std::string text) {
  Failure f;
  f.rod = rod;
  f.text = std::move(text);
  return f;
}

Failure badDefinition(std::string subject, std::string text) {
  Failure f;
  f.subject = std::move(subject);
  f.text = std::move(text);
  return f;
}

PhysicsError::PhysicsError(Failure failure) : std::invalid_argument(failure.message()), failure_(std::move(failure)) {}

}  // namespace coilsim
