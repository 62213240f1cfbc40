#pragma once
// A portable seeded random source for the synthetic generators. std::mt19937_64 is specified
// bit-exactly by the standard, but the std distributions are not (libstdc++ and libc++ differ),
// so the distributions here are built from the raw 64-bit output: the same seed gives the same
// blades and paths with every standard library.

#include <cstdint>
#include <random>

namespace bladeaxis::blade {

class Random {
  public:
    explicit Random(std::uint64_t seed) : m_engine(seed) {}

    // Uniform in [0, 1) with 53 random bits.
    double uniform();
    // Uniform in [low, high).
    double uniform(double low, double high) { return low + (high - low) * uniform(); }
    // Standard normal (Box-Muller; the second value is discarded to keep the stream simple).
    double normal();
    // Uniform integer in [0, count); count must be > 0.
    int index(int count);
    // True with probability p.
    bool chance(double p) { return uniform() < p; }

  private:
    std::mt19937_64 m_engine;
};

} // namespace bladeaxis::blade
