#include "brick_stack_sim/tools/motion_cases.h"

#include <algorithm>
#include <cmath>

namespace brick_stack_sim {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDegree = M_PI / 180.0;

constexpr double kSlideSpeed = 1.0;          ///< [m/s]
constexpr double kInclineAngle = 35.0 * kDegree;
constexpr int kInclineSupportLayers = 8;     ///< KAPLAs under the leaning one's upper end.
constexpr double kInclineStart = 0.03;       ///< The cube's start, up the slope from the board's centre [m].
constexpr double kInclineEarly = 0.05;       ///< [s]: after the first contacts settle
constexpr double kInclineLate = 0.25;        ///< [s]: the cube still on the board
constexpr double kToppleStart = 2.0 * kDegree;  ///< Past the balance angle.
constexpr double kToppleEnd = 45.0 * kDegree;   ///< Before the edge could slip or lift.
constexpr double kFlightTime = 0.3;             ///< [s]
const Eigen::Vector3d kThrow(1.0, 0.0, 2.0);    ///< [m/s]
constexpr double kThrowHeight = 0.3;            ///< [m]
constexpr int kDominoes = 20;
constexpr double kDominoSpacing = 0.4;         ///< Centre to centre, over the height [-].
constexpr double kDominoSpin = 2.0;             ///< The first one's, about its front edge [rad/s].
constexpr double kDominoTipped = 20.0 * kDegree;
constexpr int kDominoFirstTimed = 5, kDominoLastTimed = 15;

/// Rotation about world y by `angle` [rad].
Eigen::Matrix3d pitch(double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).toRotationMatrix();
}

/// How far a brick's long axis (local x) leans from vertical [rad].
double tiltOf(const BrickSnapshot& brick) {
  return std::acos(std::clamp(brick.pose.linear()(2, 0), -1.0, 1.0));
}

ScheduledBrick brickAt(const std::string& id, const std::string& type, const Eigen::Vector3d& at,
                       const Eigen::Matrix3d& orientation) {
  ScheduledBrick brick;
  brick.placement.id = id;
  brick.placement.type = type;
  brick.placement.pose.translation() = at;
  brick.placement.pose.linear() = orientation;
  return brick;
}

/// A KAPLA standing on its end, its thickness along x, leaning `tilt` [rad]
/// towards +x on the edge of its base at x = `edge_x`.
ScheduledBrick standing(const std::string& id, const BrickType& kapla, double edge_x, double tilt) {
  const double length = kapla.size.x(), thickness = kapla.size.z();
  const Eigen::Matrix3d orientation = pitch(tilt - M_PI / 2.0);
  const Eigen::Vector3d up = orientation.col(0), across = orientation.col(2);
  // The base's +x edge: centre - L/2 up - T/2 across, on the table.
  const Eigen::Vector3d centre =
      Eigen::Vector3d(edge_x, 0.0, 0.0) + 0.5 * length * up + 0.5 * thickness * across;
  return brickAt(id, kapla.name, centre, orientation);
}

/// The KAPLA's balance angle on its end, atan(T / L) [rad].
double balanceAngle(const BrickType& kapla) { return std::atan2(kapla.size.z(), kapla.size.x()); }

double combined(double a, double b) { return std::sqrt(a * b); }

Status findTypes(const BrickTypeLibrary& types, const BrickType** kapla, const BrickType** cube) {
  *kapla = types.find("kapla");
  *cube = types.find("cube");
  if (!*kapla || !*cube) return Status::error("the motion cases need brick types kapla and cube");
  return Status::success();
}

// The scenes of motionScene that take more than a brick or two.

