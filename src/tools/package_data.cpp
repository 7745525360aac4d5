#include "brick_stack_sim/tools/package_data.h"

#include <filesystem>
#include <system_error>

namespace brick_stack_sim {

std::string packageDataDir(const std::string& executable, const std::string& source_dir) {
  namespace fs = std::filesystem;
  const fs::path program(executable);
  // <prefix>/lib/brick_stack_sim/<program> -> <prefix>/share/brick_stack_sim
  const fs::path package_lib = program.parent_path();
  if (package_lib.filename() == "brick_stack_sim") {
    const fs::path share = package_lib.parent_path().parent_path() / "share" / "brick_stack_sim";
    std::error_code error;
    if (fs::is_regular_file(share / "urdf" / "bricks.urdf", error)) return share.string();
  }
  return source_dir;
}

std::string packageDataDir(const std::string& source_dir) {
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? source_dir : packageDataDir(self.string(), source_dir);
}

}  // namespace brick_stack_sim
