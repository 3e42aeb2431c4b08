#pragma once
// The line a refused device command shows (physics::describe), "" when the
// command was accepted, so that a test that expects one or the other prints why.
#include <optional>
#include <string>

#include "physics/failure.h"

namespace coilsim::test {

inline std::string refusal(const std::optional<Failure>& f) { return f ? describe(*f) : std::string(); }

}  // namespace coilsim::test
