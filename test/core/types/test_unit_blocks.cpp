// The unit-block types of the package's URDF (Caroline Pratt's wooden unit
// blocks, maple at 700 kg/m^3): each volume and centre of mass is derived by
// hand here, independently of the meshes the URDF reads.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/types/brick_type.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace {

constexpr double kInch = 0.0254;          ///< [m]
constexpr double kUnit = 5.5 * kInch;     ///< [m]
constexpr double kWidth = 2.75 * kInch;   ///< [m]
constexpr double kThick = 1.375 * kInch;  ///< [m]
constexpr double kMaple = 700.0;          ///< [kg/m^3]
/// The meshes are read as single-precision floats: sizes to a few parts in
/// 10^8 of a metre [m].
constexpr double kMeshTolerance = 1e-7;

struct Expected {
  std::string name;
  ShapeKind kind;
  Eigen::Vector3d size;      ///< [m]
  double volume;             ///< [m^3]
  Eigen::Vector3d centroid;  ///< Type frame [m].
};

std::vector<Expected> expectedUnitBlocks() {
  const double r = kThick;  // the arch opening's radius
  // A regular polygon of n segments over a half circle of radius R is n
  // triangles with the centre of apex angle pi/n: area n R^2 sin(pi/n) / 2.
  const double half_circle_area = 0.5 * kWidth * kWidth * 32 * std::sin(M_PI / 32);
  // Its first moment about the flat side: triangle k has its centroid at
  // R (sin a_k + sin a_k+1) / 3, and sum_k (sin a_k + sin a_k+1) over the
  // 32 chords = 2 sum_{k=1..31} sin(k pi/32) = 2 cot(pi/64); so the centroid
  // is at R cot(pi/64) / 48 from the flat side (4R / 3pi in the limit). The
  // frame is at R/2 from the flat side.
  const double half_circle_y = kWidth / std::tan(M_PI / 64) / 48 - 0.5 * kWidth;
  // The arch: a 4r x 2r rectangle less the 16-gon over the opening, area
  // 8 r^2 sin(pi/16), whose moment about the springing line is as above:
  // (r^2 sin(pi/16) / 2) (r / 3) 2 cot(pi/32) = (2/3) r^3 cos^2(pi/32).
  const double opening_area = 8 * r * r * std::sin(M_PI / 16);
  const double opening_moment = 2.0 / 3.0 * r * r * r * std::pow(std::cos(M_PI / 32), 2);
  const double arch_area = 8 * r * r - opening_area;
  // Rectangle's moment 8 r^2 * r; the frame sits at height r.
  const double arch_z = (8 * r * r * r - opening_moment) / arch_area - r;
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  return {
      {"unit_block", ShapeKind::kBox, {kUnit, kWidth, kThick}, kUnit * kWidth * kThick, zero},
      {"unit_half", ShapeKind::kBox, {kWidth, kWidth, kThick}, kWidth * kWidth * kThick, zero},
      {"unit_double",
       ShapeKind::kBox,
       {2 * kUnit, kWidth, kThick},
       2 * kUnit * kWidth * kThick,
       zero},
      {"unit_quadruple",
       ShapeKind::kBox,
       {4 * kUnit, kWidth, kThick},
       4 * kUnit * kWidth * kThick,
       zero},
      {"unit_pillar", ShapeKind::kBox, {kUnit, kThick, kThick}, kUnit * kThick * kThick, zero},
      {"unit_cylinder",
       ShapeKind::kCylinder,
       {kThick, kThick, kUnit},
       M_PI * 0.25 * kThick * kThick * kUnit,
       zero},
      {"unit_half_circle",
       ShapeKind::kConvex,
       {2 * kWidth, kWidth, kThick},
       half_circle_area * kThick,
       {0, half_circle_y, 0}},
      // A right triangle's centroid is a third of each leg from the right
      // angle, which is at (-W/2, -W/2): W/3 - W/2 = -W/6.
      {"unit_triangle",
       ShapeKind::kConvex,
       {kWidth, kWidth, kThick},
       0.5 * kWidth * kWidth * kThick,
       {-kWidth / 6, -kWidth / 6, 0}},
      // The wedge's section is a right triangle with its right angle at
      // (+L/2, -T/2): a third of each leg in from there.
      {"unit_ramp",
       ShapeKind::kConvex,
       {kUnit, kWidth, kThick},
       0.5 * kUnit * kThick * kWidth,
       {kUnit / 2 - kUnit / 3, 0, -kThick / 2 + kThick / 3}},
      {"unit_arch", ShapeKind::kCompound, {4 * r, r, 2 * r}, arch_area * r, {0, 0, arch_z}},
  };
}