/// A cube sliding down an inclined KAPLA. The KAPLA rises towards +x at
/// angle a, its lower edge on the table at x = 0, resting near its upper end
/// on the edge of a column of KAPLAs (along y) that stands where its
/// underside is a column high.
void inclineBricks(const BrickType& kapla, const BrickType& cube,
                   std::vector<ScheduledBrick>* bricks) {
  const double length = kapla.size.x(), width = kapla.size.y(), thickness = kapla.size.z();
  const double height = kInclineSupportLayers * thickness;
  const double column_edge = height / std::tan(kInclineAngle);
  for (int layer = 0; layer < kInclineSupportLayers; ++layer)
    bricks->push_back(
        brickAt("s" + std::to_string(layer), kapla.name,
                {column_edge + 0.5 * width, 0.0, (layer + 0.5) * thickness},
                Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix()));
  const Eigen::Matrix3d orientation = pitch(-kInclineAngle);
  const Eigen::Vector3d along = orientation.col(0), normal = orientation.col(2);
  const Eigen::Vector3d board = 0.5 * length * along + 0.5 * thickness * normal;
  bricks->push_back(brickAt("board", kapla.name, board, orientation));
  bricks->push_back(brickAt(
      "slider", cube.name,
      board + 0.5 * (thickness + cube.size.z()) * normal + kInclineStart * along, orientation));
}

/// A row of standing KAPLAs, the first set turning towards the others.
void dominoBricks(const BrickType& kapla, std::vector<ScheduledBrick>* bricks) {
  const double length = kapla.size.x(), thickness = kapla.size.z();
  const double spacing = kDominoSpacing * length;
  for (int i = 0; i < kDominoes; ++i) {
    // Base's +x edge: the row starts at x = -0.45.
    ScheduledBrick domino =
        standing("d" + std::to_string(i), kapla, -0.45 + i * spacing + thickness, 0.0);
    if (i == 0) {
      // Turning about its front edge: the centre moves at w x (its
      // offset from the edge), (w L / 2, 0, w T / 2).
      domino.placement.angular_velocity = Eigen::Vector3d(0.0, kDominoSpin, 0.0);
      domino.placement.linear_velocity =
          kDominoSpin * Eigen::Vector3d(0.5 * length, 0.0, 0.5 * thickness);
    }
    bricks->push_back(domino);
  }
}

}  // namespace

std::string motionCaseName(MotionCase motion) {
  switch (motion) {
    case MotionCase::kSlide: return "slide";
    case MotionCase::kIncline: return "incline";
    case MotionCase::kTopple: return "topple";
    case MotionCase::kFreeFlight: return "free_flight";
    case MotionCase::kDomino: return "domino";
  }
  return "unknown";
}

Status motionScene(MotionCase motion, const BrickTypeLibrary& types, Scene* scene) {
  const BrickType *kapla = nullptr, *cube = nullptr;
  if (Status found = findTypes(types, &kapla, &cube); !found) return found;
  *scene = Scene();
  scene->name = motionCaseName(motion);
  scene->table = TableOptions();
  std::vector<ScheduledBrick>& bricks = scene->bricks;
  const double thickness = kapla->size.z();
  switch (motion) {
    case MotionCase::kSlide: {
      bricks.push_back(brickAt("slider", kapla->name, {-0.3, 0.0, 0.5 * thickness},
                               Eigen::Matrix3d::Identity()));
      bricks.back().placement.linear_velocity = Eigen::Vector3d(kSlideSpeed, 0.0, 0.0);
      break;
    }
    case MotionCase::kIncline:
      inclineBricks(*kapla, *cube, &bricks);
      break;
    case MotionCase::kTopple:
      bricks.push_back(standing("slider", *kapla, 0.0, balanceAngle(*kapla) + kToppleStart));
      break;
    case MotionCase::kFreeFlight:
      bricks.push_back(
          brickAt("slider", kapla->name, {-0.2, 0.0, kThrowHeight}, Eigen::Matrix3d::Identity()));
      bricks.back().placement.linear_velocity = kThrow;
      break;
    case MotionCase::kDomino:
      dominoBricks(*kapla, &bricks);
      break;
  }
  return Status::success();
}

