#include "brick_stack_sim/core/geometry/convex_solid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "brick_stack_sim/core/geometry/polygon2d.h"
#include "geometry/polygon_clip.h"

namespace brick_stack_sim {

namespace {

/// Parallel within this [-], as box_contact.cpp: faces seen from both sides are one contact.
constexpr double kSameDirection = 1.0 - 1e-6;
/// Points closer than this many gaps are one [-], as box_contact.cpp.
constexpr double kSamePoint = 10.0;
/// Edge directions closer than this [rad] give one axis; crosses shorter give none.
constexpr double kParallel = 1e-9;

using Face = ConvexPolyhedron::Face;

/// The part's frame in the world; an identity part pose keeps the solid's
/// pose bit for bit (a product with it may turn -0 into +0).
Eigen::Isometry3d partPose(const Eigen::Isometry3d& pose, const ConvexPart& part) {
  return part.pose.matrix() == Eigen::Matrix4d::Identity() ? pose : pose * part.pose;
}

OrientedBox boxOf(const Eigen::Isometry3d& pose, const ConvexPart& part) {
  return OrientedBox{partPose(pose, part), part.box_half_extents};
}

/// The part's polyhedron moved by `pose` (the solid's) into the world.
ConvexPolyhedron placedPolyhedron(const Eigen::Isometry3d& pose, const ConvexPart& part) {
  ConvexPolyhedron placed = part.polyhedron.vertices.empty() && part.isBox()
                                ? boxPolyhedron(part.box_half_extents)
                                : part.polyhedron;
  const Eigen::Isometry3d to_world = partPose(pose, part);
  for (Eigen::Vector3d& v : placed.vertices) v = to_world * v;
  for (Face& face : placed.faces) {
    face.normal = to_world.linear() * face.normal;
    face.offset += face.normal.dot(to_world.translation());
  }
  return placed;
}

/// A placed solid's parts in the world, each moved once when first asked for.
class PlacedParts {
 public:
  explicit PlacedParts(const PlacedSolid& placed)
      : placed_(placed), cache_(placed.solid->parts.size()) {}
  std::size_t size() const { return cache_.size(); }
  const ConvexPart& part(std::size_t i) const { return placed_.solid->parts[i]; }
  OrientedBox box(std::size_t i) const { return boxOf(placed_.pose, part(i)); }
  const ConvexPolyhedron& polyhedron(std::size_t i) {
    if (!cache_[i]) cache_[i] = placedPolyhedron(placed_.pose, part(i));
    return *cache_[i];
  }

