#include "bullet/flush_box_box_algorithm.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <new>
#include <vector>

#include <Eigen/Geometry>

#include "brick_stack_sim/core/geometry/box_geometry.h"
#include "bullet/bullet_conversions.h"
#include "bullet/turn_bound.h"

namespace brick_stack_sim {
namespace {

/// Faces closer than this to parallel [rad], and one's centre closer than
/// kFlushGap [m] to the other's plane, rest flush: the stability layer's
/// defaults (`flush_angle`, `contact_distance`), where it takes the same
/// overlap as the contact's patch. Faces further apart are landing or
/// parting, and Bullet's detector follows them as before.
constexpr double kFlushAngle = 0.002;
constexpr double kFlushGap = 1e-4;

/// How far [m] any point of one box may have moved relative to the other
/// since their manifold was detected, for the manifold to be replayed
/// instead of detected again. A contact the replay misses is one that this
/// motion made: a corner that slid onto the other's face or closed a gap, at
/// most this deep. A tenth of the flush gap, a fiftieth of a millimetre:
/// bricks at rest move less than this in a few 1 ms steps at the rest
/// speeds, anything landing or sliding more in one.
constexpr double kReuseDrift = 1e-5;

/// What a separating-axis gap is trusted to [m], far above its rounding.
constexpr double kGapTolerance = 1e-9;

/// Whether a face of one box may lie within kFlushAngle of parallel to a
/// face of the other. The cosine between two face normals is an entry of
/// the boxes' relative rotation (up to sign), so when every entry is below
/// cos(kFlushAngle) no pair of faces rests flush and no patch is looked for:
/// most pairs of a landing pile's tumbling planks are settled by nine dot
/// products. The margin only lets rounding through to the full test.
bool mayRestFlush(const btMatrix3x3& basis0, const btMatrix3x3& basis1) {
  static const double least_cosine = std::cos(kFlushAngle) - 1e-12;
  const btMatrix3x3 relative = basis0.transposeTimes(basis1);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::abs(relative[i][j]) >= least_cosine) return true;
  return false;
}

OrientedBox orientedBox(const btCollisionObjectWrapper& body) {
  const auto* shape = static_cast<const btBoxShape*>(body.getCollisionShape());
  OrientedBox box;
  box.pose = convertBtToEigen(body.getWorldTransform());
  // With its margin, as Bullet's detector sees it.
  box.half_extents = convertBtToEigen(shape->getHalfExtentsWithMargin());
  return box;
}

/// The face of `box` turned most towards a direction, found once for the
/// corners of a patch.
struct FacingFace {
  Eigen::Vector3d centre;    ///< the box's [m]
  Eigen::Vector3d outward;   ///< the face's normal
  double half_extent = 0.0;  ///< [m] along it
  /// Signed distance [m] of `point` from the face's plane; negative inside the box.
  double above(const Eigen::Vector3d& point) const {
    return (point - centre).dot(outward) - half_extent;
  }
};

FacingFace faceToward(const OrientedBox& box, const Eigen::Vector3d& direction) {
  FacingFace face;
  face.centre = box.pose.translation();
  face.half_extent = box.half_extents[faceAxisToward(box, direction, &face.outward)];
  return face;
}

/// Which corners of a polygon a manifold takes: at most four.
struct ChosenCorners {
  std::array<std::size_t, 4> index{};
  std::size_t count = 0;
};

/// The four corners of the convex polygon `corners` (in order) that span
/// the largest area, in order; all of them when there are no more than four.
/// The first of equal quadrilaterals wins, so the choice is the same every
/// step while the polygon stays.
ChosenCorners widestFour(const std::vector<Eigen::Vector3d>& corners,
                         const Eigen::Vector3d& normal) {
  const std::size_t n = corners.size();
  ChosenCorners chosen;
  if (n <= 4) {
    for (std::size_t i = 0; i < n; ++i) chosen.index[i] = i;
    chosen.count = n;
    return chosen;
  }
  // A quadrilateral of a convex polygon's corners taken in order is convex:
  // twice its area is the cross product of its diagonals.
  const auto area = [&](std::size_t a, std::size_t b, std::size_t c, std::size_t d) {
    return std::abs((corners[c] - corners[a]).cross(corners[d] - corners[b]).dot(normal));
  };
  double widest = -1.0;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t c = b + 1; c < n; ++c)
        for (std::size_t d = c + 1; d < n; ++d) {
          const double twice = area(a, b, c, d);
          if (twice > widest) {
            widest = twice;
            chosen.index = {a, b, c, d};
          }
        }
  chosen.count = 4;
  return chosen;
}

}  // namespace

