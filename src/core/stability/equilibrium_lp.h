#pragma once
// The rigid-block statics LP in Clp's column form, and its solves: the
// dual simplex (from a basis when given) and the barrier. Included by
// rigid_block_statics.cpp only, which keeps Clp's types out of its header.

#include <algorithm>
#include <vector>

#include <Eigen/Geometry>
#include <coin/ClpSimplex.hpp>
#include <coin/ClpSolve.hpp>

#include "stability/rigid_block_statics.h"

namespace brick_stack_sim {

/// The LP in Clp's column form. Rows: 6 per free body (force x, y, z, then
/// torque about its COM x, y, z), in units of the largest load on a free
/// body (its weight or an applied force) and (for torques) the problem's size, so Clp's absolute
/// tolerances mean the same at any brick size.
class EquilibriumLp {
 public:
  EquilibriumLp(const std::vector<StaticsBody>& bodies, const StaticsOptions& options)
      : bodies_(bodies), row_of_(bodies.size(), -1) {
    int rows = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (bodies[i].fixed) continue;
      row_of_[i] = rows;
      rows += 6;
      weight_unit_ = std::max(
          {weight_unit_, bodies[i].mass * options.gravity, bodies[i].applied_force.norm()});
    }
    row_count_ = rows;
    load_direction_ =
        Eigen::Vector3d(0.0, 0.0, -1.0) + options.extra_acceleration / options.gravity;
    gravity_ = options.gravity;
    column_start_.push_back(0);
  }

  int rowCount() const { return row_count_; }
  int columnCount() const { return static_cast<int>(column_start_.size()) - 1; }
  double weightUnit() const { return weight_unit_; }
  int rowOf(int body) const { return body < 0 ? -1 : row_of_[body]; }
  bool free(int body) const { return rowOf(body) >= 0; }

  /// The size that turns torques into forces: the largest lever of any contact.
  void measureLevers(const std::vector<StaticsContact>& contacts) {
    for (const StaticsContact& c : contacts) {
      for (int body : {c.a, c.b})
        if (free(body)) length_unit_ = std::max(length_unit_, (c.point - bodies_[body].com).norm());
    }
  }

  /// A column for a force `direction` [unit force] applied at `point` on `a`
  /// and its reaction on `b`.
  void addForceColumn(const StaticsContact& c, const Eigen::Vector3d& direction, double cost) {
    addForceOn(c.a, c.point, direction);
    addForceOn(c.b, c.point, -direction);
    closeColumn(0.0, COIN_DBL_MAX, cost);
  }

