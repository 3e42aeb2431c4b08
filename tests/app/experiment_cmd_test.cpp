// `coilsim experiment`, run as a user would: a tiny sweep prints its table;
// bad input exits 2 naming what was wrong.
#include <gtest/gtest.h>

#include "app/run_binary.h"

namespace {

using namespace apptest;

TEST(ExperimentCommand, PrintsOneRowPerRun) {
  const fs::path dir = scratch("experiment");
  const Exec r = coilsim({"experiment", "injection", "--friction", "0.1,0.3", "--packing", "0.005"}, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_CONTAINS(r.out, "| D/d | mu | turns per D |");
  EXPECT_CONTAINS(r.out, "| 20 | 0.10 | 0.0 |");
  EXPECT_CONTAINS(r.out, "| 20 | 0.30 | 0.0 |");
}

TEST(ExperimentCommand, BadInputExitsTwoWithTheReason) {
  const fs::path dir = scratch("experiment_bad");
  Exec r = coilsim({"experiment", "crumpling"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "knows one experiment, injection");
  r = coilsim({"experiment", "injection", "--friction", "0,much"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "--friction needs numbers");
  r = coilsim({"experiment", "injection", "--cavity-ratio", "3"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "cavity ratio D/d must be in [6, 200]");
  r = coilsim({"experiment", "injection", "--packing", "0.9"}, dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_CONTAINS(r.err, "--packing");
}

}  // namespace