 private:
  const PlacedSolid& placed_;
  std::vector<std::optional<ConvexPolyhedron>> cache_;
};

/// Lowest and highest of `axis . v` over `vertices`.
Eigen::Vector2d projection(const std::vector<Eigen::Vector3d>& vertices,
                           const Eigen::Vector3d& axis) {
  Eigen::Vector2d range(std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity());
  for (const Eigen::Vector3d& v : vertices) {
    const double along = axis.dot(v);
    range = Eigen::Vector2d(std::min(range.x(), along), std::max(range.y(), along));
  }
  return range;
}

/// The polyhedron's edge directions, unit, one per family of parallel edges.
std::vector<Eigen::Vector3d> edgeDirections(const ConvexPolyhedron& polyhedron) {
  std::vector<Eigen::Vector3d> directions;
  for (const std::array<int, 2>& edge : polyhedron.edges) {
    Eigen::Vector3d d = (polyhedron.vertices[edge[1]] - polyhedron.vertices[edge[0]]).normalized();
    // One sign per line, so parallel edges sort next to each other.
    for (int k = 0; k < 3; ++k) {
      if (d[k] == 0.0) continue;
      if (d[k] < 0.0) d = -d;
      break;
    }
    directions.push_back(d);
  }
  std::sort(directions.begin(), directions.end(),
            [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
              return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
            });
  directions.erase(std::unique(directions.begin(), directions.end(),
                               [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
                                 return (a - b).norm() <= kParallel;
                               }),
                   directions.end());
  return directions;
}

/// The separating-axis gap of two convex polyhedra in the world [m].
double polyhedronSeparation(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  double largest_gap = -std::numeric_limits<double>::infinity();
  auto test_axis = [&](const Eigen::Vector3d& axis) {
    const Eigen::Vector2d along_a = projection(a.vertices, axis);
    const Eigen::Vector2d along_b = projection(b.vertices, axis);
    largest_gap = std::max({largest_gap, along_b.x() - along_a.y(), along_a.x() - along_b.y()});
  };
  for (const Face& face : a.faces) test_axis(face.normal);
  for (const Face& face : b.faces) test_axis(face.normal);
  const std::vector<Eigen::Vector3d> edges_b = edgeDirections(b);
  for (const Eigen::Vector3d& da : edgeDirections(a)) {
    for (const Eigen::Vector3d& db : edges_b) {
      const Eigen::Vector3d axis = da.cross(db);
      const double length = axis.norm();
      if (length > kParallel) test_axis(axis / length);
    }
  }
  return largest_gap;
}

std::vector<Eigen::Vector3d> loopPoints(const ConvexPolyhedron& polyhedron, const Face& face) {
  std::vector<Eigen::Vector3d> points;
  for (const int i : face.loop) points.push_back(polyhedron.vertices[i]);
  return points;
}

/// The face of `incident` turned most against `face` of `reference`, clipped
/// by the planes through the reference face's edges along its normal, `max_gap` outside them.
std::vector<Eigen::Vector3d> clippedIncidentFace(const ConvexPolyhedron& reference,
                                                 const Face& face, const ConvexPolyhedron& incident,
                                                 double max_gap) {
  const Face* against = &incident.faces.front();
  for (const Face& g : incident.faces)
    if (g.normal.dot(face.normal) < against->normal.dot(face.normal)) against = &g;
  std::vector<Eigen::Vector3d> polygon = loopPoints(incident, *against);
  const std::vector<Eigen::Vector3d> rim = loopPoints(reference, face);
  for (std::size_t i = 0; i < rim.size() && !polygon.empty(); ++i) {
    // Counter-clockwise seen from outside: the edge crossed with the normal points out.
    const Eigen::Vector3d side = (rim[(i + 1) % rim.size()] - rim[i]).cross(face.normal);
    if (side.norm() > 0.0) polygon = clipPolygon(polygon, side.normalized(), rim[i], max_gap);
  }
  return polygon;
}

/// The contacts across the faces of `reference` on which `incident` rests,
/// as contactsOnFaces() of box_contact.cpp; `towards_a` is +1 when
/// `reference` is part of b (normals point out of it).
void contactsOnFaces(const ConvexPolyhedron& reference, const ConvexPolyhedron& incident,
                     double towards_a, double max_gap, std::vector<BoxContactFace>* faces) {
  for (const Face& face : reference.faces) {
    const double nearest = projection(incident.vertices, face.normal).x() - face.offset;
    // The face's plane must separate the parts, touching within the gap.
    if (std::abs(nearest) > max_gap) continue;
    const Eigen::Vector3d normal = towards_a * face.normal;
    const bool seen = std::any_of(faces->begin(), faces->end(), [&](const BoxContactFace& f) {
      return f.normal.dot(normal) > kSameDirection;
    });
    if (seen) continue;
    BoxContactFace contact;
    contact.normal = normal;
    for (const Eigen::Vector3d& p : clippedIncidentFace(reference, face, incident, max_gap)) {
      const double depth = face.normal.dot(p) - face.offset;
      if (depth > max_gap) continue;
      // Clipping within the gap splits a corner on the face's rim in two.
      const Eigen::Vector3d on_plane = p - depth * face.normal;
      const bool duplicate =
          std::any_of(contact.points.begin(), contact.points.end(), [&](const Eigen::Vector3d& q) {
            return (q - on_plane).norm() <= kSamePoint * std::max(max_gap, 1e-9);
          });
      if (!duplicate) contact.points.push_back(on_plane);
    }
    if (!contact.points.empty()) faces->push_back(std::move(contact));
  }
}

/// The overlap of `upper_face` resting on `lower_face` (their polyhedra
/// `upper` and `lower`), worked out in the lower face's plane; empty when not flush.
std::vector<Eigen::Vector3d> flushOverlap(const ConvexPolyhedron& lower, const Face& lower_face,
                                          const ConvexPolyhedron& upper, const Face& upper_face,
                                          const Eigen::Vector3d& upper_centre, double max_gap) {
  const std::vector<Eigen::Vector3d> upper_points = loopPoints(upper, upper_face);
  Eigen::Vector3d middle = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : upper_points) middle += p / upper_points.size();
  const Eigen::Vector3d& n = lower_face.normal;
  if (std::abs(n.dot(middle) - lower_face.offset) > max_gap) return {};
  if (n.dot(upper_centre) - lower_face.offset <= 0.0) return {};
  const Eigen::Vector3d origin = n * lower_face.offset;
  const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
  auto in_plane = [&](const std::vector<Eigen::Vector3d>& points) {
    std::vector<Eigen::Vector2d> flat;
    for (const Eigen::Vector3d& p : points) flat.emplace_back(u.dot(p - origin), v.dot(p - origin));
    return convexHull(flat);
  };
  const Polygon2d overlap =
      intersectConvex(in_plane(upper_points), in_plane(loopPoints(lower, lower_face)));
  std::vector<Eigen::Vector3d> patch;
  for (const Eigen::Vector2d& c : overlap) patch.push_back(origin + c.x() * u + c.y() * v);
  return patch;
}

/// flushContactPatch() of two convex parts in the world.
bool polyhedronFlushPatch(const ConvexPolyhedron& lower, const ConvexPolyhedron& upper,
                          double max_angle, double max_gap, std::vector<Eigen::Vector3d>* patch,
                          Eigen::Vector3d* normal) {
  Eigen::Vector3d upper_centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : upper.vertices) upper_centre += p / upper.vertices.size();
  const double least_cos = std::cos(max_angle);
  for (const Face& f : lower.faces) {
    if (f.normal.z() <= 0.0) continue;  // a face that looks down carries nothing
    for (const Face& g : upper.faces) {
      if (f.normal.dot(-g.normal) < least_cos) continue;
      *patch = flushOverlap(lower, f, upper, g, upper_centre, max_gap);
      if (patch->empty()) continue;
      *normal = f.normal;
      return true;  // convex parts touch across one plane only
    }
  }
  return false;
}

