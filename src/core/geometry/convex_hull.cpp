// Quickhull (Barber, Dobkin and Huhdanpaa 1996) on triangles with a
// tolerance: a point within it of a face's plane counts as on the face, so it
// is dropped rather than added as a sliver. Coplanar triangles are merged
// into one polygon per plane afterwards.
#include "brick_stack_sim/core/geometry/convex_polyhedron.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <utility>

#include <Eigen/Geometry>

namespace brick_stack_sim {

namespace {

/// Points closer than this times the points' bounding-box diagonal to a plane
/// or a line are on it [-]: far above double rounding, far below any brick.
constexpr double kRelativeTolerance = 1e-9;

struct Triangle {
  std::array<int, 3> v{};       ///< Counter-clockwise seen from outside.
  std::array<int, 3> across{};  ///< across[i]: the triangle beyond edge v[i] -> v[i + 1].
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double offset = 0.0;
  std::vector<int> outside;  ///< Points above this triangle, not yet in the hull.
  bool alive = true;
};

class Quickhull {
 public:
  Quickhull(const std::vector<Eigen::Vector3d>& points, double tolerance)
      : points_(points), tolerance_(tolerance) {}

  /// Builds the hull from a tetrahedron of four of the points (indices, any orientation).
  void run(std::array<int, 4> simplex, const std::vector<int>& candidates);
  const std::vector<Triangle>& triangles() const { return triangles_; }
  /// Whether rounding left a horizon that is not one loop (no hull then).
  bool failed() const { return failed_; }

 private:
  double height(const Triangle& t, int point) const {
    return t.normal.dot(points_[point]) - t.offset;
  }
  int addTriangle(int a, int b, int c);
  void assign(const std::vector<int>& candidates, const std::vector<int>& targets);
  void addPoint(int face, int point);
  /// Whether `t`, beyond the edge a-b of a visible triangle, must go too.
  bool absorbs(const Triangle& t, int a, int b, int point) const;
  /// The triangles `point` sees, by flooding from `face`: a disc whose rim is the horizon.
  std::vector<int> visibleFrom(int face, int point, std::vector<char>* visible) const;

  const std::vector<Eigen::Vector3d>& points_;
  const double tolerance_;
  std::vector<Triangle> triangles_;
  bool failed_ = false;
};

int Quickhull::addTriangle(int a, int b, int c) {
  Triangle t;
  t.v = {a, b, c};
  const Eigen::Vector3d& pa = points_[a];
  t.normal = (points_[b] - pa).cross(points_[c] - pa).normalized();
  t.offset = t.normal.dot(pa);
  triangles_.push_back(std::move(t));
  return static_cast<int>(triangles_.size()) - 1;
}

void Quickhull::assign(const std::vector<int>& candidates, const std::vector<int>& targets) {
  for (const int p : candidates) {
    for (const int t : targets) {
      if (height(triangles_[t], p) > tolerance_) {
        triangles_[t].outside.push_back(p);
        break;
      }
    }  // above none: inside the hull, or on it within the tolerance
  }
}

void Quickhull::run(std::array<int, 4> s, const std::vector<int>& candidates) {
  const Eigen::Vector3d& p0 = points_[s[0]];
  if ((points_[s[1]] - p0).cross(points_[s[2]] - p0).dot(points_[s[3]] - p0) > 0.0)
    std::swap(s[1], s[2]);  // the apex below the base: the base turns away from it
  addTriangle(s[0], s[1], s[2]);
  addTriangle(s[0], s[3], s[1]);
  addTriangle(s[1], s[3], s[2]);
  addTriangle(s[2], s[3], s[0]);
  // Edge i of a triangle runs from v[i] to v[i + 1]; its twin runs backwards.
  triangles_[0].across = {1, 2, 3};
  triangles_[1].across = {3, 2, 0};
  triangles_[2].across = {1, 3, 0};
  triangles_[3].across = {2, 1, 0};
  assign(candidates, {0, 1, 2, 3});
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    while (!failed_ && triangles_[t].alive && !triangles_[t].outside.empty()) {
      const std::vector<int>& outside = triangles_[t].outside;
      const int farthest = *std::max_element(outside.begin(), outside.end(), [&](int a, int b) {
        return height(triangles_[t], a) < height(triangles_[t], b);
      });
      addPoint(static_cast<int>(t), farthest);
    }
  }
}

bool Quickhull::absorbs(const Triangle& t, int a, int b, int point) const {
  const double h = height(t, point);
  if (h > 0.0) return true;  // keeping it would fold the surface in
  if (h <= -tolerance_) return false;
  // On the line of the edge a-b: the triangle fanned from it would have no area.
  const Eigen::Vector3d edge = points_[b] - points_[a];
  if (edge.cross(points_[point] - points_[a]).norm() <= tolerance_ * edge.norm()) return true;
  // On its plane within the tolerance: a triangle fanned from the horizon
  // edge a-b to the point would lie on this one's side, turned over.
  const int c =
      t.v[0] != a && t.v[0] != b ? t.v[0] : (t.v[1] != a && t.v[1] != b ? t.v[1] : t.v[2]);
  return t.normal.dot(edge.cross(points_[point] - points_[a])) *
             t.normal.dot(edge.cross(points_[c] - points_[a])) >
         0.0;
}

std::vector<int> Quickhull::visibleFrom(int face, int point, std::vector<char>* visible) const {
  std::vector<int> found = {face}, stack = {face};
  (*visible)[face] = 1;
  while (!stack.empty()) {
    const int t = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      const int next = triangles_[t].across[i];
      if ((*visible)[next]) continue;
      if (!absorbs(triangles_[next], triangles_[t].v[i], triangles_[t].v[(i + 1) % 3], point))
        continue;
      (*visible)[next] = 1;
      found.push_back(next);
      stack.push_back(next);
    }
  }
  return found;
}

