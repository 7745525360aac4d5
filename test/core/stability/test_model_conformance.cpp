// Every stability model of the registry, driven with the same synthetic
// motions and contacts (no Bullet), so that models can be compared on
// identical inputs. Expectations come from statics: a brick whose centre of
// mass lies over its support patch stands, one whose centre lies past it
// cannot, and a load on a cantilever tips it when the common centre of mass
// passes the edge it overhangs.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/types/stability_modes.h"
#include "stability/stability_registry.h"
#include "support/kapla.h"
#include "support/leaning.h"
#include "support/modes.h"

namespace brick_stack_sim {
namespace {

using test::kKaplaLength;
using test::kKaplaMass;
using test::kKaplaThickness;
using test::kKaplaWidth;

std::string nameOf(BodyHandle handle) {
  return isGround(handle) ? "table" : "b" + std::to_string(handle);
}

/// A KAPLA along x (or along y when `crosswise`) at rest with its centre at
/// (x, y) and its bottom face at height `bottom` [m].
BodyMotion kapla(BodyHandle handle, double x, double y, double bottom) {
  return BodyMotion{handle, Eigen::Vector3d(x, y, bottom + kKaplaThickness / 2), kKaplaMass,
                    Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
}

/// A contact along the points `points` of b's face with outward `normal`.
PairContact faceContact(BodyHandle a, BodyHandle b, std::vector<Eigen::Vector3d> points,
                        const Eigen::Vector3d& normal, double mu) {
  PairContact contact;
  contact.a = a;
  contact.b = b;
  contact.normal = normal;
  contact.points = std::move(points);
  contact.friction = mu;
  return contact;
}

/// `upper` resting on `lower` over the rectangle x0..x1, y0..y1 at height z.
PairContact resting(BodyHandle upper, BodyHandle lower, double x0, double x1, double y0, double y1,
                    double z) {
  return faceContact(upper, lower, {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}},
                     Eigen::Vector3d::UnitZ(), 0.5);
}

/// Brick b along x at (x, 0) on the table: its whole bottom face touches.
PairContact onTable(BodyHandle b, double x) {
  return resting(b, kTableHandle, x - kKaplaLength / 2, x + kKaplaLength / 2, -kKaplaWidth / 2,
                 kKaplaWidth / 2, 0.0);
}

/// A V of planks b0 and b1 on the table at `theta` from vertical, their
/// upper inner edges meeting at x = 0, at rest.
struct RestingV {
  std::vector<PairContact> contacts;
  std::vector<BodyMotion> movers;
  Eigen::Vector3d right_centre;  ///< b1's centre of mass [m]
  double apex = 0.0;             ///< Height of the meeting edges [m].
};

RestingV restingV(double mu, double theta) {
  const double l = kKaplaLength, t = kKaplaThickness, w = kKaplaWidth / 2;
  const double foot = l * std::sin(theta);
  RestingV v;
  v.apex = l * std::cos(theta);
  v.right_centre = Eigen::Vector3d(0.5 * (t * std::cos(theta) + l * std::sin(theta)), 0.0,
                                   0.5 * (t * std::sin(theta) + l * std::cos(theta)));
  v.contacts = {
      faceContact(0, kTableHandle, {{-foot, -w, 0.0}, {-foot, w, 0.0}}, Eigen::Vector3d::UnitZ(),
                  mu),
      faceContact(1, kTableHandle, {{foot, -w, 0.0}, {foot, w, 0.0}}, Eigen::Vector3d::UnitZ(), mu),
      faceContact(0, 1, {{0.0, -w, v.apex}, {0.0, w, v.apex}}, -Eigen::Vector3d::UnitX(), mu)};
  const Eigen::Vector3d left_centre(-v.right_centre.x(), 0.0, v.right_centre.z());
  v.movers = {
      BodyMotion{0, left_centre, kKaplaMass, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()},
      BodyMotion{1, v.right_centre, kKaplaMass, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()}};
  return v;
}

class ModelConformance : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    options_ = test::optionsFor(GetParam()).stability;
    model_ = createStabilityModel(options_, &nameOf);
    ASSERT_NE(model_, nullptr);
  }

