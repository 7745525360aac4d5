#include "bullet/cone_friction_solver.h"

#include <algorithm>
#include <cmath>

namespace brick_stack_sim {

namespace {

/// The change of a row's impulse that would cancel its velocity error,
/// unbounded [N s]: the row's right-hand side less what the velocity
/// changes of this step already do along it.
btScalar unboundedChange(const btSolverConstraint& row, btSolverBody& a, btSolverBody& b) {
  const btScalar along_a = row.m_contactNormal1.dot(a.internalGetDeltaLinearVelocity()) +
                           row.m_relpos1CrossNormal.dot(a.internalGetDeltaAngularVelocity());
  const btScalar along_b = row.m_contactNormal2.dot(b.internalGetDeltaLinearVelocity()) +
                           row.m_relpos2CrossNormal.dot(b.internalGetDeltaAngularVelocity());
  return row.m_rhs - row.m_appliedImpulse * row.m_cfm - (along_a + along_b) * row.m_jacDiagABInv;
}

/// How far out a pair of friction impulses [N s] lies on the cone's
/// section with half-axes `limit_first` and `limit_second` [N s], squared:
/// at most 1 inside.
btScalar reach(btScalar first, btScalar second, btScalar limit_first, btScalar limit_second) {
  const btScalar along_first = first / limit_first, along_second = second / limit_second;
  return along_first * along_first + along_second * along_second;
}

/// Scales a pair outside the section back onto its edge.
void pullOntoSection(btScalar* first, btScalar* second, btScalar limit_first,
                     btScalar limit_second) {
  const btScalar out = std::sqrt(reach(*first, *second, limit_first, limit_second));
  *first /= out;
  *second /= out;
}

/// Sets a row's impulse to `total` and applies the change to both bodies;
/// the change as a velocity, Bullet's residual of a row.
btScalar applyTotal(btSolverConstraint& row, btSolverBody& a, btSolverBody& b, btScalar total) {
  const btScalar change = total - row.m_appliedImpulse;
  row.m_appliedImpulse = total;
  a.internalApplyImpulse(row.m_contactNormal1 * a.internalGetInvMass(), row.m_angularComponentA,
                         change);
  b.internalApplyImpulse(row.m_contactNormal2 * b.internalGetInvMass(), row.m_angularComponentB,
                         change);
  return change / row.m_jacDiagABInv;
}

}  // namespace

btScalar ConeFrictionSolver::solveBoundedRow(btSolverConstraint& row) {
  btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
  btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
  const btScalar total = std::clamp(row.m_appliedImpulse + unboundedChange(row, a, b),
                                    row.m_lowerLimit, row.m_upperLimit);
  const btScalar residual = applyTotal(row, a, b, total);
  return residual * residual;
}

btScalar ConeFrictionSolver::solveFrictionPair(btSolverConstraint& first,
                                               btSolverConstraint& second, btScalar normal) {
  btSolverBody& a = m_tmpSolverBodyPool[first.m_solverBodyIdA];
  btSolverBody& b = m_tmpSolverBodyPool[first.m_solverBodyIdB];
  const btScalar limit_first = first.m_friction * normal;
  const btScalar limit_second = second.m_friction * normal;
  first.m_lowerLimit = -limit_first;
  first.m_upperLimit = limit_first;
  second.m_lowerLimit = -limit_second;
  second.m_upperLimit = limit_second;
  if (limit_first <= 0 || limit_second <= 0)  // no cone to project on: each row alone
    return std::max(solveBoundedRow(first), solveBoundedRow(second));

  // What each row would need to stop the point's slip, both from the same
  // velocities. Inside the cone the point sticks with exactly that.
  const btScalar change_first = unboundedChange(first, a, b);
  const btScalar change_second = unboundedChange(second, a, b);
  btScalar total_first = first.m_appliedImpulse + change_first;
  btScalar total_second = second.m_appliedImpulse + change_second;
  if (reach(total_first, total_second, limit_first, limit_second) > 1) {
    // It slides. Each row's own effective mass would tilt the change away
    // from the slip (a long plank turns more easily about one axis than the
    // other, and bends its path); with the smaller of the two the change
    // opposes the slip. Added to this step's friction and scaled back onto
    // the cone's edge, it turns the friction towards the slip over the
    // iterations instead of swinging it there in one: a point near rest
    // whose tiny slip changes direction each iteration would otherwise be
    // kicked sideways at mu N each time, and never come to rest.
    const btScalar mass = std::min(first.m_jacDiagABInv, second.m_jacDiagABInv);
    total_first = first.m_appliedImpulse + change_first * (mass / first.m_jacDiagABInv);
    total_second = second.m_appliedImpulse + change_second * (mass / second.m_jacDiagABInv);
    if (reach(total_first, total_second, limit_first, limit_second) > 1)
      pullOntoSection(&total_first, &total_second, limit_first, limit_second);
  }
  const btScalar residual_first = applyTotal(first, a, b, total_first);
  const btScalar residual_second = applyTotal(second, a, b, total_second);
  return std::max(residual_first * residual_first, residual_second * residual_second);
}

void ConeFrictionSolver::convertContacts(btPersistentManifold** manifolds, int num_manifolds,
                                         const btContactSolverInfo& info) {
  btSequentialImpulseConstraintSolver::convertContacts(manifolds, num_manifolds, info);
  if (!carry_friction_ || !(info.m_solverMode & SOLVER_USE_WARMSTARTING) ||
      !(info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS))
    return;
  for (int i = 0; i < m_tmpSolverContactConstraintPool.size(); ++i) {
    const btSolverConstraint& contact = m_tmpSolverContactConstraintPool[i];
    const auto* point = static_cast<const btManifoldPoint*>(contact.m_originalContactPoint);
    if (!point) continue;
    // Bullet wrote both directions' impulses back into the point at the end
    // of the step before.
    const btScalar carried[2] = {point->m_appliedImpulseLateral1 * info.m_warmstartingFactor,
                                 point->m_appliedImpulseLateral2 * info.m_warmstartingFactor};
    for (int k = 0; k < 2; ++k) {
      btSolverConstraint& row =
          m_tmpSolverContactFrictionConstraintPool[contact.m_frictionIndex + k];
      applyTotal(row, m_tmpSolverBodyPool[row.m_solverBodyIdA],
                 m_tmpSolverBodyPool[row.m_solverBodyIdB], carried[k]);
    }
  }
}

void ConeFrictionSolver::release(btSolverConstraint& row, btSolverConstraint* partner) {
  btSolverBody& a = m_tmpSolverBodyPool[row.m_solverBodyIdA];
  btSolverBody& b = m_tmpSolverBodyPool[row.m_solverBodyIdB];
  if (row.m_appliedImpulse != 0) applyTotal(row, a, b, 0);
  if (partner && partner->m_appliedImpulse != 0) applyTotal(*partner, a, b, 0);
}

btScalar ConeFrictionSolver::solveSingleIteration(
    int iteration, btCollisionObject** bodies, int num_bodies, btPersistentManifold** manifolds,
    int num_manifolds, btTypedConstraint** constraints, int num_constraints,
    const btContactSolverInfo& info, btIDebugDraw* debug) {
  const int mode = info.m_solverMode;
  const bool cone_applies = (mode & SOLVER_USE_2_FRICTION_DIRECTIONS) &&
                            !(mode & SOLVER_INTERLEAVE_CONTACT_AND_FRICTION_CONSTRAINTS) &&
                            !(mode & SOLVER_RANDMIZE_ORDER) && num_constraints == 0 &&
                            m_tmpSolverNonContactConstraintPool.size() == 0;
  if (!cone_applies)
    return btSequentialImpulseConstraintSolver::solveSingleIteration(
        iteration, bodies, num_bodies, manifolds, num_manifolds, constraints, num_constraints, info,
        debug);
  btScalar residual = 0;
  if (iteration >= info.m_numIterations) return residual;

  // The normals first, then the friction they bound, in Bullet's order.
  for (int i = 0; i < m_tmpSolverContactConstraintPool.size(); ++i) {
    const btSolverConstraint& row = m_tmpSolverContactConstraintPool[m_orderTmpConstraintPool[i]];
    const btScalar change = resolveSingleConstraintRowLowerLimit(
        m_tmpSolverBodyPool[row.m_solverBodyIdA], m_tmpSolverBodyPool[row.m_solverBodyIdB], row);
    residual = std::max(residual, change * change);
  }
  // Bullet adds a contact point's two friction rows one after the other,
  // both naming the point's normal row.
  const int num_friction = m_tmpSolverContactFrictionConstraintPool.size();
  for (int i = 0; i < num_friction; ++i) {
    btSolverConstraint& row =
        m_tmpSolverContactFrictionConstraintPool[m_orderFrictionConstraintPool[i]];
    const btScalar normal = m_tmpSolverContactConstraintPool[row.m_frictionIndex].m_appliedImpulse;
    btSolverConstraint* partner =
        i + 1 < num_friction
            ? &m_tmpSolverContactFrictionConstraintPool[m_orderFrictionConstraintPool[i + 1]]
            : nullptr;
    if (partner && partner->m_frictionIndex != row.m_frictionIndex) partner = nullptr;
    if (partner) ++i;
    if (normal <= 0) {  // a point that pushes nothing holds nothing
      // Not even what was carried over from the step before; without
      // carrying, such a point's rows have never been solved this step.
      if (carry_friction_) release(row, partner);
      continue;
    }
    if (partner) {
      residual = std::max(residual, solveFrictionPair(row, *partner, normal));
    } else {
      row.m_lowerLimit = -row.m_friction * normal;
      row.m_upperLimit = row.m_friction * normal;
      residual = std::max(residual, solveBoundedRow(row));
    }
  }
  // Rolling and spinning friction as Bullet bounds them: by the normal
  // impulse times the coefficient, and never beyond the coefficient itself.
  for (int i = 0; i < m_tmpSolverContactRollingFrictionConstraintPool.size(); ++i) {
    btSolverConstraint& row = m_tmpSolverContactRollingFrictionConstraintPool[i];
    const btScalar normal = m_tmpSolverContactConstraintPool[row.m_frictionIndex].m_appliedImpulse;
    if (normal <= 0) continue;
    const btScalar bound = std::min(row.m_friction * normal, row.m_friction);
    row.m_lowerLimit = -bound;
    row.m_upperLimit = bound;
    residual = std::max(residual, solveBoundedRow(row));
  }
  return residual;
}

}  // namespace brick_stack_sim
