#include "bullet_sim_core/image_noise.h"

#include <algorithm>
#include <cmath>

namespace bullet_sim {

ImageNoise::ImageNoise(double mean, double stddev, std::uint64_t seed) : mean_(mean), stddev_(stddev), rng_(seed) {}

void ImageNoise::apply(std::vector<std::uint8_t>& bytes) {
  constexpr size_t kOffsets = 65536;
  if (pattern_.size() < bytes.size() + kOffsets) {
    std::normal_distribution<double> normal(0.0, 1.0);
    pattern_.resize(bytes.size() + kOffsets);
    for (std::int16_t& v : pattern_)
      v = static_cast<std::int16_t>(std::clamp(std::lround(255 * (mean_ + stddev_ * normal(rng_))), -255L, 255L));
  }
  const std::int16_t* __restrict noise = pattern_.data() + rng_() % kOffsets;
  std::uint8_t* __restrict p = bytes.data();
  for (size_t i = 0, n = bytes.size(); i < n; ++i) {  // vectorizes
    const int v = p[i] + noise[i];
    p[i] = static_cast<std::uint8_t>(v < 0 ? 0 : v > 255 ? 255 : v);
  }
}

}  // namespace bullet_sim