  /// Steps of 1 ms with these movers and contacts until `seconds` have passed.
  StabilityDecisions stepFor(double seconds, const std::vector<BodyMotion>& movers,
                             const std::vector<PairContact>& contacts) {
    StabilityDecisions all;
    const int steps = static_cast<int>(std::lround(seconds / 1e-3));
    for (int i = 0; i < steps; ++i) {
      StabilityInput input;
      input.dt = 1e-3;
      input.contacts = &contacts;
      // Frozen bricks leave the movers, as they leave Bullet.
      for (const BodyMotion& mover : movers)
        if (!frozen(mover.handle)) input.movers.push_back(mover);
      StabilityDecisions decisions;
      model_->decide(input, &decisions);
      append(decisions, &all);
    }
    return all;
  }

  StabilityDecisions request(const StabilityInput& input) {
    StabilityDecisions decisions;
    model_->decide(input, &decisions);
    append(decisions, &all_);
    return decisions;
  }

  bool frozen(BodyHandle brick) const {
    BrickStability stability;
    return model_->describe(brick, &stability) && stability.frozen;
  }

  /// b0 along x frozen on the table with its centre `inside` [m] before the
  /// table's edge at x = `edge`: a cantilever overhanging the edge.
  void freezeCantilever(double edge, double inside) {
    const double x = edge - inside;
    StabilityInput input;
    input.placed.push_back({kapla(0, x, 0, 0),
                            {resting(0, kTableHandle, x - kKaplaLength / 2, edge, -kKaplaWidth / 2,
                                     kKaplaWidth / 2, 0.0)}});
    ASSERT_EQ(request(input).freeze.size(), 1u);
  }

  /// b0 on the table and each next brick flush on the one below, placed at
  /// rest: each joins the stack at once.
  void placeStack(int bricks) {
    for (int i = 0; i < bricks; ++i) {
      const BodyHandle b = static_cast<BodyHandle>(i);
      StabilityInput input;
      input.placed.push_back(
          {kapla(b, 0, 0, b * kKaplaThickness),
           {resting(b, b == 0 ? kTableHandle : b - 1, -kKaplaLength / 2, kKaplaLength / 2,
                    -kKaplaWidth / 2, kKaplaWidth / 2, b * kKaplaThickness)}});
      ASSERT_EQ(request(input).freeze.size(), 1u) << "b" << b << " placed at rest";
    }
  }

  static void append(const StabilityDecisions& more, StabilityDecisions* all) {
    all->freeze.insert(all->freeze.end(), more.freeze.begin(), more.freeze.end());
    all->wake.insert(all->wake.end(), more.wake.begin(), more.wake.end());
  }

  StabilityOptions options_;
  std::unique_ptr<StabilityModel> model_;
  StabilityDecisions all_;
};

TEST_P(ModelConformance, BrickAtRestOnTheTableFreezesOnceItHasRested) {
  const std::vector<PairContact> contacts = {onTable(0, 0.0)};
  const std::vector<BodyMotion> movers = {kapla(0, 0.0, 0, 0)};
  EXPECT_TRUE(stepFor(options_.rest_time / 2, movers, contacts).freeze.empty())
      << "frozen before it had rested for rest_time";
  const StabilityDecisions decisions = stepFor(options_.rest_time, movers, contacts);
  ASSERT_EQ(decisions.freeze.size(), 1u);
  const FreezeDecision& freeze = decisions.freeze[0];
  EXPECT_EQ(freeze.brick, 0u);
  EXPECT_TRUE(freeze.kind == BrickState::kStable || freeze.kind == BrickState::kLeaning);
  EXPECT_EQ(freeze.supporters, std::vector<BodyHandle>{kTableHandle});
  EXPECT_NE(freeze.reason.find("table"), std::string::npos) << freeze.reason;
  EXPECT_TRUE(frozen(0));
}

