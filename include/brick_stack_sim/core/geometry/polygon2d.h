#pragma once

#include <array>
#include <cassert>
#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace brick_stack_sim {

/// A convex polygon in the horizontal plane, vertices counter-clockwise, no
/// repeated or collinear vertices. Fewer than three vertices is a degenerate
/// hull: a point or a segment, which has no area and so supports nothing.
using Polygon2d = std::vector<Eigen::Vector2d>;

/// Corners of a hull closer than this count as one [m].
constexpr double kHullMergeDistance = 1e-9;

/// Convex hull of `points` (Andrew's monotone chain with exact double
/// orientation tests). Points closer than `merge_distance` [m] count as one.
Polygon2d convexHull(std::vector<Eigen::Vector2d> points,
                     double merge_distance = kHullMergeDistance);

/// A polygon held in place, not on the heap, with room for what clipping
/// two quadrilaterals can make in floating point (each of four half-planes
/// at most doubles the corners) and for the hull of that.
class InlinePolygon2d {
 public:
  static constexpr std::size_t kCapacity = 128;

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  void clear() { size_ = 0; }
  void resize(std::size_t size) {
    assert(size <= kCapacity);
    size_ = size;
  }
  void push_back(const Eigen::Vector2d& corner) {
    assert(size_ < kCapacity);
    corners_[size_++] = corner;
  }
  template <typename Iterator>
  void assign(Iterator first, Iterator last) {
    clear();
    for (; first != last; ++first) push_back(*first);
  }
  Eigen::Vector2d& operator[](std::size_t i) { return corners_[i]; }
  const Eigen::Vector2d& operator[](std::size_t i) const { return corners_[i]; }
  Eigen::Vector2d* begin() { return corners_.data(); }
  Eigen::Vector2d* end() { return corners_.data() + size_; }
  const Eigen::Vector2d* begin() const { return corners_.data(); }
  const Eigen::Vector2d* end() const { return corners_.data() + size_; }

 private:
  std::array<Eigen::Vector2d, kCapacity> corners_;
  std::size_t size_ = 0;
};

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

/// intersectConvex(convexHull(subject), convexHull(clip)) of four corners
/// each, to the same bits, without the heap: the narrowphase clips every
/// resting pair of box faces every step.
void intersectQuadrilaterals(const std::array<Eigen::Vector2d, 4>& subject,
                             const std::array<Eigen::Vector2d, 4>& clip, InlinePolygon2d* overlap);

/// Area [m^2]; 0 for a degenerate hull.
double area(const Polygon2d& hull);

/// Area centroid; the mean of the vertices for a degenerate hull.
Eigen::Vector2d centroid(const Polygon2d& hull);

}  // namespace brick_stack_sim
