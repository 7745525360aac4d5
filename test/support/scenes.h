#pragma once
// Scenes written inline in a test, read with the package's brick types.

#include <string>

#include <gtest/gtest.h>

#include "brick_stack_sim/core/scene/generators.h"
#include "brick_stack_sim/core/scene/scene.h"
#include "support/kapla.h"

namespace brick_stack_sim {
namespace test {

/// The package's cube: full edge [m], a KAPLA's width (urdf/bricks.urdf).
constexpr double kCube = 0.0234;

/// The scene `yaml` describes, expecting it to be read without error.
inline Scene parsed(const std::string& yaml) {
  Scene scene;
  const Status s = parseScene(yaml, "sweep", packageTypes(), &scene);
  EXPECT_TRUE(s.ok) << s.message;
  return scene;
}

/// `bricks` KAPLA planks dropped as a pile from a `columns` x `rows`
/// lattice (generatePile with `seed`), expecting it to be generated.
inline Scene droppedPileScene(int bricks, int columns, int rows, unsigned seed = 1) {
  PileParams pile;
  pile.bricks = bricks;
  pile.columns = columns;
  pile.rows = rows;
  pile.seed = seed;
  pile.type = "kapla";
  Scene scene;
  scene.name = "pile";
  const Status s = generatePile(pile, packageTypes(), &scene.bricks);
  EXPECT_TRUE(s.ok) << s.message;
  return scene;
}

}  // namespace test
}  // namespace brick_stack_sim