TEST_P(ModelConformance, CentreOfMassPastItsSupportNeverFreezes) {
  // The table's edge at x = 0.02 and the brick's centre at 0.03: it overhangs
  // by more than half its length.
  const std::vector<PairContact> contacts = {resting(0, kTableHandle, 0.03 - kKaplaLength / 2, 0.02,
                                                     -kKaplaWidth / 2, kKaplaWidth / 2, 0)};
  EXPECT_TRUE(stepFor(0.1, {kapla(0, 0.03, 0, 0)}, contacts).freeze.empty());
  EXPECT_FALSE(frozen(0));
}

TEST_P(ModelConformance, MovingBricksAndBricksOnMovingOnesDoNotFreeze) {
  BodyMotion sliding = kapla(0, 0.0, 0, 0);
  sliding.linear_velocity.x() = 10 * options_.rest_linear_speed;
  // b1 at rest on b0, which slides: a stack cannot start on a moving brick.
  const std::vector<PairContact> contacts = {
      onTable(0, 0.0),
      resting(1, 0, -0.05, 0.05, -kKaplaWidth / 2, kKaplaWidth / 2, kKaplaThickness)};
  const StabilityDecisions decisions =
      stepFor(0.1, {sliding, kapla(1, 0.0, 0, kKaplaThickness)}, contacts);
  EXPECT_TRUE(decisions.freeze.empty());
}

TEST_P(ModelConformance, AStackAtRestFreezesFromTheBottomUpInOneStep) {
  const std::vector<PairContact> contacts = {
      onTable(0, 0.0), resting(1, 0, -kKaplaLength / 2, kKaplaLength / 2, -kKaplaWidth / 2,
                               kKaplaWidth / 2, kKaplaThickness)};
  const StabilityDecisions decisions = stepFor(
      2 * options_.rest_time, {kapla(0, 0, 0, 0), kapla(1, 0, 0, kKaplaThickness)}, contacts);
  ASSERT_EQ(decisions.freeze.size(), 2u);
  EXPECT_EQ(decisions.freeze[0].brick, 0u);
  EXPECT_EQ(decisions.freeze[1].brick, 1u);
  EXPECT_EQ(decisions.freeze[1].supporters, std::vector<BodyHandle>{0});
}

TEST_P(ModelConformance, RemovalAndPushesWakeWhatTheBrickCarried) {
  placeStack(3);
  StabilityInput push;
  push.pushed = {1};
  const StabilityDecisions pushed = request(push);
  ASSERT_EQ(pushed.wake.size(), 2u);
  EXPECT_EQ(pushed.wake[0].brick, 1u);
  EXPECT_EQ(pushed.wake[0].cause, WakeCause::kPushed);
  EXPECT_EQ(pushed.wake[1].brick, 2u);
  EXPECT_EQ(pushed.wake[1].cause, WakeCause::kCarried);
  EXPECT_NE(pushed.wake[1].reason.find("b1"), std::string::npos) << pushed.wake[1].reason;
  EXPECT_TRUE(frozen(0));

  StabilityInput removal;
  removal.removed = {0};
  EXPECT_TRUE(request(removal).wake.empty());  // nothing frozen rests on it any more
  StabilityInput again;
  again.pushed = {0};
  EXPECT_TRUE(request(again).empty());  // it is gone: a push of it is no decision
}

TEST_P(ModelConformance, RemovingASupporterNamesItInTheWakeReason) {
  placeStack(2);
  StabilityInput removal;
  removal.removed = {0};
  const StabilityDecisions decisions = request(removal);
  ASSERT_EQ(decisions.wake.size(), 1u);
  EXPECT_EQ(decisions.wake[0].brick, 1u);
  EXPECT_EQ(decisions.wake[0].cause, WakeCause::kSupporterRemoved);
  EXPECT_NE(decisions.wake[0].reason.find("b0"), std::string::npos) << decisions.wake[0].reason;
}

