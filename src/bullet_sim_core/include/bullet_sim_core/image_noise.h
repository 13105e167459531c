#pragma once
#include <cstdint>
#include <random>
#include <vector>

namespace bullet_sim {

// Gazebo's gaussian image noise on 8-bit values: value + round(255 * (mean + stddev * N(0, 1))),
// clamped, independently per byte (so per channel). Drawing 2.4 million normal samples per
// 800x800 frame would cost more than rendering it, so one pattern of (bytes + 65536) samples is
// drawn once from `seed`, and each frame adds it from a fresh random offset: every frame's noise
// is i.i.d. with the right mean and spread, and the same seed gives the same frames.
class ImageNoise {
 public:
  ImageNoise(double mean, double stddev, std::uint64_t seed);
  void apply(std::vector<std::uint8_t>& bytes);

 private:
  double mean_, stddev_;
  std::mt19937_64 rng_;
  std::vector<std::int16_t> pattern_;
};

}  // namespace bullet_sim
