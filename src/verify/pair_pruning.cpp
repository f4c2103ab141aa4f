// Check steps that are not templates: carry_shortfall (pair_pruning.h).
#include "src/verify/pair_pruning.h"

#include <algorithm>
#include <cmath>

namespace tmcert::detail {

std::uint8_t carry_shortfall(const SlabTest& slab) {
  const double ratio = slab.fat / slab.gap;
  if (!(ratio > 1)) return 1;
  return static_cast<std::uint8_t>(std::min(255.0, 1 + std::floor(2 * std::log2(ratio))));
}

}  // namespace tmcert::detail