FlushBoxBoxAlgorithm::FlushBoxBoxAlgorithm(const btCollisionAlgorithmConstructionInfo& info,
                                           const btCollisionObjectWrapper* body0,
                                           const btCollisionObjectWrapper* body1)
    : btBoxBoxCollisionAlgorithm(nullptr, info, body0, body1) {
  btManifoldArray manifolds;
  getAllContactManifolds(manifolds);
  if (manifolds.size() == 1) manifold_ = manifolds[0];
  const auto* shape0 = static_cast<const btBoxShape*>(body0->getCollisionShape());
  const auto* shape1 = static_cast<const btBoxShape*>(body1->getCollisionShape());
  const btScalar radius0 = shape0->getHalfExtentsWithMargin().length();
  const btScalar radius1 = shape1->getHalfExtentsWithMargin().length();
  // The drift is measured on the smaller box, in the larger one's frame: a
  // plank's turn on the table moves its own corners, not the table's.
  smaller_is_body0_ = radius0 <= radius1;
  smaller_radius_ = std::min(radius0, radius1);
  apart_ = dynamic_cast<ApartPairDispatcher*>(info.m_dispatcher1);
}

FlushBoxBoxAlgorithm::~FlushBoxBoxAlgorithm() {
  if (extra_) m_dispatcher->releaseManifold(extra_);
}

void FlushBoxBoxAlgorithm::getAllContactManifolds(btManifoldArray& manifolds) {
  btBoxBoxCollisionAlgorithm::getAllContactManifolds(manifolds);
  if (extra_) manifolds.push_back(extra_);
}

void FlushBoxBoxAlgorithm::processCollision(const btCollisionObjectWrapper* body0,
                                            const btCollisionObjectWrapper* body1,
                                            const btDispatcherInfo& info,
                                            btManifoldResult* result) {
  if (!manifold_) return;  // as the base class: the pair needs no collision
  const btTransform& transform0 = body0->getWorldTransform();
  const btTransform& transform1 = body1->getWorldTransform();
  const btTransform relative =
      smaller_is_body0_ ? transform1.inverseTimes(transform0) : transform0.inverseTimes(transform1);
  // An empty manifold is detected again, never replayed: a contact the
  // drift made is found at once, and what an empty pair gives depends on
  // its poses alone, so passing it over while it is apart changes nothing.
  if (detected_ && manifold_->getNumContacts() > 0 && withinReuseDrift(relative)) {
    replayManifold(result);
  } else {
    if (!addFlushCorners(*body0, *body1, result)) {
      dropExtra();
      btBoxBoxCollisionAlgorithm::processCollision(body0, body1, info, result);
    }
    rememberDetection(relative);
  }
  offerGap(*body0, *body1);
}

void FlushBoxBoxAlgorithm::offerGap(const btCollisionObjectWrapper& body0,
                                    const btCollisionObjectWrapper& body1) {
  if (!apart_ || manifold_->getNumContacts() > 0) return;
  // Bullet's detector makes points only where the boxes overlap, the flush
  // corners only within the breaking threshold; the separating-axis gap is
  // a lower bound of the distance.
  const double gap = separation(orientedBox(body0), orientedBox(body1));
  apart_->keepApart(gap - manifold_->getContactBreakingThreshold() - kGapTolerance);
}

bool FlushBoxBoxAlgorithm::withinReuseDrift(const btTransform& relative) const {
  const btScalar moved = (relative.getOrigin() - detected_relative_.getOrigin()).length();
  const btScalar turned = turnBound(relative.getBasis(), detected_relative_.getBasis());
  return moved + turned * smaller_radius_ < kReuseDrift;
}

void FlushBoxBoxAlgorithm::replayManifold(btManifoldResult* result) {
  // The normal is B's face's (or the separating axis in B's frame): it turns
  // with B. Bullet's refresh then moves each point with its body and measures
  // its depth along that normal.
  const btMatrix3x3& basis_b = manifold_->getBody1()->getWorldTransform().getBasis();
  const btMatrix3x3 turn = basis_b.timesTranspose(last_basis_b_);
  last_basis_b_ = basis_b;
  if (extra_ && extra_->getNumContacts() > 0) replay(extra_, turn, result);
  replay(manifold_, turn, result);
}

void FlushBoxBoxAlgorithm::replay(btPersistentManifold* manifold, const btMatrix3x3& turn,
                                  btManifoldResult* result) {
  for (int i = 0; i < manifold->getNumContacts(); ++i) {
    btManifoldPoint& point = manifold->getContactPoint(i);
    point.m_normalWorldOnB = turn * point.m_normalWorldOnB;
  }
  result->setPersistentManifold(manifold);
  result->refreshContactPoints();
}

void FlushBoxBoxAlgorithm::rememberDetection(const btTransform& relative) {
  detected_relative_ = relative;
  last_basis_b_ = manifold_->getBody1()->getWorldTransform().getBasis();
  detected_ = true;
}

