#pragma once
// Seeded random numbers that give the same sequence on every platform (the standard
// distributions are implementation-defined, so we map the raw 64-bit output ourselves).

#include <cmath>
#include <cstdint>
#include <random>

namespace ussnav {

class Rng {
 public:
  explicit Rng(uint64_t seed) : eng_(seed) {}
  uint64_t next() { return eng_(); }
  // Uniform in [0, 1).
  double uniform() { return double(eng_() >> 11) * (1.0 / 9007199254740992.0); }
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  // Uniform integer in [a, b] (inclusive).
  int uniformInt(int a, int b) { return a + int(eng_() % uint64_t(b - a + 1)); }
  bool bernoulli(double p) { return uniform() < p; }
  // Standard normal by Box-Muller.
  double normal(double mean = 0.0, double std = 1.0) {
    const double u1 = std::max(uniform(), 1e-300), u2 = uniform();
    return mean + std * std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
  }

 private:
  std::mt19937_64 eng_;
};

}  // namespace ussnav
