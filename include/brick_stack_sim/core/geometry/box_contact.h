#pragma once

#include <vector>

#include <Eigen/Core>

#include "brick_stack_sim/core/geometry/box_geometry.h"

namespace brick_stack_sim {

/// Where two boxes touch across one face: the face's normal and the points
/// of the other box that lie on it.
struct BoxContactFace {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< Unit, from box b towards box a.
  std::vector<Eigen::Vector3d> points;                ///< On the face's plane [m], world.
};

/// The contacts of two boxes that touch without overlapping, found from
/// geometry (a brick placed at rest has not been simulated yet): for every
/// face of either box whose plane separates the boxes within `max_gap` [m],
/// the other box's face turned towards it clipped to that face, keeping the
/// points within `max_gap` of the plane. A plank's edge on the table gives
/// the edge's two ends; two leaning planks' top edges meeting in a V give a
/// contact across each plank's face, whose two normals span the forces the
/// rounded edges can pass. Faces that rest flush are reported once (from
/// b's side). Two edges that cross at a point with no face between them are
/// not found. Empty when the boxes overlap deeper than `max_gap` or are
/// apart.
std::vector<BoxContactFace> touchingContacts(const OrientedBox& a, const OrientedBox& b,
                                             double max_gap);

}  // namespace brick_stack_sim