bool FlushBoxBoxAlgorithm::addFlushCorners(const btCollisionObjectWrapper& body0,
                                           const btCollisionObjectWrapper& body1,
                                           btManifoldResult* result) {
  if (!mayRestFlush(body0.getWorldTransform().getBasis(), body1.getWorldTransform().getBasis()))
    return false;
  const OrientedBox box0 = orientedBox(body0), box1 = orientedBox(body1);
  std::vector<Eigen::Vector3d>& patch = patch_;
  Eigen::Vector3d normal;  // the lower face's, towards the upper box
  // Bullet's B is body1: its normal points from body1 towards body0. Which
  // box lies on the other is asked both ways: on a slope the upper one's
  // centre may be the lower.
  const bool body1_lower = flushContactPatch(box1, box0, kFlushAngle, kFlushGap, &patch, &normal);
  if (!body1_lower && !flushContactPatch(box0, box1, kFlushAngle, kFlushGap, &patch, &normal))
    return false;
  const OrientedBox& upper = body1_lower ? box0 : box1;
  const double reach = manifold_->getContactBreakingThreshold();
  // Two rectangles overlap in at most eight corners.
  std::array<Corner, 8> within_reach;
  std::size_t count = 0;
  const ChosenCorners chosen = widestFour(patch, normal);
  const FacingFace upper_face = faceToward(upper, -normal);
  const auto take = [&](std::size_t index) {
    const Eigen::Vector3d& c = patch[index];
    const double depth = upper_face.above(c);
    if (depth <= reach && count < within_reach.size())
      within_reach[count++] = {c, c + normal * depth, depth};
  };
  for (std::size_t i = 0; i < chosen.count; ++i) take(chosen.index[i]);
  for (std::size_t i = 0; i < patch.size(); ++i)
    if (std::find(chosen.index.begin(), chosen.index.begin() + chosen.count, i) ==
        chosen.index.begin() + chosen.count)
      take(i);
  if (count == 0) return false;
  const Corner* corners = within_reach.data();
  const std::size_t in_first = std::min<std::size_t>(count, 4);
  fillManifold(manifold_, corners, corners + in_first, body1_lower, normal, result);
  fillExtra(corners + in_first, corners + count, body1_lower, normal, result);
  return true;
}

void FlushBoxBoxAlgorithm::fillManifold(btPersistentManifold* manifold, const Corner* begin,
                                        const Corner* end, bool body1_lower,
                                        const Eigen::Vector3d& normal, btManifoldResult* result) {
  const double reach = manifold->getContactBreakingThreshold();
  // Points the corners will not replace would hold slots the manifold then
  // frees by its own choice: they go first. A corner replaces the point it
  // lies within reach of, and keeps its warm start.
  result->setPersistentManifold(manifold);
  for (int j = manifold->getNumContacts() - 1; j >= 0; --j) {
    const btManifoldPoint& cached = manifold->getContactPoint(j);
    const Eigen::Vector3d middle =
        0.5 * convertBtToEigen(cached.getPositionWorldOnA() + cached.getPositionWorldOnB());
    bool kept = false;
    for (const Corner* corner = begin; corner != end; ++corner)
      kept |= (0.5 * (corner->on_lower + corner->on_upper) - middle).norm() < reach;
    if (!kept) manifold->removeContactPoint(j);
  }
  for (const Corner* corner = begin; corner != end; ++corner) {
    if (body1_lower)
      result->addContactPoint(convertEigenToBt(normal), convertEigenToBt(corner->on_lower),
                              corner->depth);
    else
      result->addContactPoint(convertEigenToBt(-normal), convertEigenToBt(corner->on_upper),
                              corner->depth);
  }
  result->refreshContactPoints();
}

void FlushBoxBoxAlgorithm::fillExtra(const Corner* begin, const Corner* end, bool body1_lower,
                                     const Eigen::Vector3d& normal, btManifoldResult* result) {
  if (begin == end) {
    dropExtra();
    return;
  }
  // The same bodies in the same order as the first, so that its normals
  // point the same way.
  if (!extra_) extra_ = m_dispatcher->getNewManifold(manifold_->getBody0(), manifold_->getBody1());
  manifold_->m_companionIdA = kSplitPatchTag;
  extra_->m_companionIdA = kSplitPatchTag;
  fillManifold(extra_, begin, end, body1_lower, normal, result);
  result->setPersistentManifold(manifold_);
}

void FlushBoxBoxAlgorithm::dropExtra() {
  if (extra_) extra_->clearManifold();
  manifold_->m_companionIdA = 0;
}

btCollisionAlgorithm* FlushBoxBoxAlgorithm::CreateFunc::CreateCollisionAlgorithm(
    btCollisionAlgorithmConstructionInfo& info, const btCollisionObjectWrapper* body0,
    const btCollisionObjectWrapper* body1) {
  void* memory = info.m_dispatcher1->allocateCollisionAlgorithm(sizeof(FlushBoxBoxAlgorithm));
  return new (memory) FlushBoxBoxAlgorithm(info, body0, body1);
}

}  // namespace brick_stack_sim
