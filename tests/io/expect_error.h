#pragma once
// Helpers for tests of user-facing errors: catch the InputError and look for
// the parts a message must have (file, JSON path, expectation).
#include <gtest/gtest.h>

#include <string>

#include "io/json_reader.h"

// Passes when `text` contains `part`; prints the whole text otherwise.
#define EXPECT_CONTAINS(text, part)                                              \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "  in message: " \
                                                             << std::string(text)

namespace coilsim::io {

// The message of the InputError that `f` throws (fails the test if none).
template <class F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return {};
}

}  // namespace coilsim::io