void Quickhull::addPoint(int face, int point) {
  std::vector<char> visible(triangles_.size(), 0);
  const std::vector<int> doomed = visibleFrom(face, point, &visible);
  std::vector<int> created, orphans;
  std::unordered_map<int, int> starting_at;  // horizon edge's first vertex -> new triangle
  for (const int t : doomed) {
    for (int i = 0; i < 3; ++i) {
      const int beyond = triangles_[t].across[i];
      if (visible[beyond]) continue;
      const int a = triangles_[t].v[i], b = triangles_[t].v[(i + 1) % 3];
      if (starting_at.count(a)) {
        failed_ = true;  // the horizon pinches: rounding has broken the surface
        return;
      }
      const int fresh = addTriangle(a, b, point);
      Triangle& outer = triangles_[beyond];
      for (int j = 0; j < 3; ++j)
        if (outer.across[j] == t) outer.across[j] = fresh;
      triangles_[fresh].across[0] = beyond;
      starting_at[a] = fresh;
      created.push_back(fresh);
    }
  }
  // The horizon is one loop: the side (b, point) of a new triangle meets the
  // new triangle whose horizon edge starts at b.
  for (const int t : created) {
    const int next = starting_at.at(triangles_[t].v[1]);
    triangles_[t].across[1] = next;
    triangles_[next].across[2] = t;
  }
  for (const int t : doomed) {
    Triangle& gone = triangles_[t];
    gone.alive = false;
    for (const int p : gone.outside)
      if (p != point) orphans.push_back(p);
    std::vector<int>().swap(gone.outside);
  }
  assign(orphans, created);
}

/// Four of `points` spanning a volume, or an error saying why there are none.
Status initialSimplex(const std::vector<Eigen::Vector3d>& points, double tolerance,
                      std::array<int, 4>* simplex) {
  const int n = static_cast<int>(points.size());
  // The two farthest apart among the extremes along x, y and z.
  std::vector<int> extremes;
  for (int k = 0; k < 3; ++k) {
    int low = 0, high = 0;
    for (int i = 1; i < n; ++i) {
      if (points[i][k] < points[low][k]) low = i;
      if (points[i][k] > points[high][k]) high = i;
    }
    extremes.push_back(low);
    extremes.push_back(high);
  }
  int a = extremes[0], b = extremes[1];
  for (const int i : extremes)
    for (const int j : extremes)
      if ((points[i] - points[j]).norm() > (points[a] - points[b]).norm()) a = i, b = j;
  const Eigen::Vector3d direction = (points[b] - points[a]).normalized();
  auto from_line = [&](int i) { return (points[i] - points[a]).cross(direction).norm(); };
  int c = 0;
  for (int i = 1; i < n; ++i)
    if (from_line(i) > from_line(c)) c = i;
  if (!(from_line(c) > tolerance))
    return Status::error("points are coplanar: they span no volume (all lie on one line)");
  const Eigen::Vector3d normal = (points[b] - points[a]).cross(points[c] - points[a]).normalized();
  auto from_plane = [&](int i) { return std::abs(normal.dot(points[i] - points[a])); };
  int d = 0;
  for (int i = 1; i < n; ++i)
    if (from_plane(i) > from_plane(d)) d = i;
  if (!(from_plane(d) > tolerance))
    return Status::error("points are coplanar: they span no volume");
  *simplex = {a, b, c, d};
  return Status::success();
}

/// The loop around a group of triangles (counter-clockwise, as theirs), with
/// vertices on a straight run of it left out.
std::vector<int> boundaryLoop(const std::vector<Triangle>& triangles, const std::vector<int>& group,
                              const std::vector<int>& group_of,
                              const std::vector<Eigen::Vector3d>& points, double tolerance) {
  std::unordered_map<int, int> next;
  for (const int t : group) {
    for (int i = 0; i < 3; ++i)
      if (group_of[triangles[t].across[i]] != group_of[t])
        next[triangles[t].v[i]] = triangles[t].v[(i + 1) % 3];
  }
  std::vector<int> loop = {next.begin()->first};
  while (loop.size() <= next.size()) {
    const int following = next.at(loop.back());
    if (following == loop.front()) break;
    loop.push_back(following);
  }
  for (bool removed = true; removed && loop.size() > 3;) {
    removed = false;
    for (std::size_t i = 0; i < loop.size() && loop.size() > 3; ++i) {
      const Eigen::Vector3d& u = points[loop[(i + loop.size() - 1) % loop.size()]];
      const Eigen::Vector3d& w = points[loop[(i + 1) % loop.size()]];
      const Eigen::Vector3d& v = points[loop[i]];
      if ((v - u).cross((w - u).normalized()).norm() > tolerance) continue;
      loop.erase(loop.begin() + static_cast<std::ptrdiff_t>(i));
      removed = true;
    }
  }
  return loop;
}

