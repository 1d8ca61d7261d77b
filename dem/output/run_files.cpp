#include "dem/output/run_files.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "dem/core/errors.hpp"

namespace icedem {
namespace fs = std::filesystem;

bool RunFiles::resumable() const {
  if (!checkpoint_exists) return false;
  return !meta || (meta->status != "complete" && meta->status != "failed");
}

RunFiles look_at_run(const std::string& output) {
  RunFiles f;
  f.output = output;
  f.checkpoint = checkpoint_path(output);
  std::error_code ec;
  f.output_exists = fs::exists(output, ec) && !(fs::is_regular_file(output, ec) && fs::file_size(output, ec) == 0);
  f.checkpoint_exists = fs::exists(f.checkpoint, ec);
  if (f.output_exists) try {
      f.meta = read_output_meta(output);
    } catch (const InputError& e) {
      f.damage = e.what();
    }
  return f;
}

std::string keep_aside(const std::string& path) {
  std::error_code ec;
  for (int n = 1; n < 1000; ++n) {
    const std::string name = path + ".damaged" + (n > 1 ? fmt::format(".{}", n) : "");
    if (fs::exists(name, ec)) continue;
    // copy, not rename: the caller holds the output's lock on its inode
    if (!fs::copy_file(path, name, fs::copy_options::none, ec) || ec)
      throw OutputError(fmt::format("{}: cannot keep the damaged output as {}: {}", path, name, ec.message()));
    return name;
  }
  throw OutputError(fmt::format("{}: cannot keep the damaged output: {}.damaged to .damaged.999 all exist", path, path));
}

std::optional<std::string> output_of_checkpoint(const std::string& path) {
  const std::string suffix = checkpoint_path("");
  if (path.size() <= suffix.size() || path.compare(path.size() - suffix.size(), suffix.size(), suffix) != 0)
    return std::nullopt;
  return path.substr(0, path.size() - suffix.size());
}

}  // namespace icedem