double motionExpected(MotionCase motion, const BrickTypeLibrary& types, const TableOptions& table,
                      double gravity) {
  const BrickType *kapla = nullptr, *cube = nullptr;
  if (!findTypes(types, &kapla, &cube).ok) return kNaN;
  switch (motion) {
    case MotionCase::kSlide:
      return kSlideSpeed * kSlideSpeed / (2.0 * combined(kapla->friction, table.friction) * gravity);
    case MotionCase::kIncline:
      return gravity * (std::sin(kInclineAngle) -
                        combined(cube->friction, kapla->friction) * std::cos(kInclineAngle));
    case MotionCase::kTopple: {
      // About the edge: I = m (L^2 + T^2) / 3, COM at r = sqrt(L^2 + T^2) / 2.
      const double diagonal = std::hypot(kapla->size.x(), kapla->size.z());
      const double rate = 3.0 * gravity / (2.0 * diagonal);  // m g r / I [1/s^2]
      const double end = kToppleEnd - balanceAngle(*kapla);
      double phi = kToppleStart, speed = 0.0, t = 0.0;
      const double h = 1e-6;  // [s]: RK4 on phi'' = rate sin(phi)
      while (phi < end) {
        const auto accel = [rate](double p) { return rate * std::sin(p); };
        const double k1p = speed, k1v = accel(phi);
        const double k2p = speed + 0.5 * h * k1v, k2v = accel(phi + 0.5 * h * k1p);
        const double k3p = speed + 0.5 * h * k2v, k3v = accel(phi + 0.5 * h * k2p);
        const double k4p = speed + h * k3v, k4v = accel(phi + h * k3p);
        const double next = phi + h / 6.0 * (k1p + 2.0 * k2p + 2.0 * k3p + k4p);
        speed += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        if (next >= end) return t + h * (end - phi) / (next - phi);
        phi = next;
        t += h;
      }
      return t;
    }
    case MotionCase::kFreeFlight:
      return kThrow.z() * kFlightTime - 0.5 * gravity * kFlightTime * kFlightTime;
    case MotionCase::kDomino:
      return kNaN;
  }
  return kNaN;
}

void MotionProbe::observe(const BrickWorld& world) {
  const double t = world.time();
  BrickSnapshot slider;
  switch (motion_) {
    case MotionCase::kSlide:
      if (world.find("slider", &slider))
        value_ = slider.pose.translation().x() - slider.placed_pose.translation().x();
      return;
    case MotionCase::kIncline: {
      if (!world.find("slider", &slider)) return;
      const Eigen::Vector3d down_slope = -pitch(-kInclineAngle).col(0);
      const double s = (slider.pose.translation() - slider.placed_pose.translation()).dot(down_slope);
      const double half_step = 0.5 * world.options().time_step;
      if (std::isnan(early_) && t >= kInclineEarly - half_step) early_ = s;
      if (std::isnan(late_) && t >= kInclineLate - half_step) {
        late_ = s;
        value_ = 2.0 * (late_ - early_) / (kInclineLate * kInclineLate - kInclineEarly * kInclineEarly);
      }
      return;
    }
    case MotionCase::kTopple: {
      if (!std::isnan(value_) || !world.find("slider", &slider)) return;
      // Between the samples on either side of the angle, linearly.
      const double tilt = tiltOf(slider);
      if (tilt >= kToppleEnd && !std::isnan(previous_tilt_))
        value_ = t - world.options().time_step * (tilt - kToppleEnd) / (tilt - previous_tilt_);
      previous_tilt_ = tilt;
      return;
    }
    case MotionCase::kFreeFlight:
      if (std::isnan(value_) && t >= kFlightTime - 0.5 * world.options().time_step &&
          world.find("slider", &slider))
        value_ = slider.pose.translation().z() - slider.placed_pose.translation().z();
      return;
    case MotionCase::kDomino: {
      if (tipped_at_.empty()) tipped_at_.assign(kDominoes, kNaN);
      for (int i = next_domino_; i < kDominoes; ++i) {
        BrickSnapshot domino;
        if (!world.find("d" + std::to_string(i), &domino) || tiltOf(domino) < kDominoTipped) break;
        tipped_at_[i] = t;
        next_domino_ = i + 1;
      }
      const double first = tipped_at_[kDominoFirstTimed], last = tipped_at_[kDominoLastTimed];
      if (std::isnan(value_) && !std::isnan(last) && last > first && world.find("d0", &slider)) {
        const double spacing = kDominoSpacing * slider.size.x();
        value_ = (kDominoLastTimed - kDominoFirstTimed) * spacing / (last - first);
      }
      return;
    }
  }
}

double MotionProbe::measured() const { return value_; }

}  // namespace brick_stack_sim