/// Groups of alive triangles on one plane: flooding from a seed, a
/// neighbour joins when its vertices lie within the tolerance of the seed's
/// plane (not its neighbour's, so a gentle curve does not creep into one face).
std::vector<std::vector<int>> coplanarGroups(const std::vector<Triangle>& triangles,
                                             const std::vector<Eigen::Vector3d>& points,
                                             double tolerance, std::vector<int>* group_of) {
  std::vector<std::vector<int>> groups;
  group_of->assign(triangles.size(), -1);
  for (std::size_t seed = 0; seed < triangles.size(); ++seed) {
    if (!triangles[seed].alive || (*group_of)[seed] >= 0) continue;
    const Triangle& plane = triangles[seed];
    const int id = static_cast<int>(groups.size());
    groups.push_back({static_cast<int>(seed)});
    (*group_of)[seed] = id;
    for (std::size_t k = 0; k < groups[id].size(); ++k) {
      for (const int next : triangles[groups[id][k]].across) {
        if ((*group_of)[next] >= 0 || plane.normal.dot(triangles[next].normal) <= 0.0) continue;
        const bool on_plane =
            std::all_of(triangles[next].v.begin(), triangles[next].v.end(), [&](int p) {
              return std::abs(plane.normal.dot(points[p]) - plane.offset) <= tolerance;
            });
        if (!on_plane) continue;
        (*group_of)[next] = id;
        groups[id].push_back(next);
      }
    }
  }
  return groups;
}

/// The polyhedron of the hull's triangles, one face per plane, only the
/// vertices its faces use.
ConvexPolyhedron mergeFaces(const std::vector<Triangle>& triangles,
                            const std::vector<Eigen::Vector3d>& points, double tolerance) {
  std::vector<int> group_of;
  const std::vector<std::vector<int>> groups =
      coplanarGroups(triangles, points, tolerance, &group_of);
  ConvexPolyhedron hull;
  std::unordered_map<int, int> index;  // point -> vertex
  for (const std::vector<int>& group : groups) {
    Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
    for (const int t : group) {
      const Triangle& tri = triangles[t];
      weighted += (points[tri.v[1]] - points[tri.v[0]]).cross(points[tri.v[2]] - points[tri.v[0]]);
    }
    ConvexPolyhedron::Face face;
    face.normal = weighted.normalized();
    const std::vector<int> loop = boundaryLoop(triangles, group, group_of, points, tolerance);
    face.offset = 0.0;
    for (const int p : loop) {
      face.offset += face.normal.dot(points[p]) / static_cast<double>(loop.size());
      const auto inserted = index.emplace(p, static_cast<int>(hull.vertices.size()));
      if (inserted.second) hull.vertices.push_back(points[p]);
      face.loop.push_back(inserted.first->second);
    }
    hull.faces.push_back(std::move(face));
  }
  for (const ConvexPolyhedron::Face& face : hull.faces) {
    for (std::size_t i = 0; i < face.loop.size(); ++i) {
      const int a = face.loop[i], b = face.loop[(i + 1) % face.loop.size()];
      if (a < b) hull.edges.push_back({a, b});
    }
  }
  return hull;
}

}  // namespace

Status convexHull3d(const std::vector<Eigen::Vector3d>& points, ConvexPolyhedron* hull) {
  if (points.size() < 4)
    return Status::error("fewer than 4 points (" + std::to_string(points.size()) +
                         "): a hull needs 4 not on one plane");
  Eigen::AlignedBox3d box;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite())
      return Status::error("a point is not finite (point " + std::to_string(i) + ")");
    box.extend(points[i]);
  }
  const double tolerance = kRelativeTolerance * box.diagonal().norm();
  std::array<int, 4> simplex{};
  if (Status found = initialSimplex(points, tolerance, &simplex); !found) return found;
  // Repeated points (a mesh lists a corner once per triangle) add nothing.
  std::vector<int> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  auto less = [&](int a, int b) {
    return std::lexicographical_compare(points[a].data(), points[a].data() + 3, points[b].data(),
                                        points[b].data() + 3);
  };
  std::sort(order.begin(), order.end(), less);
  order.erase(
      std::unique(order.begin(), order.end(), [&](int a, int b) { return points[a] == points[b]; }),
      order.end());
  Quickhull quickhull(points, tolerance);
  quickhull.run(simplex, order);
  if (quickhull.failed())
    return Status::error("points too nearly coplanar in places for a hull in double precision");
  *hull = mergeFaces(quickhull.triangles(), points, tolerance);
  return Status::success();
}

}  // namespace brick_stack_sim
