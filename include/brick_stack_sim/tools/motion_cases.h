#pragma once
// Motions with an answer from mechanics, for the benchmark's run time
// against error in motion (the statics cases measure what stands). Each
// case is a scene, a probe that measures one quantity while it runs, and
// what mechanics says that quantity is.

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/core/scene/scene.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/world/brick_world.h"

namespace brick_stack_sim {

enum class MotionCase {
  /// A KAPLA sliding on the table from 1 m/s: stopping distance
  /// v^2 / (2 mu g) [m].
  kSlide,
  /// A cube sliding down a KAPLA leaning at 35 degrees (steeper than atan
  /// mu): acceleration g (sin a - mu cos a) [m/s^2].
  kIncline,
  /// A KAPLA standing on its end, released 2 degrees past its balance
  /// angle atan(T / L): time to tip to 45 degrees [s], from the rigid
  /// pendulum about its edge, I phi'' = m g r sin phi, integrated finely.
  kTopple,
  /// A KAPLA thrown up at (1, 0, 2) m/s: height gained after 0.3 s,
  /// v t - g t^2 / 2 [m].
  kFreeFlight,
  /// A row of 20 standing KAPLAs 0.4 L apart, the first tipped into the
  /// second: the speed of the toppling wave [m/s]. No closed form: the
  /// benchmark compares it with plain Bullet at 1/4000 s, and the test with
  /// the measured range for thin dominoes.
  kDomino,
};

/// Every case, in the benchmark's order.
const MotionCase kMotionCases[] = {MotionCase::kSlide, MotionCase::kIncline, MotionCase::kTopple,
                                   MotionCase::kFreeFlight, MotionCase::kDomino};

/// "slide", "incline", "topple", "free_flight", "domino".
std::string motionCaseName(MotionCase motion);

/// The scene of `motion` with the package's `types` (a kapla and a cube are
/// needed) on the default table.
Status motionScene(MotionCase motion, const BrickTypeLibrary& types, Scene* scene);

/// What mechanics says the measured quantity is, with the types' friction
/// (combined as the world combines it) and `gravity` [m/s^2]; NaN for the
/// domino wave.
double motionExpected(MotionCase motion, const BrickTypeLibrary& types, const TableOptions& table,
                      double gravity);

/// Measures the quantity of a case from the world after each step.
class MotionProbe {
 public:
  explicit MotionProbe(MotionCase motion) : motion_(motion) {}
  void observe(const BrickWorld& world);
  /// NaN when the motion did not happen within the run (a domino row that
  /// stopped, a brick that never tipped).
  double measured() const;

 private:
  MotionCase motion_;
  double previous_tilt_ = std::numeric_limits<double>::quiet_NaN();  ///< [rad]
  double early_ = std::numeric_limits<double>::quiet_NaN();
  double late_ = std::numeric_limits<double>::quiet_NaN();
  double value_ = std::numeric_limits<double>::quiet_NaN();
  int next_domino_ = 0;
  std::vector<double> tipped_at_;  ///< Per domino: when it passed the tilt that counts [s].
};

}  // namespace brick_stack_sim
