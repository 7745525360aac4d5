#pragma once
// The scene generators (docs/design.md, "Simulation and scenes"): parametric
// structures whose statics are known, so scenes, benchmarks and tests can
// build them exactly.

#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "brick_stack_sim/core/scene/scene.h"
#include "brick_stack_sim/core/status.h"
#include "brick_stack_sim/core/types/brick_type.h"
#include "brick_stack_sim/core/types/world_options.h"

namespace brick_stack_sim {

/// Parameters of the `tower` generator.
struct TowerParams {
  int layers = 10;
  int bricks_per_layer = 2;  ///< 2 or 3.
  std::string type;          ///< Empty: the default type.
  double start = 0.0;        ///< Time of the first placement [s].
  double interval = 0.0;     ///< Time between placements [s]; 0: all at `start`.
  double gap = 0.0;          ///< Vertical clearance between layers at placement [m].
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< Centre of the (first) tower [m].
  int grid_x = 1, grid_y = 1;                        ///< Copies of the tower along x and y.
  double spacing = 0.13;                             ///< Distance between copies [m].
};

/// Parameters of the `harmonic` generator (docs/testing.md, "Ground truth"): n bricks
/// stacked over the table's +x edge, brick i from the top overhanging the one
/// below (the table edge for the lowest) by factor * L / (2 i). Statics: it
/// stands for factor < 1 and falls for factor > 1.
struct HarmonicParams {
  int bricks = 4;
  double factor = 0.95;
  std::string type;
  double start = 0.0;     ///< [s]
  double interval = 0.0;  ///< [s] between placements, bottom brick first.
};

/// Parameters of the `slant_tower` generator: one brick per layer along x,
/// each layer shifted by `offset` in +x from the one below.
struct SlantTowerParams {
  int layers = 10;
  double offset = 0.01;  ///< [m]
  std::string type;
  double start = 0.0;     ///< [s]
  double interval = 0.0;  ///< [s]
};

/// Parameters of the `pyramid` generator: rows of bricks along x laid end to
/// end, each row one brick shorter and resting across the joints below.
struct PyramidParams {
  int base = 20;       ///< Bricks in the lowest row; base (base + 1) / 2 in all.
  double gap = 0.002;  ///< Gap between neighbours in a row [m].
  std::string type;
  double start = 0.0;     ///< [s]
  double interval = 0.0;  ///< [s]
};

/// Parameters of the `pile` generator: bricks dropped from a lattice above the
/// table with pseudo-random yaw, tilt and offsets (fixed seed: reproducible).
struct PileParams {
  int bricks = 1000;
  int columns = 7;             ///< Lattice cells along x.
  int rows = 5;                ///< Lattice cells along y.
  double cell = 0.13;          ///< Lattice pitch [m]; a KAPLA turned any way spans 0.119 m.
  double layer_height = 0.04;  ///< Vertical pitch [m]; a KAPLA tilted 0.2 rad spans 0.036 m.
  double base_height = 0.03;   ///< Height of the lowest layer's centres [m].
  double max_tilt = 0.2;       ///< Largest roll and pitch [rad].
  unsigned seed = 1;
  std::string type;
  double start = 0.0;                                ///< [s]
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< Centre of the lattice [m].
};

/// Parameters of the `aframe` generator: one inverted V (the card house's
/// element), two bricks on their ends leaning on each other, each tilted by
/// `angle` from vertical with their upper inner edges meeting at the apex.
/// Statics: with friction mu on the table and between the bricks, it stands
/// while tan(angle) <= 2 mu + T / L (friction comes from the scene's types
/// and table).
struct AFrameParams {
  double angle = 0.349;  ///< Tilt of each brick from vertical [rad]; 0.349 is 20 degrees.
  std::string type;
  double start = 0.0;                                ///< Time of both placements [s].
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< The apex, seen from above [m].
};

/// Parameters of the `card_house` generator (thesis figure 10): `levels`
/// rows of V's, `levels` V's in the lowest and one fewer in each above, a
/// level brick laid flat across the apexes of each two neighbouring V's and
/// a V standing on each level brick. Two level bricks on one apex cannot
/// both lie along its middle, so each row is shifted sideways (along y) by
/// a little more than half a brick's width from the one below: each level
/// brick rests on half of each apex it spans.
struct CardHouseParams {
  int levels = 3;
  double angle = 0.349;  ///< Tilt of each leaning brick from vertical [rad].
  std::string type;
  double start = 0.0;  ///< [s]
  /// Between placements [s]: one per V (both its bricks at once) or level brick.
  double interval = 0.0;
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< Centre of the house, seen from above [m].
};

/// Parameters of the `impact` generator (thesis 4.1, "4 stack impact"): a
/// tower built brick by brick, then one brick thrown at one of its layers.
struct ImpactParams {
  TowerParams tower;   ///< The tower struck (13 layers of two in the thesis).
  int layer = 13;      ///< Layer struck, 1 = the lowest.
  double speed = 1.0;  ///< Speed of the thrown brick [m/s], square to the face it hits.
  /// Time from the last tower brick to the throw [s]: the tower has frozen.
  double delay = 1.0;
  /// Distance from the struck face at the throw [m]. A slow throw starts
  /// nearer (at most kMaxImpactFlight of flight), so that gravity has not
  /// pulled it below the layer when it arrives.
  double gap = 0.004;
};

/// Longest flight of the `impact` generator's throw [s]: a KAPLA falls
/// 0.02 mm in that time, far less than the 0.3 mm it is aimed above the
/// layer's centre.
constexpr double kMaxImpactFlight = 0.002;
/// The thrown brick flies this much above the struck layer's centre [m]: a
/// throw exactly flush would catch the edges of the layers above and below
/// once gravity has pulled it down by a hair.
constexpr double kImpactAimAbove = 0.0003;
/// Id of the `impact` generator's thrown brick.
constexpr char kStrikerId[] = "striker";

/// Parameters of the `kapla_record` generator: a tall hollow tower of square
/// floors, each two crossed layers of two planks (the 4-stack), built one
/// plank per `interval`.
struct KaplaRecordParams {
  int floors = 133;
  std::string type;
  double start = 0.0;                                ///< [s]
  double interval = 0.0;                             ///< [s]
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< Centre of the tower [m].
};

/// Parameters of the `arch` generator: an arch of `voussoirs` wedge-shaped
/// blocks standing on the table, its springings on the table top, in the
/// x-z plane. Each voussoir is a trapezoidal prism between two radial
/// joints (its intrados and extrados are chords), of a type the generator
/// defines. Semicircular (`pointed` = 0): one arc about the middle of the
/// springing line. Pointed: each half an arc of `radius` about a centre
/// `pointed` times `radius` beyond the middle, the two top voussoirs (a
/// type of their own, `type_name`_crown) meeting on a vertical joint.
struct ArchParams {
  int voussoirs = 15;                                ///< Even when pointed.
  double radius = 0.1;                               ///< Of the centre line of the ring [m].
  double thickness = 0.015;                          ///< Of the ring, radially [m].
  double depth = 0.03;                               ///< Along y [m].
  double pointed = 0.0;                              ///< In [0, 0.9] [-].
  double density = 700.0;                            ///< [kg/m^3]; 700: maple, as toy blocks.
  double friction = 0.8;                             ///< Of the voussoirs' material [-].
  std::string type_name = "voussoir";                ///< The type it defines.
  double start = 0.0;                                ///< Every voussoir is placed at rest then [s].
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< Middle of the springing line [m].
};

/// Parameters of the `column` generator: `count` bricks of one type stacked
/// along z, each centred on the one below (a column of cylinders standing
/// on end, or of any type).
struct ColumnParams {
  int count = 5;
  std::string type;
  double start = 0.0;                                ///< [s]
  double interval = 0.0;                             ///< [s]
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< [m]
};

/// Parameters of the `block_tower` generator: one brick per level, all of
/// one box type lying as its frame says, stacked along z from the table top,
/// each brick offset horizontally from the one below by a seeded random
/// vector, all offsets scaled by one factor so that the most critical level
/// has `criticality`. The criticality of level k (brick k-1 carrying bricks
/// k..n-1) is the larger over x and y of |that axis' coordinate of the
/// centre of mass of bricks k..n-1 minus brick k-1's centre| over brick
/// k-1's half extent along the axis. Statics: it stands exactly when
/// `criticality` < 1.
struct BlockTowerParams {
  int bricks = 5;  ///< Levels, 1 to 50.
  std::string type = "kapla";
  double criticality = 0.9;  ///< Of the most critical level (> 0) [-]; one brick has no level.
  std::uint64_t seed = 0;    ///< Of the offsets' directions and relative sizes.
  double start = 0.0;        ///< Every brick is placed at rest then [s].
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< The lowest brick's centre [m].
};

/// Appends a tower: layers alternate between bricks along x and along y, each
/// layer resting across the ends of the one below.
Status generateTower(const TowerParams& params, const BrickTypeLibrary& types,
                     std::vector<ScheduledBrick>* bricks);

/// Appends a harmonic stack at the +x edge of `table`.
Status generateHarmonic(const HarmonicParams& params, const TableOptions& table,
                        const BrickTypeLibrary& types, std::vector<ScheduledBrick>* bricks);

/// Appends a slant tower starting at the table centre.
Status generateSlantTower(const SlantTowerParams& params, const BrickTypeLibrary& types,
                          std::vector<ScheduledBrick>* bricks);

/// Appends a pyramid (running bond) centred on the table.
Status generatePyramid(const PyramidParams& params, const BrickTypeLibrary& types,
                       std::vector<ScheduledBrick>* bricks);

/// Appends an inverted V on the table.
Status generateAFrame(const AFrameParams& params, const BrickTypeLibrary& types,
                      std::vector<ScheduledBrick>* bricks);

/// Appends a card house on the table, from the lowest row up.
Status generateCardHouse(const CardHouseParams& params, const BrickTypeLibrary& types,
                         std::vector<ScheduledBrick>* bricks);

/// Appends a tower and, after it, a brick thrown at the outer long face of
/// the first brick of `layer`: even layers (counted from 0) lie along x and
/// are struck from -y, odd ones along y and are struck from -x, the thrown
/// brick lying parallel to the one it strikes.
Status generateImpact(const ImpactParams& params, const BrickTypeLibrary& types,
                      std::vector<ScheduledBrick>* bricks);

/// Appends a kapla_record tower (2 x floors layers of the `tower` generator).
Status generateKaplaRecord(const KaplaRecordParams& params, const BrickTypeLibrary& types,
                           std::vector<ScheduledBrick>* bricks);

/// Appends an arch and the voussoir type it is built of (to `types`).
Status generateArch(const ArchParams& params, std::vector<BrickType>* types,
                    std::vector<ScheduledBrick>* bricks);

/// Appends a column.
Status generateColumn(const ColumnParams& params, const BrickTypeLibrary& types,
                      std::vector<ScheduledBrick>* bricks);

/// Appends a block tower; refuses a type that is not a box, and a
/// criticality that the type's own centre of mass, off its box's centre,
/// already passes.
Status generateBlockTower(const BlockTowerParams& params, const BrickTypeLibrary& types,
                          std::vector<ScheduledBrick>* bricks);

/// Appends a pile drop.
Status generatePile(const PileParams& params, const BrickTypeLibrary& types,
                    std::vector<ScheduledBrick>* bricks);

/// How many bricks each generator appends, from its parameters alone (what
/// a scene is counted by before it is built); parameters the generator
/// refuses count what their numbers say, a negative count as 0, and a count
/// beyond kMaxCountedBricks as that.
constexpr std::int64_t kMaxCountedBricks = std::int64_t{1} << 50;
std::int64_t brickCount(const TowerParams& params);
std::int64_t brickCount(const HarmonicParams& params);
std::int64_t brickCount(const SlantTowerParams& params);
std::int64_t brickCount(const PyramidParams& params);
std::int64_t brickCount(const PileParams& params);
std::int64_t brickCount(const AFrameParams& params);
std::int64_t brickCount(const CardHouseParams& params);
std::int64_t brickCount(const ImpactParams& params);
std::int64_t brickCount(const KaplaRecordParams& params);
std::int64_t brickCount(const ArchParams& params);
std::int64_t brickCount(const ColumnParams& params);
std::int64_t brickCount(const BlockTowerParams& params);

}  // namespace brick_stack_sim
