#pragma once

#include <vector>

#include <BulletCollision/CollisionDispatch/btBoxBoxCollisionAlgorithm.h>
#include <btBulletCollisionCommon.h>
#include <Eigen/Core>

#include "bullet/apart_pair_dispatcher.h"

namespace brick_stack_sim {

/// The value of btPersistentManifold::m_companionIdA (a field Bullet itself
/// never reads or writes) in both manifolds of a pair whose flush corners
/// are split between two.
constexpr int kSplitPatchTag = 0x5f1a5;

/// Bullet's box-box narrowphase, with faces that rest flush given the
/// corners of their overlap.
///
/// Two boxes lying flat one on the other touch across the overlap of two
/// faces, a polygon of up to eight corners (two planks crossing at an
/// angle). Bullet's clipper keeps four of them, the deepest first, and on
/// faces that rest flush which corner is deepest is rounding: from one
/// step to the next the manifold drops a corner that bears the weight for
/// one that bears nothing, its warm-started impulse with it, and a plank
/// lying across another is kicked every few steps, never at rest for a
/// whole rest window. Here, where the faces are parallel within
/// kFlushAngle and touch, the manifold is given the overlap's corners:
/// chosen by geometry, the same every step while the boxes rest, so every
/// point keeps its warm start. Everywhere else Bullet's detector runs.
///
/// A manifold holds four points, and two planks lying along each other at
/// a small angle overlap in a hexagon. Four of its corners span less than
/// the whole: a plank loaded off that quadrilateral tipped about its side
/// wherever statics holds it, and rocked in place. The four that span the
/// largest area go to the pair's manifold and the others to a second one,
/// tagged (kSplitPatchTag) so that a reader takes both as one pair.
///
/// A pair with points whose relative pose has moved less than kReuseDrift
/// since its manifold was last detected keeps that manifold: its points ride with the
/// two bodies (Bullet's refresh) and its normals turn with the body they face out of,
/// the way Jolt's body pair cache replays a contact. Bricks at rest on each
/// other are most of a pile's pairs, and their detection gives the same
/// points step after step.
///
/// A pair left with no point whose boxes are apart beyond the distance at
/// which a point can be made gives that excess to an ApartPairDispatcher
/// (when it is the dispatcher), which passes the pair over until its bodies
/// could have closed it.
class FlushBoxBoxAlgorithm : public btBoxBoxCollisionAlgorithm {
 public:
  FlushBoxBoxAlgorithm(const btCollisionAlgorithmConstructionInfo& info,
                       const btCollisionObjectWrapper* body0,
                       const btCollisionObjectWrapper* body1);
  ~FlushBoxBoxAlgorithm() override;

  void getAllContactManifolds(btManifoldArray& manifolds) override;

  void processCollision(const btCollisionObjectWrapper* body0,
                        const btCollisionObjectWrapper* body1, const btDispatcherInfo& info,
                        btManifoldResult* result) override;

  struct CreateFunc : public btCollisionAlgorithmCreateFunc {
    btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& info,
                                                   const btCollisionObjectWrapper* body0,
                                                   const btCollisionObjectWrapper* body1) override;
  };

 private:
  /// A corner of a flush patch within reach of the upper face.
  struct Corner {
    Eigen::Vector3d on_lower, on_upper;
    double depth;  // < 0: penetrating
  };

  /// Puts the flush corners of the two boxes into the pair's manifolds;
  /// false (and nothing changed) where their faces do not rest flush.
  bool addFlushCorners(const btCollisionObjectWrapper& body0, const btCollisionObjectWrapper& body1,
                       btManifoldResult* result);

  /// Makes `manifold`'s points `corners`, each keeping the warm start of
  /// the point it replaces.
  static void fillManifold(btPersistentManifold* manifold, const Corner* begin, const Corner* end,
                           bool body1_lower, const Eigen::Vector3d& normal,
                           btManifoldResult* result);

  /// Holds the corners past the first four in the second manifold
  /// (dropExtra() when there are none).
  void fillExtra(const Corner* begin, const Corner* end, bool body1_lower,
                 const Eigen::Vector3d& normal, btManifoldResult* result);
  /// Empties the second manifold and untags the pair: one manifold holds
  /// all its points.
  void dropExtra();

  /// Whether the smaller box has moved less than kReuseDrift, at every
  /// point of it, relative to the larger since the manifold was last
  /// detected; `relative` is its pose in the larger one's frame.
  bool withinReuseDrift(const btTransform& relative) const;

  /// Moves the manifolds' points with the bodies, as if detected again.
  void replayManifold(btManifoldResult* result);
  /// Turns `manifold`'s normals with body B and refreshes its points.
  void replay(btPersistentManifold* manifold, const btMatrix3x3& turn, btManifoldResult* result);

  /// Keeps what a replay starts from once the manifold has been detected.
  void rememberDetection(const btTransform& relative);

  /// With no point, tells the dispatcher how far apart beyond reach the
  /// boxes are.
  void offerGap(const btCollisionObjectWrapper& body0, const btCollisionObjectWrapper& body1);

  /// The pair's manifold, which the base class owns (null when the pair
  /// needs no collision).
  btPersistentManifold* manifold_ = nullptr;
  /// The flush corners past the four manifold_ holds (null until a patch
  /// had more than four); this algorithm owns it.
  btPersistentManifold* extra_ = nullptr;
  /// The overlap of the faces, kept between steps so that a resting pair's
  /// step does not go to the heap for it.
  mutable std::vector<Eigen::Vector3d> patch_;
  /// The smaller box's pose in the larger one's frame when the manifold was
  /// last detected.
  btTransform detected_relative_;
  /// The basis of the manifold's body B at the last step, whose change since
  /// turns a replayed point's normal.
  btMatrix3x3 last_basis_b_;
  /// Whether detected_relative_ holds a detection a replay may start from.
  bool detected_ = false;
  /// Whether body0 is the smaller box (by the distance of its corners from
  /// its centre), whose drift is measured.
  bool smaller_is_body0_ = true;
  /// The distance of the smaller box's corners from its centre [m].
  btScalar smaller_radius_ = 0.0;
  /// The dispatcher that passes apart pairs over; null for any other.
  ApartPairDispatcher* apart_ = nullptr;
};

}  // namespace brick_stack_sim
