#include "coupling/foam_runner.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "dem/core/errors.hpp"

namespace fs = std::filesystem;

namespace icedem {

std::string foam_case_dir(const FoamCaseSpec& spec, const std::string& cache_dir) {
  return (fs::path(cache_dir) / (spec.mesh + "-" + foam_case_hash(spec))).string();
}

FlowGrid grid_from_probes(const std::string& probes_file, const GridAxes& axes) {
  std::ifstream in(probes_file);
  if (!in) throw CouplingError(fmt::format("{}: no probe samples (did Allrun's 'probes' step run?)", probes_file));
  // comment lines (# Probe i (x y z), # Time), then one line per time: t (u v w) (u v w) ...
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') last = line;
  std::vector<Eigen::Vector3d> velocity;
  std::vector<unsigned char> solid;
  velocity.reserve(axes.count());
  solid.reserve(axes.count());
  for (std::size_t at = last.find('('); at != std::string::npos; at = last.find('(', at + 1)) {
    std::istringstream v(last.substr(at + 1, last.find(')', at) - at - 1));
    Eigen::Vector3d g;
    if (!(v >> g.x() >> g.y() >> g.z()))
      throw CouplingError(fmt::format("{}: sample {} is not a vector", probes_file, velocity.size()));
    const bool outside = !(g.cwiseAbs().maxCoeff() < 1e100);  // -1e300: no cell holds the point
    solid.push_back(outside);
    velocity.push_back(outside ? Eigen::Vector3d::Zero() : Eigen::Vector3d(-g));  // U = -grad(Phi)
  }
  if (velocity.size() != static_cast<std::size_t>(axes.count()))
    throw CouplingError(fmt::format("{}: {} samples for {} grid points", probes_file, velocity.size(), axes.count()));
  return FlowGrid(axes, std::move(velocity), std::move(solid));
}

namespace {

std::string tail(const fs::path& file, int lines) {
  std::ifstream in(file);
  std::vector<std::string> all;
  for (std::string l; std::getline(in, l);) all.push_back(l);
  std::string out;
  for (std::size_t i = all.size() > std::size_t(lines) ? all.size() - lines : 0; i < all.size(); ++i)
    out += "\n  " + all[i];
  return out;
}

}  // namespace

FlowGrid solved_flow_grid(const Scene& scene, std::ostream& log) {
  const FoamCaseSpec spec = foam_case_spec(scene);
  const fs::path dir = foam_case_dir(spec, scene.coupling.cache_dir);
  const fs::path grid_file = dir / "flow_grid.h5";
  if (fs::exists(grid_file)) {
    log << fmt::format("coupled flow: the solved case {} (cached)\n", dir.string());
    return FlowGrid::read(grid_file.string());
  }
  // solve in a private directory, then publish it with one rename
  std::error_code ec;
  fs::create_directories(dir.parent_path(), ec);
  if (ec) throw CouplingError(fmt::format("coupling.cache_dir {}: cannot create it ({})", dir.parent_path().string(), ec.message()));
  const fs::path work = dir.string() + fmt::format(".tmp-{}", ::getpid());
  fs::remove_all(work);
  write_foam_case(spec, foam_template_dir(), work.string());
  log << fmt::format("coupled flow: meshing and solving the OpenFOAM case in {} ({} mesh) ...\n", work.string(), spec.mesh);
  const auto start = std::chrono::steady_clock::now();
  const fs::path allrun_log = work / "log.Allrun";
  const int status = std::system(fmt::format("'{}' > '{}' 2>&1", (work / "Allrun").string(), allrun_log.string()).c_str());
  if (status != 0)
    throw CouplingError(fmt::format("OpenFOAM case {} failed (Allrun exit {}):{}", work.string(),
                                    WIFEXITED(status) ? WEXITSTATUS(status) : status, tail(allrun_log, 12)));
  FlowGrid grid = grid_from_probes((work / "postProcessing" / "grid" / "0" / "gradPhi").string(), foam_grid_axes(spec));
  grid.write((work / "flow_grid.h5").string(), foam_case_hash(spec), spec.mesh);
  fs::rename(work, dir, ec);  // another run may have published the same case first: use theirs
  if (ec) fs::remove_all(work);
  log << fmt::format("coupled flow: solved in {:.1f} s, cached in {}\n",
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), dir.string());
  return FlowGrid::read(grid_file.string());
}

}  // namespace icedem