  /// A column for the extra load `acceleration` times every free body's
  /// mass, scaled by the column's value [m/s^2].
  void addLoadColumn(const Eigen::Vector3d& direction, double upper, double cost) {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      if (!free(static_cast<int>(i))) continue;
      const Eigen::Vector3d load = bodies_[i].mass * gravity_ / weight_unit_ * direction;
      for (int k = 0; k < 3; ++k) add(row_of_[i] + k, load[k]);
    }
    closeColumn(0.0, upper, cost);
  }

  /// Two columns per row (surplus and deficit) that absorb any imbalance at
  /// a unit cost each.
  void addImbalanceColumns() {
    for (int row = 0; row < row_count_; ++row) {
      for (double sign : {1.0, -1.0}) {
        add(row, sign);
        closeColumn(0.0, COIN_DBL_MAX, 1.0);
      }
    }
  }

  /// Row bounds: what the contacts must supply for each free body, in units
  /// of the weight unit: minus its load.
  void rowBounds(std::vector<double>* bounds) const {
    bounds->assign(row_count_, 0.0);
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      if (!free(static_cast<int>(i))) continue;
      const StaticsBody& body = bodies_[i];
      const Eigen::Vector3d load =
          (body.mass * gravity_ * load_direction_ + body.applied_force) / weight_unit_;
      const Eigen::Vector3d torque = body.applied_torque / (weight_unit_ * length_unit_);
      for (int k = 0; k < 3; ++k) {
        (*bounds)[row_of_[i] + k] = -load[k];
        (*bounds)[row_of_[i] + 3 + k] = -torque[k];
      }
    }
  }

  /// Solves from Clp's slack basis, or from `start` (a status per column,
  /// then per row, as ClpSimplex::Status) when given.
  bool solve(ClpSimplex* model, const std::vector<unsigned char>* start = nullptr,
             int* iterations = nullptr) const {
    load(model);
    if (start && start->size() == static_cast<std::size_t>(columnCount() + row_count_)) {
      // Clp repairs a basis with too many or too few basic variables when it
      // factorizes: slacks fill in, surplus columns leave.
      model->createStatus();
      for (int c = 0; c < columnCount(); ++c)
        model->setColumnStatus(c, static_cast<ClpSimplex::Status>((*start)[c]));
      for (int r = 0; r < row_count_; ++r)
        model->setRowStatus(r, static_cast<ClpSimplex::Status>((*start)[columnCount() + r]));
    }
    // The rows are already in units of weight and size; Clp's own scaling
    // has been seen to stop at a scaled optimum that is not one unscaled
    // (secondary status 3) on a plank over a brick.
    model->scaling(0);
    model->dual();
    if (iterations) *iterations = model->getIterationCount();
    // Whatever the dual left unfinished, the primal finishes from its basis.
    if (!model->isProvenOptimal() || model->secondaryStatus() != 0) {
      model->primal(1);
      if (iterations) *iterations += model->getIterationCount();
    }
    return model->isProvenOptimal() && model->secondaryStatus() == 0;
  }

  /// Solves by Clp's barrier with presolve, from no basis. Without the
  /// crossover the answer is an interior point: its least imbalance is
  /// exact, its forces are one admissible set, but it has no basis and its
  /// duals name no single mechanism. With it, a vertex as solve() leaves.
  bool solveByBarrier(ClpSimplex* model, bool crossover, int* iterations) const {
    load(model);
    model->scaling(0);  // as solve(): the rows are in units already
    ClpSolve how;
    how.setSolveType(crossover ? ClpSolve::useBarrier : ClpSolve::useBarrierNoCross);
    how.setPresolveType(ClpSolve::presolveOn);
    model->initialSolve(how);
    if (iterations) *iterations += model->getIterationCount();
    if (crossover && (!model->isProvenOptimal() || model->secondaryStatus() != 0)) {
      model->primal(1);
      if (iterations) *iterations += model->getIterationCount();
    }
    return model->isProvenOptimal() && model->secondaryStatus() == 0;
  }

  int freeBodyCount() const { return row_count_ / 6; }

 private:
  /// The problem into `model`, to be minimised.
  void load(ClpSimplex* model) const {
    std::vector<double> bounds;
    rowBounds(&bounds);
    model->setLogLevel(0);
    model->loadProblem(columnCount(), row_count_, column_start_.data(), row_index_.data(),
                       value_.data(), column_lower_.data(), column_upper_.data(), cost_.data(),
                       bounds.data(), bounds.data());
    model->setOptimizationDirection(1.0);
  }
  void addForceOn(int body, const Eigen::Vector3d& point, const Eigen::Vector3d& direction) {
    if (!free(body)) return;
    const int row = row_of_[body];
    const Eigen::Vector3d torque = (point - bodies_[body].com).cross(direction) / length_unit_;
    for (int k = 0; k < 3; ++k) {
      add(row + k, direction[k]);
      add(row + 3 + k, torque[k]);
    }
  }
  void add(int row, double value) {
    if (value == 0.0) return;
    row_index_.push_back(row);
    value_.push_back(value);
  }
  void closeColumn(double lower, double upper, double cost) {
    column_start_.push_back(static_cast<CoinBigIndex>(row_index_.size()));
    column_lower_.push_back(lower);
    column_upper_.push_back(upper);
    cost_.push_back(cost);
  }

  const std::vector<StaticsBody>& bodies_;
  std::vector<int> row_of_;
  int row_count_ = 0;
  double weight_unit_ = 0.0;
  double length_unit_ = 1e-9;
  double gravity_ = 9.81;
  Eigen::Vector3d load_direction_;
  std::vector<CoinBigIndex> column_start_;
  std::vector<int> row_index_;
  std::vector<double> value_, column_lower_, column_upper_, cost_;
};

}  // namespace brick_stack_sim
