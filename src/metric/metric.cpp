#include "src/metric/metric.h"

#include "src/model/mass.h"

#include "kernels/vec3.h"
#include "kernels/number_types.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace tmcert {

Metric Metric::from_mass(const MassDistribution& mass) {
  Metric metric;
  metric.g_ = moment_matrix(mass);
  if (!invert_positive_definite(metric.g_, metric.g_inv_))
    throw InputError("moment matrix of the mass distribution is not positive definite "
                     "(mass points must not lie in one plane)");
  return metric;
}

void Metric::require_positive_definite(const MassDistribution& mass) { tmcert::require_positive_definite(mass); }

Exact Metric::rho2(const Vec3E& x) const {
  const Exact h[4] = {x[0], x[1], x[2], Exact(1)};
  Exact s = 0;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) s += h[r] * g_inv_[4 * r + c] * h[c];
  return s;
}

Exact Metric::norm2(const Mat34E& m) const {
  Exact s = 0;
  for (int row = 0; row < 3; ++row)
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) s += m[4 * row + r] * g_[4 * r + c] * m[4 * row + c];
  return s;
}

}  // namespace tmcert
