// Bullet's GrahamScanConvexHull2D was the library candidate, but it sorts by
// btAtan2Fast (errors of ~1e-2 rad) and treats points within sqrt(FLT_EPSILON)
// = 0.35 mm of the anchor as coincident: at brick scale that drops real corners
// of a contact patch. The monotone chain below needs only exact cross products.
#include "brick_stack_sim/core/geometry/polygon2d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace brick_stack_sim {

namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length_squared = ab.squaredNorm();
  const double t =
      length_squared > 0.0 ? std::clamp((p - a).dot(ab) / length_squared, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// The hull and the clip below are written once for two kinds of buffer: the
// heap's (Polygon2d) and one held in place (InlinePolygon2d), so that both
// give the same corners to the last bit.

/// Sorts `points` and keeps, in place, the first of those closer than
/// `merge_distance` [m] to one kept before.
template <typename Points>
void sortAndMerge(Points* points, double merge_distance) {
  std::sort(points->begin(), points->end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::size_t kept = 0;
  for (std::size_t i = 0; i < points->size(); ++i) {
    const Eigen::Vector2d p = (*points)[i];
    // Further apart in x than the distance, never closer in all (the norm
    // of a vector is at least each of its components, in doubles too): the
    // square root is left for the few that are near.
    const bool duplicate = std::any_of(
        points->begin(), points->begin() + static_cast<std::ptrdiff_t>(kept),
        [&](const Eigen::Vector2d& q) {
          return std::abs(p.x() - q.x()) <= merge_distance && (p - q).norm() <= merge_distance;
        });
    if (!duplicate) (*points)[kept++] = p;
  }
  points->resize(kept);
}

/// The hull of sorted, merged `unique` points into `hull`.
template <typename Points>
void chainHull(const Points& unique, Points* hull) {
  if (unique.size() < 3) {
    hull->resize(unique.size());
    std::copy(unique.begin(), unique.end(), hull->begin());
    return;
  }
  hull->resize(2 * unique.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < unique.size(); ++i) {  // lower chain
    while (k >= 2 && cross((*hull)[k - 2], (*hull)[k - 1], unique[i]) <= 0.0) --k;
    (*hull)[k++] = unique[i];
  }
  for (std::size_t i = unique.size() - 1, lower = k + 1; i-- > 0;) {  // upper chain
    while (k >= lower && cross((*hull)[k - 2], (*hull)[k - 1], unique[i]) <= 0.0) --k;
    (*hull)[k++] = unique[i];
  }
  hull->resize(k - 1);  // the last point repeats the first
  if (hull->size() < 3) {
    // All points collinear: keep the two extremes as a segment.
    hull->resize(2);
    (*hull)[0] = unique[0];
    (*hull)[1] = unique[unique.size() - 1];
  }
}

/// Sutherland-Hodgman: `subject` clipped by each edge's inner half-plane of
/// `clip` in turn, with `first` and `second` as the two buffers passed back
/// and forth; returns the one that holds the result. Each half-plane at
/// most doubles the corners.
template <typename Points>
Points* clipConvex(const Points& subject, const Points& clip, Points* first, Points* second) {
  Points* output = first;
  Points* input = second;
  output->resize(subject.size());
  std::copy(subject.begin(), subject.end(), output->begin());
  for (std::size_t i = 0; i < clip.size() && !output->empty(); ++i) {
    const Eigen::Vector2d& a = clip[i];
    const Eigen::Vector2d& b = clip[(i + 1) % clip.size()];
    std::swap(input, output);
    output->clear();
    for (std::size_t j = 0; j < input->size(); ++j) {
      const Eigen::Vector2d& p = (*input)[j];
      const Eigen::Vector2d& q = (*input)[(j + 1) % input->size()];
      const double side_p = cross(a, b, p), side_q = cross(a, b, q);
      if (side_p >= 0.0) output->push_back(p);
      if ((side_p >= 0.0) != (side_q >= 0.0))
        output->push_back(p + (q - p) * (side_p / (side_p - side_q)));
    }
  }
  return output;
}

/// intersectConvex() into `overlap`, with `scratch` as a second buffer.
template <typename Points>
void intersectInto(const Points& subject, const Points& clip, Points* overlap, Points* scratch) {
  if (subject.size() < 3 || clip.size() < 3) {
    overlap->clear();
    return;
  }
  Points* clipped = clipConvex(subject, clip, scratch, overlap);
  Points* hull = clipped == scratch ? overlap : scratch;
  sortAndMerge(clipped, kHullMergeDistance);
  chainHull(*clipped, hull);
  if (hull->size() < 3) hull->clear();
  if (hull != overlap) {
    overlap->resize(hull->size());
    std::copy(hull->begin(), hull->end(), overlap->begin());
  }
}

}  // namespace

Polygon2d convexHull(std::vector<Eigen::Vector2d> points, double merge_distance) {
  sortAndMerge(&points, merge_distance);
  Polygon2d hull;
  chainHull(points, &hull);
  return hull;
}

double signedDistance(const Polygon2d& hull, const Eigen::Vector2d& point) {
  if (hull.empty()) return -std::numeric_limits<double>::infinity();
  if (hull.size() == 1) return -(point - hull[0]).norm();
  if (hull.size() == 2) return -distanceToSegment(point, hull[0], hull[1]);
  double nearest_edge = std::numeric_limits<double>::infinity();
  bool inside = true;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d& a = hull[i];
    const Eigen::Vector2d& b = hull[(i + 1) % hull.size()];
    if (cross(a, b, point) < 0.0) inside = false;  // right of a counter-clockwise edge
    nearest_edge = std::min(nearest_edge, distanceToSegment(point, a, b));
  }
  return inside ? nearest_edge : -nearest_edge;
}

