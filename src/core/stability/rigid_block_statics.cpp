#include "stability/rigid_block_statics.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <coin/ClpSimplex.hpp>
#include <coin/ClpSolve.hpp>

namespace brick_stack_sim {

namespace {

/// A body whose dual velocity (at most 1) exceeds this moves in the
/// mechanism; below it is the simplex's rounding.
constexpr double kMoving = 1e-7;
/// Names a basis remembers before it starts again from the last problem's
/// alone (about 6 MB): three LPs of groups of 500 planks.
constexpr std::size_t kRememberedNames = 100000;

/// Free bodies from which an LP the kept basis knows little of is solved
/// by Clp's barrier (an interior-point method) instead of the dual simplex.
/// On a settled pile's group of 731 planks (4 386 rows, 52 324 columns)
/// the dual simplex took 11.5 s from the slack basis, the barrier without a
/// crossover 0.41 s and with one 1.7 s. A problem asked again (a component
/// whose loads changed) is re-solved from its basis in a few pivots, which
/// no barrier beats: on pile500 the barrier for those too made the
/// stability stage eight times dearer.
constexpr int kBarrierBodies = 200;
/// The share of a problem's free bodies the basis must know for the
/// simplex to start from it [-].
constexpr double kKnownForWarmStart = 0.5;

/// Sine of a contact normal's tilt from vertical [-] above which its
/// pyramid is turned to the slope (1.1 degrees): on flatter contacts a
/// brick's weight asks for at most 2 % of the normal force in friction.
constexpr double kTiltedContact = 0.02;

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
    std::vector<double> bounds;
    rowBounds(&bounds);
    model->setLogLevel(0);
    model->loadProblem(columnCount(), row_count_, column_start_.data(), row_index_.data(),
                       value_.data(), column_lower_.data(), column_upper_.data(), cost_.data(),
                       bounds.data(), bounds.data());
    model->setOptimizationDirection(1.0);
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
    std::vector<double> bounds;
    rowBounds(&bounds);
    model->setLogLevel(0);
    model->loadProblem(columnCount(), row_count_, column_start_.data(), row_index_.data(),
                       value_.data(), column_lower_.data(), column_upper_.data(), cost_.data(),
                       bounds.data(), bounds.data());
    model->setOptimizationDirection(1.0);
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

/// The edges of the pyramid inscribed in the friction cone of `c`, unit
/// normal force each; just the normal when there is no friction.
std::vector<Eigen::Vector3d> coneEdges(const StaticsContact& c, int faces) {
  const Eigen::Vector3d n = c.normal.normalized();
  if (c.friction <= 0.0) return {n};
  // On a tilted contact an edge lies along the plane's steepest slope: the
  // friction that holds a brick's weight there is exact, as Coulomb's cone
  // holds it, not cos(pi / faces) of it (a plank lying on a leaning one
  // near the friction angle, which the engine holds, was refused).
  // Elsewhere the edges follow the world axes projected on the plane:
  // exact for friction along a brick's axes, the usual direction in a stack.
  Eigen::Vector3d t1 = Eigen::Vector3d::UnitZ() - n.z() * n;
  if (t1.norm() < kTiltedContact) t1 = Eigen::Vector3d::UnitX() - n.x() * n;
  if (t1.norm() < 0.3) t1 = Eigen::Vector3d::UnitY() - n.y() * n;
  t1.normalize();
  const Eigen::Vector3d t2 = n.cross(t1);
  std::vector<Eigen::Vector3d> edges;
  for (int j = 0; j < faces; ++j) {
    const double angle = 2.0 * M_PI * j / faces;
    edges.push_back(n + c.friction * (std::cos(angle) * t1 + std::sin(angle) * t2));
  }
  return edges;
}

/// Adds one column per cone edge of every contact touching a free body;
/// returns each contact's first column (-1 when it has none).
std::vector<int> addContactColumns(const std::vector<StaticsContact>& contacts,
                                   const StaticsOptions& options, EquilibriumLp* lp,
                                   std::vector<std::vector<Eigen::Vector3d>>* edges) {
  std::vector<int> first_column;
  for (const StaticsContact& c : contacts) {
    edges->push_back(coneEdges(c, std::max(options.friction_faces, 4)));
    if (!lp->free(c.a) && !lp->free(c.b)) {
      first_column.push_back(-1);
      continue;
    }
    first_column.push_back(lp->columnCount());
    for (const Eigen::Vector3d& edge : edges->back()) lp->addForceColumn(c, edge, 0.0);
  }
  return first_column;
}

/// Where each column and row of the LP sits in a StaticsBasis: a
/// contact's columns under its key, one per cone edge; a body's rows under
/// its key, and its imbalance columns (2 row + side) under its key.
class BasisNames {
 public:
  BasisNames(const StaticsWarmStart& warm, const EquilibriumLp& lp,
             const std::vector<int>& first_column,
             const std::vector<std::vector<Eigen::Vector3d>>& edges, int first_imbalance,
             std::size_t bodies)
      : warm_(warm),
        lp_(lp),
        first_column_(first_column),
        edges_(edges),
        first_imbalance_(first_imbalance),
        bodies_(bodies) {}

