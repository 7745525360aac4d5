#include "brick_stack_sim/core/geometry/convex_polyhedron.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace brick_stack_sim {

namespace {

/// Each undirected edge of the faces' loops once, smaller index first.
std::vector<std::array<int, 2>> edgesOfLoops(const std::vector<ConvexPolyhedron::Face>& faces) {
  std::vector<std::array<int, 2>> edges;
  for (const ConvexPolyhedron::Face& face : faces) {
    for (std::size_t i = 0; i < face.loop.size(); ++i) {
      const int a = face.loop[i], b = face.loop[(i + 1) % face.loop.size()];
      // A closed surface walks every edge once each way: keep one direction.
      if (a < b) edges.push_back({a, b});
    }
  }
  return edges;
}

ConvexPolyhedron::Face makeFace(const Eigen::Vector3d& normal, double offset,
                                std::vector<int> loop) {
  ConvexPolyhedron::Face face;
  face.normal = normal;
  face.offset = offset;
  face.loop = std::move(loop);
  return face;
}

}  // namespace

ConvexPolyhedron boxPolyhedron(const Eigen::Vector3d& half_extents) {
  ConvexPolyhedron box;
  // Vertex i has sign +1 along axis k when bit k of i is set, as corners() numbers them.
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d sign((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    box.vertices.push_back(sign.cwiseProduct(half_extents));
  }
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const int bu = 1 << u, bv = 1 << v, bit = 1 << axis;
    for (const int side : {1, -1}) {
      const int base = side > 0 ? bit : 0;
      // (u, v, axis) is right-handed: u then v turns counter-clockwise about +axis.
      std::vector<int> loop = {base, base + bu, base + bu + bv, base + bv};
      if (side < 0) std::reverse(loop.begin(), loop.end());
      Eigen::Vector3d normal = Eigen::Vector3d::Zero();
      normal[axis] = side;
      box.faces.push_back(makeFace(normal, half_extents[axis], std::move(loop)));
    }
  }
  box.edges = edgesOfLoops(box.faces);
  return box;
}

ConvexPolyhedron cylinderPolyhedron(double radius, double length, int sides) {
  ConvexPolyhedron prism;
  const double half_length = 0.5 * length;
  const double step = 2.0 * M_PI / sides;
  // Vertices 0..n-1 on the bottom rim, n..2n-1 above them on the top rim.
  for (const double z : {-half_length, half_length}) {
    for (int i = 0; i < sides; ++i)
      prism.vertices.emplace_back(radius * std::cos(i * step), radius * std::sin(i * step), z);
  }
  std::vector<int> bottom, top;
  for (int i = 0; i < sides; ++i) {
    bottom.push_back(sides - 1 - i);  // seen from below, clockwise from above
    top.push_back(sides + i);
  }
  prism.faces.push_back(makeFace(-Eigen::Vector3d::UnitZ(), half_length, std::move(bottom)));
  prism.faces.push_back(makeFace(Eigen::Vector3d::UnitZ(), half_length, std::move(top)));
  const double apothem = radius * std::cos(0.5 * step);
  for (int i = 0; i < sides; ++i) {
    const int next = (i + 1) % sides;
    const double angle = (i + 0.5) * step;
    const Eigen::Vector3d normal(std::cos(angle), std::sin(angle), 0.0);
    // Along the rim then up: the tangent crossed with +z is the outward normal.
    prism.faces.push_back(makeFace(normal, apothem, {i, next, sides + next, sides + i}));
  }
  prism.edges = edgesOfLoops(prism.faces);
  return prism;
}

int cylinderSides(double radius, double max_sag) {
  constexpr int kFewest = 16;
  constexpr int kMost = 256;  // beyond this the sag is below a micrometre at brick scale
  for (int sides = kFewest; sides < kMost; sides += 2) {
    if (radius * (1.0 - std::cos(M_PI / sides)) <= max_sag) return sides;
  }
  return kMost;
}

SolidMass solidMass(const ConvexPolyhedron& polyhedron) {
  SolidMass mass;
  if (polyhedron.vertices.empty()) return mass;
  // Tetrahedra from a point inside: coordinates stay small, sums do not cancel.
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : polyhedron.vertices) reference += v;
  reference /= static_cast<double>(polyhedron.vertices.size());
  double volume = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const ConvexPolyhedron::Face& face : polyhedron.faces) {
    const Eigen::Vector3d a = polyhedron.vertices[face.loop[0]] - reference;
    for (std::size_t i = 1; i + 1 < face.loop.size(); ++i) {
      const Eigen::Vector3d b = polyhedron.vertices[face.loop[i]] - reference;
      const Eigen::Vector3d c = polyhedron.vertices[face.loop[i + 1]] - reference;
      // The tetrahedron (0, a, b, c): signed volume, and its integral of x x^T,
      // V/20 (sum of v v^T over its vertices + s s^T), s the vertices' sum.
      const double v = a.dot(b.cross(c)) / 6.0;
      const Eigen::Vector3d s = a + b + c;
      volume += v;
      first += v * s / 4.0;
      second += v / 20.0 *
                (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
    }
  }
  mass.volume = volume;
  if (volume <= 0.0) return mass;
  const Eigen::Vector3d shift = first / volume;
  mass.centroid = reference + shift;
  const Eigen::Matrix3d about_centroid = second - volume * shift * shift.transpose();
  mass.inertia = about_centroid.trace() * Eigen::Matrix3d::Identity() - about_centroid;
  return mass;
}

}  // namespace brick_stack_sim