Eigen::Vector2d nearestPoint(const Polygon2d& hull, const Eigen::Vector2d& point) {
  if (hull.empty() || (hull.size() >= 3 && signedDistance(hull, point) >= 0.0)) return point;
  if (hull.size() == 1) return hull[0];
  Eigen::Vector2d nearest = hull[0];
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d& a = hull[i];
    const Eigen::Vector2d& b = hull[(i + 1) % hull.size()];
    const Eigen::Vector2d edge = b - a;
    const double t = edge.squaredNorm() > 0.0
                         ? std::clamp((point - a).dot(edge) / edge.squaredNorm(), 0.0, 1.0)
                         : 0.0;
    const Eigen::Vector2d candidate = a + t * edge;
    if ((candidate - point).squaredNorm() < (nearest - point).squaredNorm()) nearest = candidate;
  }
  return nearest;
}

bool contains(const Polygon2d& hull, const Eigen::Vector2d& point, double tolerance) {
  return signedDistance(hull, point) >= -tolerance;
}

Polygon2d intersectConvex(const Polygon2d& subject, const Polygon2d& clip) {
  Polygon2d overlap, scratch;
  overlap.reserve(subject.size() + clip.size());
  scratch.reserve(subject.size() + clip.size());
  intersectInto(subject, clip, &overlap, &scratch);
  return overlap;
}

void intersectQuadrilaterals(const std::array<Eigen::Vector2d, 4>& subject,
                             const std::array<Eigen::Vector2d, 4>& clip, InlinePolygon2d* overlap) {
  InlinePolygon2d subject_hull, clip_hull, scratch;
  // Four corners clipped by four half-planes: at most 64 corners.
  static_assert(InlinePolygon2d::kCapacity >= 2 * 64, "room for the hull of the clipped corners");
  scratch.assign(subject.begin(), subject.end());
  sortAndMerge(&scratch, kHullMergeDistance);
  chainHull(scratch, &subject_hull);
  scratch.assign(clip.begin(), clip.end());
  sortAndMerge(&scratch, kHullMergeDistance);
  chainHull(scratch, &clip_hull);
  intersectInto(subject_hull, clip_hull, overlap, &scratch);
}

double area(const Polygon2d& hull) {
  if (hull.size() < 3) return 0.0;
  double twice = 0.0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d& a = hull[i];
    const Eigen::Vector2d& b = hull[(i + 1) % hull.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

Eigen::Vector2d centroid(const Polygon2d& hull) {
  if (hull.empty()) return Eigen::Vector2d::Zero();
  const double total = area(hull);
  if (hull.size() < 3 || total <= 0.0) {
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& p : hull) mean += p;
    return mean / static_cast<double>(hull.size());
  }
  // Fan from the first vertex: area-weighted triangle centroids.
  Eigen::Vector2d weighted = Eigen::Vector2d::Zero();
  for (std::size_t i = 1; i + 1 < hull.size(); ++i) {
    const double triangle = 0.5 * cross(hull[0], hull[i], hull[i + 1]);
    weighted += triangle * (hull[0] + hull[i] + hull[i + 1]) / 3.0;
  }
  return weighted / total;
}

}  // namespace brick_stack_sim