  /// The start: the basis's status of every column and row it names;
  /// new columns at their lower bound (0), new rows' slacks basic.
  std::vector<unsigned char> start() const {
    std::vector<unsigned char> status(lp_.columnCount() + lp_.rowCount(),
                                      static_cast<unsigned char>(ClpSimplex::atLowerBound));
    for (int r = 0; r < lp_.rowCount(); ++r)
      status[lp_.columnCount() + r] = static_cast<unsigned char>(ClpSimplex::basic);
    visit([&](StaticsBasis::Statuses& names, std::uint64_t key, int count, int first) {
      auto found = names.find(key);
      if (found == names.end()) return;
      const std::vector<unsigned char>& kept = found->second;
      for (int j = 0; j < count && j < static_cast<int>(kept.size()); ++j)
        if (kept[j] != StaticsBasis::kUnknown) status[first + j] = kept[j];
    });
    return status;
  }

  /// The share of the problem's free bodies whose rows the basis names [-].
  double knownBodies() const {
    std::size_t free_bodies = 0, known = 0;
    for (std::size_t i = 0; i < bodies_; ++i) {
      if (lp_.rowOf(static_cast<int>(i)) < 0) continue;
      ++free_bodies;
      known += warm_.basis->rows.count(warm_.body_keys[i]);
    }
    return free_bodies == 0 ? 1.0 : static_cast<double>(known) / free_bodies;
  }

  /// Puts `model`'s final status under each of its names, keeping the
  /// names of other problems; past kRememberedNames the others go first.
  void keep(const ClpSimplex& model) const {
    StaticsBasis& basis = *warm_.basis;
    if (basis.names > kRememberedNames) basis = StaticsBasis();
    const unsigned char* status = model.statusArray();
    visit([&](StaticsBasis::Statuses& names, std::uint64_t key, int count, int first) {
      std::vector<unsigned char>& kept = names[key];
      if (static_cast<int>(kept.size()) < count) kept.resize(count, StaticsBasis::kUnknown);
      for (int j = 0; j < count; ++j) {
        if (kept[j] == StaticsBasis::kUnknown) ++basis.names;
        kept[j] = status[first + j];
      }
    });
  }

  /// Forgets the basis: never start from a failure's.
  void forget() const { *warm_.basis = StaticsBasis(); }