/// The point of a face (its rim, counter-clockwise about `normal`) nearest `point`.
Eigen::Vector3d nearestOnFace(const std::vector<Eigen::Vector3d>& rim,
                              const Eigen::Vector3d& normal, const Eigen::Vector3d& point) {
  const Eigen::Vector3d projected = point - normal.dot(point - rim[0]) * normal;
  bool inside = true;
  for (std::size_t i = 0; i < rim.size() && inside; ++i)
    inside = (rim[(i + 1) % rim.size()] - rim[i]).cross(normal).dot(projected - rim[i]) <= 0.0;
  if (inside) return projected;
  Eigen::Vector3d nearest = rim[0];
  for (std::size_t i = 0; i < rim.size(); ++i) {
    const Eigen::Vector3d& p = rim[i];
    const Eigen::Vector3d edge = rim[(i + 1) % rim.size()] - p;
    const double squared = edge.squaredNorm();
    const double t = squared > 0.0 ? std::clamp((point - p).dot(edge) / squared, 0.0, 1.0) : 0.0;
    const Eigen::Vector3d on_edge = p + t * edge;
    if ((on_edge - point).squaredNorm() < (nearest - point).squaredNorm()) nearest = on_edge;
  }
  return nearest;
}

/// The point of a convex polyhedron in the world nearest `point`: the
/// nearest on the faces it lies above, since the solid's nearest point lies
/// on a face whose plane separates it from `point`.
Eigen::Vector3d nearestPointInPolyhedron(const ConvexPolyhedron& polyhedron,
                                         const Eigen::Vector3d& point) {
  Eigen::Vector3d best = point;  // above no face: inside
  double best_squared = std::numeric_limits<double>::infinity();
  for (const Face& face : polyhedron.faces) {
    if (face.normal.dot(point) - face.offset <= 0.0) continue;
    const Eigen::Vector3d nearest = nearestOnFace(loopPoints(polyhedron, face), face.normal, point);
    if ((nearest - point).squaredNorm() < best_squared) {
      best_squared = (nearest - point).squaredNorm();
      best = nearest;
    }
  }
  return best;
}

}  // namespace

