#pragma once
// Deterministic pseudo-random numbers for the measurement noise. The standard
// library's distributions are implementation-defined (libstdc++ and libc++
// give different std::normal_distribution sequences), so the committed files
// would depend on the toolchain; these are specified here bit for bit.
#include <cstdint>

namespace refrod {

// splitmix64 (Steele, Lea, Flood 2014): a tiny, well-mixed 64-bit generator.
class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(seed) {}
  uint64_t next();
  // Uniform in (0, 1): 53 random bits, never 0 (Box-Muller takes its log).
  double uniform();
  // Standard normal by the Box-Muller transform (one value per call; the
  // second of each pair is discarded to keep the sequence simple).
  double normal();

 private:
  uint64_t state_;
};

}  // namespace refrod
