#pragma once

#include <algorithm>
#include <cmath>

#include <LinearMath/btMatrix3x3.h>

namespace brick_stack_sim {

/// How far a point at unit distance from a body's origin can have been
/// carried by turning its basis from `then` to `now` [m per m]: the
/// Frobenius norm |now - then|_F = sqrt(2 (3 - tr(then^T now))), which bounds
/// the spectral norm from above. A point at distance r moved at most r times
/// this.
inline btScalar turnBound(const btMatrix3x3& now, const btMatrix3x3& then) {
  btScalar trace = 0;
  for (int i = 0; i < 3; ++i) trace += now[i].dot(then[i]);
  return std::sqrt(std::max(btScalar(0), 2 * (3 - trace)));
}

}  // namespace brick_stack_sim