TEST_P(ModelConformance, ALoadPastTheCantileversEdgeTipsItAndOneShortOfItDoesNot) {
  // b0 overhangs the table's edge at x = 0.6 with its centre 20 mm inside.
  // A second KAPLA of the same mass on it, crosswise, centred at x moves the
  // common centre of mass to (0.58 + x) / 2: over the table for x < 0.62,
  // past the edge for x > 0.62 (statics of two equal masses).
  freezeCantilever(0.6, 0.02);
  auto place_on_top = [&](double x) { return kapla(1, x, 0, kKaplaThickness); };
  auto top_contact = [&](double x) {
    return resting(1, 0, x - kKaplaWidth / 2, x + kKaplaWidth / 2, -kKaplaWidth / 2,
                   kKaplaWidth / 2, kKaplaThickness);
  };
  const PlacementEvaluation short_of =
      model_->evaluatePlacement(place_on_top(0.61), {top_contact(0.61)});
  EXPECT_TRUE(short_of.stable) << short_of.reason;
  EXPECT_TRUE(short_of.would_fall.empty());
  EXPECT_EQ(short_of.supporters, std::vector<BodyHandle>{0});
  EXPECT_NEAR(short_of.margin, kKaplaWidth / 2, 1e-9);  // its own centre over its patch

  const PlacementEvaluation past =
      model_->evaluatePlacement(place_on_top(0.63), {top_contact(0.63)});
  EXPECT_FALSE(past.stable);
  EXPECT_EQ(past.would_fall, std::vector<BodyHandle>{0});
  EXPECT_NE(past.reason.find("b0"), std::string::npos) << past.reason;

  // Asking changed nothing: placing it for real now decides as statics says.
  EXPECT_TRUE(frozen(0));
  EXPECT_FALSE(frozen(1));
  StabilityInput input;
  input.placed.push_back({place_on_top(0.63), {top_contact(0.63)}});
  const StabilityDecisions decisions = request(input);
  ASSERT_EQ(decisions.freeze.size(), 1u);  // it rests stably on b0...
  EXPECT_FALSE(frozen(0));                 // ...whose load then leaves the table
  EXPECT_FALSE(frozen(1));
  ASSERT_GE(decisions.wake.size(), 2u);
  EXPECT_EQ(decisions.wake[0].brick, 0u);
  EXPECT_EQ(decisions.wake[0].cause, WakeCause::kOutsideSupport);
}

TEST_P(ModelConformance, APlacementWithNothingFrozenUnderItIsNotStable) {
  const PlacementEvaluation floating =
      model_->evaluatePlacement(kapla(4, 0, 0, 0.05), std::vector<PairContact>{});
  EXPECT_FALSE(floating.stable);
  EXPECT_TRUE(floating.supporters.empty());
  EXPECT_FALSE(floating.reason.empty());
}

TEST_P(ModelConformance, OfAGroupAtRestThePartStaticsHoldsFreezesWithoutWhatMustFall) {
  // A V of planks b0 and b1 at half the angle statics holds on mu = 0.5
  // (tan(theta) <= 2 mu + T/L, vThresholdAngle), their upper inner edges
  // meeting at x = 0, and a plank b2 that touches only b1's side face
  // (normal +y), as a plank caught against it for an instant does: nothing
  // presses it onto that face, so friction there holds none of its weight.
  // All three are at rest and touch, so they are judged as one group. The
  // V stands without b2 and freezes; b2 cannot, and stays with the engine.
  // Refused as a whole, the V never froze while b2 touched it.
  if (!model_->judgesLeaning()) GTEST_SKIP() << "judges no leaning groups";
  const double mu = 0.5;
  const RestingV v = restingV(mu, 0.5 * test::vThresholdAngle(mu));
  const double w = kKaplaWidth / 2, x = v.right_centre.x();
  std::vector<PairContact> contacts = v.contacts;
  contacts.push_back(faceContact(2, 1, {{x, w, 0.4 * v.apex}, {x, w, 0.6 * v.apex}},
                                 Eigen::Vector3d::UnitY(), mu));
  std::vector<BodyMotion> movers = v.movers;
  movers.push_back(kapla(2, x + 0.04, 2.0 * w, 0.5 * v.apex));
  stepFor(4.0 * options_.rest_time, movers, contacts);
  EXPECT_TRUE(frozen(0));
  EXPECT_TRUE(frozen(1));
  EXPECT_FALSE(frozen(2));
  BrickStability left;
  ASSERT_TRUE(model_->describe(0, &left));
  EXPECT_FALSE(left.contact_forces.empty());
}