 private:
  /// Calls `each(family, key, count, first)` for each contact's and
  /// body's run of `count` columns or rows, the first at index `first` of
  /// Clp's status array (columns, then rows).
  template <typename Visit>
  void visit(Visit&& each) const {
    StaticsBasis& basis = *warm_.basis;
    for (std::size_t c = 0; c < first_column_.size(); ++c) {
      if (first_column_[c] < 0) continue;
      each(basis.columns, warm_.contact_keys[c], static_cast<int>(edges_[c].size()),
           first_column_[c]);
    }
    for (std::size_t i = 0; i < bodies_; ++i) {
      const int row = lp_.rowOf(static_cast<int>(i));
      if (row < 0) continue;
      each(basis.rows, warm_.body_keys[i], 6, lp_.columnCount() + row);
      each(basis.imbalance, warm_.body_keys[i], 12, first_imbalance_ + 2 * row);
    }
  }

  const StaticsWarmStart& warm_;
  const EquilibriumLp& lp_;
  const std::vector<int>& first_column_;
  const std::vector<std::vector<Eigen::Vector3d>>& edges_;
  int first_imbalance_;
  std::size_t bodies_;
};

// solveStatics's steps after building the LP.

/// Solves `lp` into `model`, from the basis `names` finds in the warm start
/// when there is one, which then keeps the final basis for the next solve.
/// With `barrier`, by the barrier with a crossover first.
bool solveFromWarmStart(const EquilibriumLp& lp, const BasisNames* names, bool barrier,
                        ClpSimplex* model, int* iterations) {
  if (barrier) {
    // A vertex for the mechanism's duals and for the next warm start; the
    // simplex from the kept basis is the fallback.
    if (lp.solveByBarrier(model, true, iterations)) {
      if (names) names->keep(*model);
      return true;
    }
    *model = ClpSimplex();
  }
  if (!names) return lp.solve(model, nullptr, iterations);
  const std::vector<unsigned char> start = names->start();
  const bool solved = lp.solve(model, &start, iterations);
  if (solved) {
    names->keep(*model);
  } else {
    names->forget();
  }
  return solved;
}

/// Each free body's imbalance in the solution `x`: the sum of its rows'
/// surplus and deficit columns. Returns the total over all bodies.
double readImbalance(const EquilibriumLp& lp, const double* x, int first_imbalance,
                     std::vector<double>* imbalance) {
  double total = 0.0;
  for (std::size_t i = 0; i < imbalance->size(); ++i) {
    const int row = lp.rowOf(static_cast<int>(i));
    if (row < 0) continue;
    for (int k = 0; k < 6; ++k)
      (*imbalance)[i] +=
          x[first_imbalance + 2 * (row + k)] + x[first_imbalance + 2 * (row + k) + 1];
    total += (*imbalance)[i];
  }
  return total;
}

/// Each contact's force in the solution `x`, its cone edges weighted by
/// their columns, back from weight units to newtons.
void readContactForces(const EquilibriumLp& lp, const double* x,
                       const std::vector<int>& first_column,
                       const std::vector<std::vector<Eigen::Vector3d>>& edges,
                       std::vector<Eigen::Vector3d>* forces) {
  for (std::size_t c = 0; c < forces->size(); ++c) {
    if (first_column[c] < 0) continue;
    for (std::size_t j = 0; j < edges[c].size(); ++j)
      (*forces)[c] += x[first_column[c] + j] * lp.weightUnit() * edges[c][j];
  }
}

/// The bodies of the collapse mechanism of an infeasible LP. The dual of
/// "least imbalance" is a velocity per row (a body's translation, and
/// rotation times the problem's size), at most 1 each, in which no contact
/// does positive work (reduced costs of the force columns >= 0) and the
/// loads' work is the least imbalance. The bodies it moves are the
/// mechanism; those it leaves still are held.
void markMechanism(const EquilibriumLp& lp, const ClpSimplex& model, std::vector<bool>* moves) {
  const double* velocity = model.dualRowSolution();
  for (std::size_t i = 0; i < moves->size(); ++i) {
    const int row = lp.rowOf(static_cast<int>(i));
    if (row < 0) continue;
    for (int k = 0; k < 6; ++k)
      if (std::abs(velocity[row + k]) > kMoving) (*moves)[i] = true;
  }
}

}  // namespace

StaticsSolution solveStatics(const std::vector<StaticsBody>& bodies,
                             const std::vector<StaticsContact>& contacts,
                             const StaticsOptions& options, StaticsWarmStart* warm) {
  StaticsSolution solution;
  solution.imbalance.assign(bodies.size(), 0.0);
  solution.moves.assign(bodies.size(), false);
  solution.forces.assign(contacts.size(), Eigen::Vector3d::Zero());
  EquilibriumLp lp(bodies, options);
  if (lp.rowCount() == 0) {
    solution.solved = solution.feasible = true;
    return solution;
  }
  lp.measureLevers(contacts);
  std::vector<std::vector<Eigen::Vector3d>> edges;
  const std::vector<int> first_column = addContactColumns(contacts, options, &lp, &edges);
  const int first_imbalance = lp.columnCount();
  lp.addImbalanceColumns();

  std::unique_ptr<BasisNames> names;  // set when warm-started
  if (warm && warm->basis && warm->body_keys.size() == bodies.size() &&
      warm->contact_keys.size() == contacts.size()) {
    names = std::make_unique<BasisNames>(*warm, lp, first_column, edges, first_imbalance,
                                         bodies.size());
  }
  ClpSimplex model;
  const bool barrier =
      lp.freeBodyCount() >= kBarrierBodies && (!names || names->knownBodies() < kKnownForWarmStart);
  if (barrier) {
    // A large problem that balances is answered by the interior point: any
    // admissible set of forces proves it stands. One that does not is
    // solved again to a vertex, whose duals name the mechanism.
    if (lp.solveByBarrier(&model, false, &solution.iterations)) {
      const double* x = model.getColSolution();
      std::vector<double> imbalance(bodies.size(), 0.0);
      if (readImbalance(lp, x, first_imbalance, &imbalance) <=
          options.tolerance * static_cast<double>(std::max<std::size_t>(1, bodies.size()))) {
        solution.solved = solution.feasible = true;
        readContactForces(lp, x, first_column, edges, &solution.forces);
        return solution;
      }
    }
    model = ClpSimplex();
  }
  if (!solveFromWarmStart(lp, names.get(), barrier, &model, &solution.iterations)) {
    // With imbalance columns the LP is always feasible and bounded.
    solution.message = "the statics LP did not solve (Clp status " +
                       std::to_string(model.status()) + ", secondary " +
                       std::to_string(model.secondaryStatus()) + ")";
    return solution;
  }
  solution.solved = true;
  const double* x = model.getColSolution();
  const double total = readImbalance(lp, x, first_imbalance, &solution.imbalance);
  readContactForces(lp, x, first_column, edges, &solution.forces);
  solution.feasible = total <= options.tolerance * std::max<std::size_t>(1, bodies.size());
  for (double& value : solution.imbalance)
    if (value <= options.tolerance) value = 0.0;
  if (!solution.feasible) markMechanism(lp, model, &solution.moves);
  return solution;
}

double horizontalAccelerationMargin(const std::vector<StaticsBody>& bodies,
                                    const std::vector<StaticsContact>& contacts,
                                    const Eigen::Vector3d& direction, const StaticsOptions& options,
                                    double cap) {
  EquilibriumLp lp(bodies, options);
  if (lp.rowCount() == 0) return cap;
  lp.measureLevers(contacts);
  std::vector<std::vector<Eigen::Vector3d>> edges;
  addContactColumns(contacts, options, &lp, &edges);
  const int load_column = lp.columnCount();
  // The column is the acceleration over g; maximised.
  lp.addLoadColumn(direction.normalized(), cap / options.gravity, -1.0);
  ClpSimplex model;
  if (!lp.solve(&model)) return 0.0;
  return std::clamp(model.getColSolution()[load_column] * options.gravity, 0.0, cap);
}

}  // namespace brick_stack_sim
