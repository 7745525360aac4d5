#include "brick_stack_sim/core/geometry/load_distribution.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace brick_stack_sim {

namespace {

/// Slack for "inside a patch" when checking a share's point of action [m]:
/// far below any length that matters for a brick, far above rounding.
constexpr double kInsideTolerance = 1e-9;

bool leverRule(double mass, const Eigen::Vector2d& point, const std::vector<Polygon2d>& patches,
               std::vector<LoadShare>* shares) {
  const Eigen::Vector2d a = centroid(patches[0]), b = centroid(patches[1]);
  const Eigen::Vector2d axis = b - a;
  const double length_squared = axis.squaredNorm();
  if (length_squared <= 0.0) return false;
  const double t = (point - a).dot(axis) / length_squared;
  if (t < 0.0 || t > 1.0) return false;
  // The part of the load's position across the centre line moves both points
  // of action by the same amount, which balances the moment about that line.
  const Eigen::Vector2d across = point - (a + t * axis);
  const LoadShare first{mass * (1.0 - t), a + across}, second{mass * t, b + across};
  if ((first.mass > 0.0 && !contains(patches[0], first.point, kInsideTolerance)) ||
      (second.mass > 0.0 && !contains(patches[1], second.point, kInsideTolerance)))
    return false;
  *shares = {first, second};
  return true;
}

/// Shares at the patch centres closest to an equal split (least squares) with
/// force and moment balance as constraints; supporters that would have to pull
/// are dropped one at a time (a bounded active set).
bool leastNorm(double mass, const Eigen::Vector2d& point, const std::vector<Polygon2d>& patches,
               std::vector<LoadShare>* shares) {
  const int count = static_cast<int>(patches.size());
  std::vector<Eigen::Vector2d> centres;
  for (const Polygon2d& patch : patches) centres.push_back(centroid(patch));
  std::vector<bool> active(count, true);
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(count);
  for (int round = 0; round < count; ++round) {
    std::vector<int> index;
    for (int i = 0; i < count; ++i)
      if (active[i]) index.push_back(i);
    const int n = static_cast<int>(index.size());
    if (n == 0) return false;
    Eigen::MatrixXd constraints(3, n);
    for (int j = 0; j < n; ++j)
      constraints.col(j) << 1.0, centres[index[j]].x(), centres[index[j]].y();
    const Eigen::Vector3d target(mass, mass * point.x(), mass * point.y());
    const Eigen::VectorXd equal = Eigen::VectorXd::Constant(n, mass / n);
    const Eigen::VectorXd correction =
        constraints.completeOrthogonalDecomposition().solve(target - constraints * equal);
    const Eigen::VectorXd solution = equal + correction;
    // Collinear centres cannot balance a load off their line.
    if ((constraints * solution - target).norm() > 1e-9 * std::max(mass, 1e-12)) return false;
    int most_negative = -1;
    for (int j = 0; j < n; ++j)
      if (solution[j] < 0.0 && (most_negative < 0 || solution[j] < solution[most_negative]))
        most_negative = j;
    if (most_negative < 0) {
      forces.setZero();
      for (int j = 0; j < n; ++j) forces[index[j]] = solution[j];
      shares->assign(count, LoadShare{});
      for (int i = 0; i < count; ++i) (*shares)[i] = LoadShare{forces[i], centres[i]};
      return true;
    }
    active[index[most_negative]] = false;
  }
  return false;
}

bool onePatchCarries(double mass, const Eigen::Vector2d& point,
                     const std::vector<Polygon2d>& patches, std::vector<LoadShare>* shares) {
  int best = -1;
  double best_margin = 0.0;
  for (int i = 0; i < static_cast<int>(patches.size()); ++i) {
    const double margin = signedDistance(patches[i], point);
    if (margin >= -kInsideTolerance && (best < 0 || margin > best_margin)) {
      best = i;
      best_margin = margin;
    }
  }
  if (best < 0) return false;
  shares->assign(patches.size(), LoadShare{});
  (*shares)[best] = LoadShare{mass, point};
  return true;
}

/// Always succeeds when `point` is inside the combined hull: some triangle of
/// a fan over the hull's corners contains it, and its barycentric weights are
/// a balanced split over (at most three) patches.
bool hullTriangle(double mass, const Eigen::Vector2d& point, const std::vector<Polygon2d>& patches,
                  std::vector<LoadShare>* shares) {
  std::vector<Eigen::Vector2d> corners;
  std::vector<int> owner;
  for (int i = 0; i < static_cast<int>(patches.size()); ++i)
    for (const Eigen::Vector2d& corner : patches[i]) {
      corners.push_back(corner);
      owner.push_back(i);
    }
  const Polygon2d hull = convexHull(corners);
  if (hull.size() < 3) return false;
  auto owner_of = [&](const Eigen::Vector2d& vertex) {
    for (std::size_t k = 0; k < corners.size(); ++k)
      if (corners[k] == vertex) return owner[k];
    return -1;
  };
  for (std::size_t i = 1; i + 1 < hull.size(); ++i) {
    const Eigen::Vector2d &a = hull[0], &b = hull[i], &c = hull[i + 1];
    Eigen::Matrix2d basis;
    basis.col(0) = b - a;
    basis.col(1) = c - a;
    const Eigen::Vector2d uv = basis.fullPivLu().solve(point - a);
    const double w[3] = {1.0 - uv.x() - uv.y(), uv.x(), uv.y()};
    if (std::min({w[0], w[1], w[2]}) < -1e-12) continue;
    shares->assign(patches.size(), LoadShare{});
    const Eigen::Vector2d* vertex[3] = {&a, &b, &c};
    std::vector<Eigen::Vector2d> moment(patches.size(), Eigen::Vector2d::Zero());
    for (int k = 0; k < 3; ++k) {
      const int patch = owner_of(*vertex[k]);
      const double weight = std::max(w[k], 0.0);
      (*shares)[patch].mass += mass * weight;
      moment[patch] += mass * weight * *vertex[k];
    }
    for (std::size_t p = 0; p < patches.size(); ++p)
      if ((*shares)[p].mass > 0.0) (*shares)[p].point = moment[p] / (*shares)[p].mass;
    return true;
  }
  return false;
}

}  // namespace

LoadSplitRule distributeLoad(double mass, const Eigen::Vector2d& point,
                             const std::vector<Polygon2d>& patches,
                             std::vector<LoadShare>* shares) {
  shares->clear();
  if (patches.empty()) return LoadSplitRule::kUnsupported;
  if (patches.size() == 1) {
    if (!contains(patches[0], point, kInsideTolerance)) return LoadSplitRule::kUnsupported;
    shares->push_back(LoadShare{mass, point});
    return LoadSplitRule::kSingleSupporter;
  }
  if (patches.size() == 2 && leverRule(mass, point, patches, shares))
    return LoadSplitRule::kLeverRule;
  if (patches.size() >= 3 && leastNorm(mass, point, patches, shares))
    return LoadSplitRule::kLeastNorm;
  if (onePatchCarries(mass, point, patches, shares)) return LoadSplitRule::kOnePatchCarries;
  if (hullTriangle(mass, point, patches, shares)) return LoadSplitRule::kHullTriangle;
  shares->clear();
  return LoadSplitRule::kUnsupported;
}

}  // namespace brick_stack_sim