TEST_P(ModelConformance, AGroupAtRestWaitsWhileAMoverPressesOnItAndFreezesOnceItHasGone) {
  // The V of the test above, which statics holds. A plank b3 sliding past
  // the rest speed pushes b1 towards the apex, at the middle of its outer
  // face, with 2 % of a plank's weight: while a moving brick presses on
  // it, what statics says of the V may not hold a step on, so the V waits.
  // Once the plank has gone, the V freezes.
  if (!model_->judgesLeaning()) GTEST_SKIP() << "judges no leaning groups";
  const double mu = 0.5, theta = 0.5 * test::vThresholdAngle(mu), dt = 1e-3;
  const RestingV v = restingV(mu, theta);
  const Eigen::Vector3d outward(std::cos(theta), 0.0, std::sin(theta));  // b1's outer face
  const Eigen::Vector3d touch = v.right_centre + 0.5 * kKaplaThickness * outward;
  PairContact push = faceContact(3, 1, {touch}, outward, mu);
  ContactPoint point;
  point.position = touch;
  point.normal = outward;
  point.impulse = 0.02 * kKaplaMass * 9.81 * dt;  // on b3; b1 bears its reaction
  push.manifold = {point};
  std::vector<PairContact> pressed = v.contacts;
  pressed.push_back(push);
  std::vector<BodyMotion> movers = v.movers;
  movers.push_back(BodyMotion{3, touch + 0.5 * kKaplaThickness * outward, kKaplaMass,
                              Eigen::Vector3d(0.0, 0.1, 0.0), Eigen::Vector3d::Zero()});

  stepFor(4.0 * options_.rest_time, movers, pressed);
  EXPECT_FALSE(frozen(0));
  EXPECT_FALSE(frozen(1));

  stepFor(4.0 * options_.rest_time, v.movers, v.contacts);
  EXPECT_TRUE(frozen(0));
  EXPECT_TRUE(frozen(1));
}

TEST_P(ModelConformance, AGroupFreezesWithAPartnerWhoseRestWindowHasNotFilled) {
  // The V of the tests above, which statics holds. b0 is still; b1 crosses
  // the rest speed for one step in every 15, as a plank of a settling pile
  // jitters, so its rest window (20 steps) never fills. b0 alone leans on
  // a brick that moves and cannot freeze; judged only with bricks whose
  // window has filled, the V never was. At the shared tick the bricks at
  // rest now join the groups they touch: the V freezes.
  if (!model_->judgesLeaning()) GTEST_SKIP() << "judges no leaning groups";
  const double mu = 0.5, dt = 1e-3;
  const RestingV v = restingV(mu, 0.5 * test::vThresholdAngle(mu));
  const int window = static_cast<int>(std::lround(options_.rest_time / dt));
  ASSERT_GT(window, 15);
  for (int step = 0; step < 10 * window && !(frozen(0) && frozen(1)); ++step) {
    StabilityInput input;
    input.dt = dt;
    input.contacts = &v.contacts;
    // Frozen bricks leave the movers, as they leave Bullet.
    for (BodyMotion mover : v.movers) {
      if (frozen(mover.handle)) continue;
      if (mover.handle == 1 && step % 15 == 7)
        mover.linear_velocity.x() = 2.0 * options_.rest_linear_speed;
      input.movers.push_back(mover);
    }
    StabilityDecisions decisions;
    model_->decide(input, &decisions);
    EXPECT_TRUE(decisions.wake.empty()) << "step " << step;
  }
  EXPECT_TRUE(frozen(0));
  EXPECT_TRUE(frozen(1));
}

