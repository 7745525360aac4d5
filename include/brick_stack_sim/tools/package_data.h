#pragma once

#include <string>

namespace brick_stack_sim {

/// Where the package's urdf/, config/ and scenes/ are for one of its programs
/// at `executable`: a program installed by `catkin_make install` sits in
/// <prefix>/lib/brick_stack_sim/ and its data in <prefix>/share/brick_stack_sim/,
/// found there when that holds urdf/bricks.urdf; anywhere else (the devel
/// space, whose share/ holds only CMake files) it is `source_dir`, the
/// package it was built from. Relative to the program rather than a path
/// fixed at build time, so that an install space does not read the source
/// tree, and can be moved.
std::string packageDataDir(const std::string& executable, const std::string& source_dir);

/// packageDataDir() of the running program (/proc/self/exe).
std::string packageDataDir(const std::string& source_dir);

}  // namespace brick_stack_sim
