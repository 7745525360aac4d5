#include "stability/support_evaluation.h"

#include <algorithm>

namespace brick_stack_sim {

void evaluateSupport(const Eigen::Vector3d& load_point, BrickStability* s) {
  std::vector<Eigen::Vector2d> all_points;
  double height_sum = 0.0;
  std::size_t point_count = 0;
  for (SupportPatch& patch : s->supports) {
    std::vector<Eigen::Vector2d> projected;
    patch.height = 0.0;
    for (const Eigen::Vector3d& p : patch.points) {
      projected.push_back(p.head<2>());
      patch.height += p.z();
    }
    patch.height /= std::max<std::size_t>(patch.points.size(), 1);
    patch.hull = convexHull(projected);
    all_points.insert(all_points.end(), projected.begin(), projected.end());
    height_sum += patch.height * patch.points.size();
    point_count += patch.points.size();
  }
  s->combined_hull = convexHull(all_points);
  s->support_height = point_count ? height_sum / point_count : 0.0;
  s->com_above = load_point;
  // Resting on nothing has no hull to measure against: margin 0, next to an
  // empty list of supporters, rather than an infinity nobody can publish.
  s->margin = s->supports.empty() ? 0.0 : signedDistance(s->combined_hull, load_point.head<2>());
}

std::vector<BodyHandle> supportersOf(const BrickStability& stability) {
  std::vector<BodyHandle> handles;
  for (const SupportPatch& patch : stability.supports) handles.push_back(patch.supporter);
  for (const SupportPatch& patch : stability.side_contacts) handles.push_back(patch.supporter);
  std::sort(handles.begin(), handles.end());
  handles.erase(std::unique(handles.begin(), handles.end()), handles.end());
  return handles;
}

}  // namespace brick_stack_sim