ConvexSolid boxSolid(const Eigen::Vector3d& half_extents) {
  ConvexPart part;
  part.polyhedron = boxPolyhedron(half_extents);
  part.box_half_extents = half_extents;
  return ConvexSolid{{std::move(part)}};
}

ConvexSolid polyhedronSolid(ConvexPolyhedron polyhedron) {
  ConvexPart part;
  part.polyhedron = std::move(polyhedron);
  return ConvexSolid{{std::move(part)}};
}

Eigen::AlignedBox3d bounds(const PlacedSolid& placed) {
  Eigen::AlignedBox3d result;
  PlacedParts parts(placed);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (parts.part(i).isBox()) {
      result.extend(bounds(parts.box(i)));
    } else {
      for (const Eigen::Vector3d& v : parts.polyhedron(i).vertices) result.extend(v);
    }
  }
  return result;
}

Eigen::Vector2d extentAlong(const PlacedSolid& placed, const Eigen::Vector3d& axis) {
  Eigen::Vector2d range(std::numeric_limits<double>::infinity(),
                        -std::numeric_limits<double>::infinity());
  PlacedParts parts(placed);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    Eigen::Vector2d along;
    if (parts.part(i).isBox()) {
      const OrientedBox box = parts.box(i);
      const double centre = box.pose.translation().dot(axis), reach = projectedRadius(box, axis);
      along = Eigen::Vector2d(centre - reach, centre + reach);
    } else {
      along = projection(parts.polyhedron(i).vertices, axis);
    }
    range = Eigen::Vector2d(std::min(range.x(), along.x()), std::max(range.y(), along.y()));
  }
  return range;
}

double thinnestHalfWidth(const ConvexSolid& solid) {
  double least = std::numeric_limits<double>::infinity();
  for (const ConvexPart& part : solid.parts) {
    if (part.isBox()) {
      least = std::min(least, part.box_half_extents.minCoeff());
      continue;
    }
    for (const Face& face : part.polyhedron.faces) {
      const double width = face.offset - projection(part.polyhedron.vertices, face.normal).x();
      least = std::min(least, 0.5 * width);
    }
  }
  return solid.parts.empty() ? 0.0 : least;
}

double radiusAbout(const ConvexSolid& solid, const Eigen::Vector3d& centre) {
  double largest = 0.0;
  for (const ConvexPart& part : solid.parts) {
    const std::vector<Eigen::Vector3d> vertices =
        placedPolyhedron(Eigen::Isometry3d::Identity(), part).vertices;
    for (const Eigen::Vector3d& v : vertices) largest = std::max(largest, (v - centre).norm());
  }
  return largest;
}

double separation(const PlacedSolid& a, const PlacedSolid& b) {
  double least = std::numeric_limits<double>::infinity();
  PlacedParts parts_a(a), parts_b(b);
  for (std::size_t i = 0; i < parts_a.size(); ++i) {
    for (std::size_t j = 0; j < parts_b.size(); ++j) {
      const double gap = parts_a.part(i).isBox() && parts_b.part(j).isBox()
                             ? separation(parts_a.box(i), parts_b.box(j))
                             : polyhedronSeparation(parts_a.polyhedron(i), parts_b.polyhedron(j));
      least = std::min(least, gap);
    }
  }
  return least;
}