/// `upper`, at rest on `lower` over the rectangle x0..x1, y0..y1 at height
/// z, pressing on it at the rectangle's corners with `share` of its weight,
/// as the engine split its weight in a step of `dt`.
PairContact pressing(BodyHandle upper, BodyHandle lower, double x0, double x1, double y0, double y1,
                     double z, double share, double dt) {
  PairContact contact = resting(upper, lower, x0, x1, y0, y1, z);
  for (const Eigen::Vector3d& corner : contact.points) {
    ContactPoint point;
    point.position = corner;
    point.normal = Eigen::Vector3d::UnitZ();
    point.impulse = share * kKaplaMass * 9.81 * dt / 4.0;  // on `upper`, up
    contact.manifold.push_back(point);
  }
  return contact;
}

TEST_P(ModelConformance, ABrickAtRestTipsACantileverWhereStaticsSaysAndNotWhereTheEngineSplitsIt) {
  // b0 overhangs the table's edge at x = 0.6 with its centre 5 mm inside;
  // b2 beside it (y = 30 mm) with its centre 40 mm inside. b1, crosswise at
  // x = 0.612, rests on both ends: their patches span y in [-11.7, 11.7]
  // and [18.3, 41.7] mm. The engine puts all of b1's weight on b0, which
  // taken as a fixed load tips b0 (12 mm past the edge against its own
  // 5 mm). But b1's centre is over b2's patch (y = 30 mm), so statics may
  // carry all of it there, and b0 must stay. Centred over b0 instead
  // (y = 0), b1 can only press on b0, and their joint centre of mass is
  // past the edge ((0.595 + 0.612) / 2 = 0.6035): b0 must tip.
  const double dt = 1e-3, x = 0.612, w = kKaplaWidth / 2, t = kKaplaThickness;
  freezeCantilever(0.6, 0.005);
  StabilityInput beside;
  beside.placed.push_back(
      {kapla(2, 0.56, 0.03, 0),
       {resting(2, kTableHandle, 0.56 - kKaplaLength / 2, 0.6, 0.03 - w, 0.03 + w, 0.0)}});
  ASSERT_EQ(request(beside).freeze.size(), 1u);
  const double b2_end = 0.56 + kKaplaLength / 2;
  const std::vector<PairContact> on_both = {
      pressing(1, 0, x - w, x + w, -w, w, t, 1.0, dt),
      pressing(1, 2, x - w, b2_end, 0.03 - w, 0.03 + w, t, 0.0, dt)};
  const StabilityDecisions decisions =
      stepFor(4.0 * options_.rest_time, {kapla(1, x, 0.03, t)}, on_both);
  for (const WakeDecision& woken : decisions.wake) ADD_FAILURE() << "woken: " << woken.reason;
  EXPECT_TRUE(frozen(0));
  EXPECT_TRUE(frozen(1));
}

TEST_P(ModelConformance, ABrickAtRestOnlyOnACantileversEndTipsIt) {
  // The control of the test above: b1 centred over b0 (y = 0), on b0 alone.
  const double dt = 1e-3, x = 0.612, w = kKaplaWidth / 2, t = kKaplaThickness;
  freezeCantilever(0.6, 0.005);
  const std::vector<PairContact> on_b0 = {pressing(1, 0, x - w, x + w, -w, w, t, 1.0, dt)};
  const StabilityDecisions decisions =
      stepFor(4.0 * options_.rest_time, {kapla(1, x, 0.0, t)}, on_b0);
  EXPECT_FALSE(frozen(0));
  ASSERT_FALSE(decisions.wake.empty());
  EXPECT_EQ(decisions.wake.front().brick, 0u);
}

INSTANTIATE_TEST_SUITE_P(Registry, ModelConformance, ::testing::ValuesIn(test::modelModes()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

}  // namespace
}  // namespace brick_stack_sim
