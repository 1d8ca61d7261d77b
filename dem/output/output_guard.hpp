// The one guard of every file a command writes (icedem run, resume, stl, flow, foam-case,
// calibrate): before any work, an output that would destroy what a user has is refused with
// InputError (exit 2) naming the option, the file and why. Nothing an input of the command, no
// file of another run, no directory, no empty name; its directory must exist and be writable.
#pragma once

#include <string>
#include <vector>

namespace icedem {

/// What a command writes at a path.
enum class OutputKind {
  kRun,        // a run's HDF5 output: replaces an earlier run's output of that name, never a
               // checkpoint nor a file that is not a run's output
  kFile,       // a text file (STL, CSV, JSON, a scenario): never replaces an HDF5 file (a run's
               // output, a checkpoint, a contact problem)
  kDirectory,  // a directory the command fills (an OpenFOAM case): never a file
};

struct PlannedOutput {
  std::string option;  // how the user named it: "-o", "--summary-json", ...
  std::string path;
  OutputKind kind = OutputKind::kFile;
  bool checkpoints = false;  // a run's output whose run writes PATH.checkpoint and PATH.checkpoint.tmp too
  bool torn = false;         // a killed run's output too damaged to read, which the command keeps aside
                             // (dem/output/run_files.hpp) before it replaces it: what is in it is not checked
};

/// Refuses (InputError naming the option, the file and the reason) an output that
///  - has an empty name;
///  - is an input of the command, or a file the command writes besides it (a run's checkpoint
///    and its temporary file count);
///  - is an existing directory (a file output) or an existing file (a directory output);
///  - lies in a directory that does not exist or cannot be written;
///  - would replace an HDF5 file with a text file, a checkpoint or a file that is not HDF5 with
///    a run's output (an empty file may be replaced; a torn run output kept aside may be too).
void guard_outputs(const std::vector<PlannedOutput>& outputs, const std::vector<std::string>& inputs);

/// Whether two paths name one file (the same path once resolved, or one file under two names).
bool same_file(const std::string& a, const std::string& b);

}  // namespace icedem