TEST(UnitBlocks, EveryTypeHasItsShapeSizeMassAndCentreOfMass) {
  BrickTypeLibrary types = test::packageTypes();
  for (const Expected& e : expectedUnitBlocks()) {
    SCOPED_TRACE(e.name);
    const BrickType* type = types.find(e.name);
    ASSERT_NE(type, nullptr);
    EXPECT_EQ(type->shape.kind, e.kind);
    EXPECT_NEAR((type->size - e.size).cwiseAbs().maxCoeff(), 0.0, kMeshTolerance)
        << type->size.transpose();
    // Lying flat, centred on its bounds.
    ASSERT_TRUE(type->solid);
    const Eigen::AlignedBox3d bounds = shapeBounds(type->shape, *type->solid);
    EXPECT_NEAR(bounds.center().cwiseAbs().maxCoeff(), 0.0, kMeshTolerance)
        << bounds.center().transpose();
    // The URDF keeps 6 significant digits: within half a unit of the 6th.
    const double mass = kMaple * e.volume;
    EXPECT_NEAR(type->mass, mass, 5e-6 * mass);
    EXPECT_NEAR((type->mass_frame.translation() - e.centroid).norm(), 0.0, kMeshTolerance)
        << type->mass_frame.translation().transpose();
    // The inertia is the solid's (the URDF gives zeros): a body's.
    EXPECT_TRUE((type->inertia.array() > 0.0).all()) << type->inertia.transpose();
  }
}

TEST(UnitBlocks, TheArchIsTwoLegsAndACrownOfSixteenConvexPieces) {
  BrickTypeLibrary types = test::packageTypes();
  const BrickType* arch = types.find("unit_arch");
  ASSERT_NE(arch, nullptr);
  ASSERT_EQ(arch->shape.parts.size(), 18u);
  int boxes = 0, convex = 0;
  for (const ShapePart& part : arch->shape.parts) {
    boxes += part.kind == ShapeKind::kBox;
    convex += part.kind == ShapeKind::kConvex;
  }
  EXPECT_EQ(boxes, 2);
  EXPECT_EQ(convex, 16);
}

TEST(UnitBlocks, KaplaTypesAreUnchangedAndStillTheDefault) {
  BrickTypeLibrary types = test::packageTypes();
  EXPECT_EQ(types.defaultType(), "kapla");
  struct Old {
    const char* name;
    Eigen::Vector3d size;  ///< [m]
    double mass;           ///< [kg]
  };
  for (const Old& old : {Old{"kapla", {0.117, 0.0234, 0.0078}, 0.0119},
                         Old{"half_kapla", {0.0585, 0.0234, 0.0078}, 0.00595},
                         Old{"cube", {0.0234, 0.0234, 0.0234}, 0.00713}}) {
    SCOPED_TRACE(old.name);
    const BrickType* type = types.find(old.name);
    ASSERT_NE(type, nullptr);
    EXPECT_TRUE(type->isBox());
    EXPECT_EQ(type->size, old.size);
    EXPECT_EQ(type->mass, old.mass);
  }
}

}  // namespace
}  // namespace brick_stack_sim
