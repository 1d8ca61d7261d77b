#include "dem/output/output_guard.hpp"

#include <H5Cpp.h>

#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <fmt/format.h>

#include "dem/core/errors.hpp"
#include "dem/core/hdf5_io.hpp"
#include "dem/core/isolated_read.hpp"
#include "dem/output/checkpoint.hpp"

namespace icedem {
namespace fs = std::filesystem;
namespace {

// HDF5's signature at the start of a file (where icedem, libfclib and h5py put the superblock)
bool is_hdf5(const std::string& path) {
  std::array<char, 8> head{};
  std::ifstream in(path, std::ios::binary);
  return in.read(head.data(), head.size()) && std::memcmp(head.data(), "\x89HDF\r\n\x1a\n", 8) == 0;
}

// an HDF5 file holding a run's resumable state (dem/output/checkpoint.hpp); one HDF5 cannot read
// counts by its name. Read in a child process, as every file a command did not write
// (dem/core/isolated_read.hpp): HDF5 may crash on a damaged one
bool is_checkpoint(const std::string& path) {
  if (!is_hdf5(path)) return false;
  const IsolatedResult found = read_isolated(
      [&] {
        QuietHdf5 quiet;
        const H5::H5File file(path, H5F_ACC_RDONLY, H5::FileCreatPropList::DEFAULT, unlocked_access());
        return std::string(file.nameExists("/checkpoint") ? "yes" : "no");
      },
      60.0);
  if (found.ok) return found.value == "yes";
  return path.size() > 11 && path.compare(path.size() - 11, 11, ".checkpoint") == 0;
}

// the files the command writes, each with how the user named it: the outputs, and the
// checkpoint and temporary file of each run output that checkpoints
std::vector<std::pair<std::string, std::string>> written(const std::vector<PlannedOutput>& outputs) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const PlannedOutput& o : outputs) {
    out.emplace_back(o.option, o.path);
    if (o.checkpoints) {
      out.emplace_back(fmt::format("the checkpoint of {} {}", o.option, o.path), checkpoint_path(o.path));
      out.emplace_back(fmt::format("the temporary checkpoint of {} {}", o.option, o.path),
                       checkpoint_path(o.path) + ".tmp");
    }
  }
  return out;
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::equivalent(a, b, ec)) return true;
  const auto resolved = [](const std::string& p) {
    std::error_code e;
    return fs::weakly_canonical(fs::absolute(p), e);
  };
  return resolved(a) == resolved(b);
}

void guard_outputs(const std::vector<PlannedOutput>& outputs, const std::vector<std::string>& inputs) {
  for (const PlannedOutput& o : outputs)
    if (o.path.empty()) throw InputError(fmt::format("{} '': give a file name", o.option));
  // an input, or twice written
  const auto files = written(outputs);
  for (std::size_t i = 0; i < files.size(); ++i) {
    const auto& [option, path] = files[i];
    for (const std::string& input : inputs)
      if (!input.empty() && same_file(path, input))
        throw InputError(fmt::format("{} {}: that is an input of the command ({}); choose another file", option, path,
                                     input));
    for (std::size_t j = 0; j < i; ++j)
      if (same_file(path, files[j].second))
        throw InputError(fmt::format("{} {}: the command writes that file already ({}); choose another file", option,
                                     path, files[j].first));
  }
  // what is there now
  std::error_code ec;
  for (const PlannedOutput& o : outputs) {
    const std::string& path = o.path;
    const bool exists = fs::exists(path, ec);
    if (o.kind != OutputKind::kDirectory && fs::is_directory(path, ec))
      throw InputError(fmt::format("{} {}: that is a directory; give a file name", o.option, path));
    if (o.kind == OutputKind::kDirectory && exists && !fs::is_directory(path, ec))
      throw InputError(fmt::format("{} {}: that is a file; give a directory for the case", o.option, path));
    const fs::path dir = fs::absolute(path).parent_path();
    if (!fs::is_directory(dir, ec))
      throw InputError(fmt::format("{} {}: the directory {} does not exist", o.option, path, dir.string()));
    if (::access(dir.c_str(), W_OK) != 0 || (exists && ::access(path.c_str(), W_OK) != 0))
      throw InputError(fmt::format("{} {}: cannot write there ({} is not writable)", o.option, path,
                                   exists ? path : dir.string()));
    if (exists && o.kind != OutputKind::kDirectory && !o.torn && fs::file_size(path, ec) > 0) {
      if (o.kind == OutputKind::kFile && is_hdf5(path))
        throw InputError(fmt::format("{} {}: that is an HDF5 file (a run's output, a checkpoint or a contact "
                                     "problem) and would be replaced; choose another file",
                                     o.option, path));
      if (o.kind == OutputKind::kRun && is_checkpoint(path))
        throw InputError(fmt::format("{} {}: that is a run's checkpoint, what `icedem resume` continues a killed "
                                     "run from; choose another file",
                                     o.option, path));
      if (o.kind == OutputKind::kRun && !is_hdf5(path))
        throw InputError(fmt::format("{} {}: that file is not a run's output and would be replaced; choose "
                                     "another file",
                                     o.option, path));
    }
  }
}

}  // namespace icedem
