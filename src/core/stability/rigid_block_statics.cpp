#include "stability/rigid_block_statics.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <coin/ClpSimplex.hpp>

#include "stability/equilibrium_lp.h"

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
  // The imbalance and forces of the solution in `solved`, and whether they
  // balance: the same test for an interior point as for a vertex.
  const auto read_answer = [&](const ClpSimplex& solved) {
    const double* x = solved.getColSolution();
    solution.imbalance.assign(bodies.size(), 0.0);
    solution.forces.assign(contacts.size(), Eigen::Vector3d::Zero());
    const double total = readImbalance(lp, x, first_imbalance, &solution.imbalance);
    readContactForces(lp, x, first_column, edges, &solution.forces);
    solution.solved = true;
    solution.feasible = total <= options.tolerance * std::max<std::size_t>(1, bodies.size());
    for (double& value : solution.imbalance)
      if (value <= options.tolerance) value = 0.0;
    return solution.feasible;
  };
  ClpSimplex model;
  const bool barrier =
      lp.freeBodyCount() >= kBarrierBodies && (!names || names->knownBodies() < kKnownForWarmStart);
  if (barrier) {
    // A large problem that balances is answered by the interior point: any
    // admissible set of forces proves it stands. One that does not is
    // solved again to a vertex, whose duals name the mechanism.
    if (lp.solveByBarrier(&model, false, &solution.iterations) && read_answer(model))
      return solution;
    solution.solved = false;
    model = ClpSimplex();
  }
  if (!solveFromWarmStart(lp, names.get(), barrier, &model, &solution.iterations)) {
    // With imbalance columns the LP is always feasible and bounded.
    solution.message = "the statics LP did not solve (Clp status " +
                       std::to_string(model.status()) + ", secondary " +
                       std::to_string(model.secondaryStatus()) + ")";
    return solution;
  }
  read_answer(model);
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
