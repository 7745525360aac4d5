#pragma once

#include <vector>

#include <Eigen/Core>

namespace brick_stack_sim {

/// A convex polygon in the horizontal plane, vertices counter-clockwise, no
/// repeated or collinear vertices. Fewer than three vertices is a degenerate
/// hull: a point or a segment, which has no area and so supports nothing.
using Polygon2d = std::vector<Eigen::Vector2d>;

/// Convex hull of `points` (Andrew's monotone chain with exact double
/// orientation tests). Points closer than `merge_distance` [m] count as one.
Polygon2d convexHull(std::vector<Eigen::Vector2d> points, double merge_distance = 1e-9);

/// Signed distance [m] from `point` to the boundary of `hull`: positive
/// inside, negative outside. A degenerate hull (point or segment) has no
/// inside: the result is minus the distance to it, never positive, so a brick
/// resting on a point or an edge is never called stable.
double signedDistance(const Polygon2d& hull, const Eigen::Vector2d& point);

/// `point` when it lies in `hull`, else the point of `hull` nearest to it
/// (on its boundary); `point` for an empty hull.
Eigen::Vector2d nearestPoint(const Polygon2d& hull, const Eigen::Vector2d& point);

/// Whether `point` lies inside `hull` or within `tolerance` [m] of it.
bool contains(const Polygon2d& hull, const Eigen::Vector2d& point, double tolerance = 0.0);

/// Intersection of two convex polygons (counter-clockwise); empty when they
/// do not overlap with positive area.
Polygon2d intersectConvex(const Polygon2d& subject, const Polygon2d& clip);

/// Area [m^2]; 0 for a degenerate hull.
double area(const Polygon2d& hull);

/// Area centroid; the mean of the vertices for a degenerate hull.
Eigen::Vector2d centroid(const Polygon2d& hull);

}  // namespace brick_stack_sim