Eigen::Vector3d nearestPointIn(const PlacedSolid& placed, const Eigen::Vector3d& point) {
  Eigen::Vector3d best = point;
  double best_squared = std::numeric_limits<double>::infinity();
  PlacedParts parts(placed);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const Eigen::Vector3d nearest = parts.part(i).isBox()
                                        ? nearestPointIn(parts.box(i), point)
                                        : nearestPointInPolyhedron(parts.polyhedron(i), point);
    if ((nearest - point).squaredNorm() < best_squared) {
      best_squared = (nearest - point).squaredNorm();
      best = nearest;
    }
  }
  return best;
}

std::vector<BoxContactFace> touchingContacts(const PlacedSolid& a, const PlacedSolid& b,
                                             double max_gap) {
  std::vector<BoxContactFace> faces;
  PlacedParts parts_a(a), parts_b(b);
  for (std::size_t i = 0; i < parts_a.size(); ++i) {
    for (std::size_t j = 0; j < parts_b.size(); ++j) {
      // Each pair of parts reports its own faces: two parts resting on one
      // plane are two contacts.
      std::vector<BoxContactFace> pair;
      if (parts_a.part(i).isBox() && parts_b.part(j).isBox()) {
        pair = touchingContacts(parts_a.box(i), parts_b.box(j), max_gap);
      } else {
        contactsOnFaces(parts_b.polyhedron(j), parts_a.polyhedron(i), 1.0, max_gap, &pair);
        contactsOnFaces(parts_a.polyhedron(i), parts_b.polyhedron(j), -1.0, max_gap, &pair);
      }
      faces.insert(faces.end(), std::make_move_iterator(pair.begin()),
                   std::make_move_iterator(pair.end()));
    }
  }
  return faces;
}

bool flushContactPatch(const PlacedSolid& lower, const PlacedSolid& upper, double max_angle,
                       double max_gap, std::vector<Eigen::Vector3d>* patch,
                       Eigen::Vector3d* normal) {
  // A box on a box, the common case, without walking parts: the contact
  // stage asks this of every resting pair every step.
  const std::vector<ConvexPart>& lower_parts = lower.solid->parts;
  const std::vector<ConvexPart>& upper_parts = upper.solid->parts;
  if (lower_parts.size() == 1 && upper_parts.size() == 1 && lower_parts[0].isBox() &&
      upper_parts[0].isBox())
    return flushContactPatch(boxOf(lower.pose, lower_parts[0]), boxOf(upper.pose, upper_parts[0]),
                             max_angle, max_gap, patch, normal);
  std::vector<Eigen::Vector3d> found;
  std::optional<Eigen::Vector3d> first_normal;
  PlacedParts parts_l(lower), parts_u(upper);
  for (std::size_t i = 0; i < parts_l.size(); ++i) {
    for (std::size_t j = 0; j < parts_u.size(); ++j) {
      std::vector<Eigen::Vector3d> pair;
      Eigen::Vector3d pair_normal;
      const bool flush = parts_l.part(i).isBox() && parts_u.part(j).isBox()
                             ? flushContactPatch(parts_l.box(i), parts_u.box(j), max_angle, max_gap,
                                                 &pair, &pair_normal)
                             : polyhedronFlushPatch(parts_l.polyhedron(i), parts_u.polyhedron(j),
                                                    max_angle, max_gap, &pair, &pair_normal);
      if (!flush) continue;
      if (!first_normal) first_normal = pair_normal;
      found.insert(found.end(), pair.begin(), pair.end());
    }
  }
  if (!first_normal) return false;
  *patch = std::move(found);
  if (normal) *normal = *first_normal;
  return true;
}

}  // namespace brick_stack_sim
