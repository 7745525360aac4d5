#pragma once

#include <btBulletDynamicsCommon.h>

namespace brick_stack_sim {

/// Bullet's sequential-impulse solver with Coulomb's friction cone.
///
/// Bullet solves a contact's friction along one direction, that of the
/// sliding velocity however small, so nothing holds a brick across it: a
/// pile of planks at rest creeps, losing potential energy with no kinetic
/// energy to speak of, and never falls asleep. With Bullet's second direction
/// (SOLVER_USE_2_FRICTION_DIRECTIONS) each direction is clamped on its own
/// to [-mu N, mu N], a square that holds up to 1.41 times what Coulomb's
/// cone holds, so bricks rest in Bullet that statics finds sliding.
///
/// Here the two directions of a contact point are solved as a pair, both
/// from the same velocities. Where what they would need to stop the point's
/// slip lies inside the cone (radius mu N, N the normal impulse of this
/// iteration) the point sticks with exactly that. Where it lies outside, the
/// point slides: the change, taken with one effective mass for both rows so
/// that it opposes the slip, is added to the friction so far and the sum
/// scaled back onto the cone's edge. A brick then holds across the slip as
/// well as along it, never more than the cone allows (what the statics LP
/// assumes), and slides as Coulomb says in any direction: friction directions
/// clamped one at a time would stop a plank sliding at 45 degrees to them
/// after 71 % of its way. Turning the friction onto the slip over the
/// iterations rather than at once is what lets a point near rest stay there:
/// a tiny slip that changes direction each iteration would otherwise swing a
/// friction of mu N round with it, a sideways kick each time.
///
/// With `carry_friction`, a contact point's friction starts each step from
/// what held it at the step before, times the warm-starting factor, as its
/// normal impulse does: Bullet 3.24 starts friction from nothing every step
/// (since its friction directions may turn), and in a pile a thousand planks
/// deep 20 iterations never rebuild what holds the planks, which creep. The
/// two directions here follow the contact normal alone, so what is carried
/// over still points where it acted.
///
/// The solver mode must have SOLVER_USE_2_FRICTION_DIRECTIONS and must not
/// interleave contacts and friction nor randomise the order; else, and in a
/// world with joints (this package adds none), Bullet's own iteration runs.
class ConeFrictionSolver : public btSequentialImpulseConstraintSolver {
 public:
  explicit ConeFrictionSolver(bool carry_friction = false) : carry_friction_(carry_friction) {}

 protected:
  void convertContacts(btPersistentManifold** manifolds, int num_manifolds,
                       const btContactSolverInfo& info) override;
  btScalar solveSingleIteration(int iteration, btCollisionObject** bodies, int num_bodies,
                                btPersistentManifold** manifolds, int num_manifolds,
                                btTypedConstraint** constraints, int num_constraints,
                                const btContactSolverInfo& info, btIDebugDraw* debug) override;

 private:
  /// The friction rows of one contact point, `first` and `second`, with the
  /// normal impulse `normal` [N s]. The largest squared residual of the two
  /// rows, Bullet's measure of an iteration's change.
  btScalar solveFrictionPair(btSolverConstraint& first, btSolverConstraint& second,
                             btScalar normal);
  /// A row with its bounds already set, as Bullet solves it; its squared
  /// residual.
  btScalar solveBoundedRow(btSolverConstraint& row);
  /// Sets both friction rows of a point that pushes nothing to nothing.
  void release(btSolverConstraint& row, btSolverConstraint* partner);

  bool carry_friction_;
};

}  // namespace brick_stack_sim
