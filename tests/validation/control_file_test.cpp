// The workbench on the shared control file, made by an independent discrete
// Cosserat rod simulator (../shared/data/measurements/README.md): a correct
// model with E fitted must reach a stage error below 5 % at every stage,
// and diagnose must find no significant effect (there is none in the file).
#include <gtest/gtest.h>

#include <fstream>

#include "io/measurement.h"
#include "validation/diagnose.h"

namespace coilsim::validation {
namespace {

// Located from the source root (a CMake define), not the working directory.
const std::string kControl = COILSIM_SOURCE_DIR "/../shared/data/measurements/control-helix-a.json";

TEST(ControlFile, BaseModelWithEFittedIsWithinFivePercent) {
  if (!std::ifstream(kControl)) GTEST_SKIP() << kControl << " is absent (../shared/data not present): nothing checked";
  const Measurement m = io::readMeasurement(kControl);
  StageSimulator sim(m);
  Comparison cmp(m);
  FitOptions fo;
  fo.params = {"young_modulus_gpa"};
  const FitResult f = identify(sim, cmp, ModelParams::nominal(m), fo);
  ASSERT_TRUE(f.ok) << f.message;
  const auto stages = cmp.compare(sim.run(f.params, false));
  ASSERT_EQ(stages.size(), 3u);
  for (size_t k = 0; k < stages.size(); ++k) {
    ASSERT_TRUE(stages[k].ok()) << stages[k].message();
    EXPECT_LT(stages[k].metrics.stageError, 0.05) << m.stages[k].name;
    std::printf("%s: stage error %.4f\n", m.stages[k].name.c_str(), stages[k].metrics.stageError);
  }
  EXPECT_GT(f.fitted[0].sigma, 0.0);
  std::printf("E = %.4g +- %.2g GPa (nominal %.4g)\n", f.fitted[0].value / 1e9, f.fitted[0].sigma / 1e9, m.coil.youngModulus / 1e9);
}

TEST(ControlFile, DiagnoseFindsNoSignificantEffect) {
  if (!std::ifstream(kControl)) GTEST_SKIP() << kControl << " is absent (../shared/data not present): nothing checked";
  const Measurement m = io::readMeasurement(kControl);
  StageSimulator sim(m);
  Comparison cmp(m);
  const Diagnosis d = diagnose(sim, cmp, ModelParams::nominal(m), {});
  ASSERT_TRUE(d.ok) << d.message;
  EXPECT_EQ(d.candidates.size(), 5u);
  for (const CandidateResult& c : d.candidates)
    EXPECT_FALSE(c.significant) << c.effect << " explains " << c.explainedFraction << ": " << d.verdict;
}

}  // namespace
}  // namespace coilsim::validation
