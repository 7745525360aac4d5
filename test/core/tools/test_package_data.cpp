// Where the package's programs find urdf/, config/ and scenes/: next to
// themselves in an install space, the source tree anywhere else.
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "brick_stack_sim/tools/package_data.h"

namespace brick_stack_sim {
namespace {

namespace fs = std::filesystem;

class PackageData : public ::testing::Test {
 protected:
  void SetUp() override {
    prefix_ = fs::temp_directory_path() / ("package_data_" + std::to_string(::getpid()));
    fs::create_directories(prefix_ / "lib" / "brick_stack_sim");
  }
  void TearDown() override { fs::remove_all(prefix_); }

  /// Gives the fake install space <prefix>/share/brick_stack_sim/urdf/bricks.urdf.
  void installData() {
    fs::create_directories(share() / "urdf");
    std::ofstream(share() / "urdf" / "bricks.urdf") << "<robot name='bricks'/>\n";
  }
  fs::path share() const { return prefix_ / "share" / "brick_stack_sim"; }
  std::string program() const { return (prefix_ / "lib" / "brick_stack_sim" / "stack_sim_run"); }

  fs::path prefix_;
};

TEST_F(PackageData, AnInstalledProgramReadsTheInstallSpace) {
  installData();
  EXPECT_EQ(packageDataDir(program(), "/src/brick_stack_sim"), share().string());
}

TEST_F(PackageData, WithoutInstalledDataTheSourceTreeIsRead) {
  // The devel space: share/brick_stack_sim exists but holds only CMake files.
  fs::create_directories(share() / "cmake");
  EXPECT_EQ(packageDataDir(program(), "/src/brick_stack_sim"), "/src/brick_stack_sim");
}

TEST_F(PackageData, OnlyAProgramOfThisPackageLooksBesideItself) {
  installData();
  const std::string elsewhere = (prefix_ / "lib" / "other_package" / "stack_sim_run");
  EXPECT_EQ(packageDataDir(elsewhere, "/src/brick_stack_sim"), "/src/brick_stack_sim");
}

TEST_F(PackageData, TheTestProgramItselfReadsTheSourceTree) {
  // test_core runs from the build tree, far from any install space.
  EXPECT_EQ(packageDataDir("/src/brick_stack_sim"), "/src/brick_stack_sim");
}

}  // namespace
}  // namespace brick_stack_sim
