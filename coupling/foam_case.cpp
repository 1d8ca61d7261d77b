#include "coupling/foam_case.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "dem/world/cone_geometry.hpp"

namespace fs = std::filesystem;

namespace icedem {

namespace {

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("{}: cannot read", p.string()));
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

FoamCaseSpec foam_case_spec(const Scene& scene) {
  const CouplingSettings& c = scene.coupling;
  // background cell and hull refinement per mesh (docs/model/openfoam.md: coarse ~15k cells,
  // medium ~110k, fine ~300k; rms speed differences 0.35 % and 0.13 % against fine)
  const std::map<std::string, std::pair<double, int>> meshes{{"coarse", {0.2, 2}}, {"medium", {0.1, 2}},
                                                             {"fine", {0.1, 3}}};
  const auto [cell, level] = meshes.at(c.mesh);
  return FoamCaseSpec{scene.structure.profile, scene.structure.segments, c.domain_length,
                      scene.channel.tank_width, scene.channel.tank_depth, c.mesh, cell, level,
                      c.grid_spacing, c.grid_depth};
}

std::string foam_case_inputs(const FoamCaseSpec& s) {
  // bump the version when the conversion of the samples (foam_runner.cpp) changes
  std::string t = "icedem foam case v2\nprofile";
  for (const ProfileStation& p : s.profile) t += fmt::format(" ({:.17g} {:.17g})", p.y, p.radius);
  t += fmt::format("\nsegments {}\nlength {:.17g}\nwidth {:.17g}\ndepth {:.17g}\nmesh {}\ncell {:.17g}\nlevel {}\n"
                   "grid_spacing {:.17g}\ngrid_depth {:.17g}\n",
                   s.segments, s.length, s.width, s.depth, s.mesh, s.cell, s.level, s.grid_spacing, s.grid_depth);
  // the template's own files are inputs too: a changed dictionary must not reuse an old solution
  const fs::path tpl = foam_template_dir();
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(tpl))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) t += "file " + fs::relative(f, tpl).string() + "\n" + read_file(f);
  return t;
}

std::string foam_case_hash(const FoamCaseSpec& spec) {
  std::uint64_t h = 1469598103934665603ULL;  // FNV-1a 64
  for (unsigned char ch : foam_case_inputs(spec)) {
    h ^= ch;
    h *= 1099511628211ULL;
  }
  return fmt::format("{:016x}", h);
}

GridAxes foam_grid_axes(const FoamCaseSpec& s) {
  const double d = s.grid_spacing;
  const int nx = static_cast<int>(std::floor(s.length / d + 1e-9)) + 1;
  const int nz = static_cast<int>(std::floor(s.width / d + 1e-9)) + 1;
  const int ny = static_cast<int>(std::ceil(s.grid_depth / d - 1e-9)) + 1;
  // centred in x and z; y from -grid_depth up to the lid in equal steps
  return GridAxes{-(nx - 1) * d / 2, d, nx, -s.grid_depth, s.grid_depth / (ny - 1), ny, -(nz - 1) * d / 2, d, nz};
}

std::string foam_template_dir() {
  const char* env = std::getenv("ICEDEM_FOAM_TEMPLATE");
  return env && *env ? env : ICEDEM_FOAM_TEMPLATE;
}

namespace {

void write_file(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream out(p, std::ios::binary);
  if (!(out << text)) throw std::runtime_error(fmt::format("{}: cannot write", p.string()));
}

std::string fill(const std::string& text, const std::map<std::string, std::string>& tokens, const fs::path& file) {
  std::string out = text;
  for (const auto& [k, v] : tokens) {
    const std::string token = "@" + k + "@";
    for (std::size_t at = out.find(token); at != std::string::npos; at = out.find(token, at + v.size()))
      out.replace(at, token.size(), v);
  }
  std::smatch m;
  if (std::regex_search(out, m, std::regex("@[A-Z0-9_]+@")))
    throw std::runtime_error(fmt::format("{}: unknown token {} in the template", file.string(), m.str()));
  return out;
}

// the probes function object listing every grid point; a point on the lid is
// sampled 1 mm below it (a probe on a boundary face may find no cell)
std::string probes_dict(const GridAxes& a) {
  std::string s =
      "FoamFile { version 2.0; format ascii; class dictionary; object probesDict; }\n"
      "// Written by icedem foam-case: the grid points (coupling/flow_grid.hpp), y slowest, then z, then x.\n"
      "functions\n{\n    grid\n    {\n        type probes;\n        libs (\"libsampling.so\");\n"
      "        fields (gradPhi);\n        writeControl writeTime;\n"
      // cellPoint: interpolated; the default is the containing cell's value, up to half a cell off
      "        interpolationScheme cellPoint;\n        probeLocations\n        (\n";
  for (int j = 0; j < a.ny; ++j)
    for (int k = 0; k < a.nz; ++k)
      for (int i = 0; i < a.nx; ++i) {
        Eigen::Vector3d p = a.point(i, j, k);
        p.y() = std::min(p.y(), -1e-3);
        s += fmt::format("            ({:.6g} {:.6g} {:.6g})\n", p.x(), p.y(), p.z());
      }
  return s + "        );\n    }\n}\n";
}

}  // namespace

void write_foam_case(const FoamCaseSpec& s, const std::string& template_dir, const std::string& case_dir) {
  const fs::path tpl(template_dir), dir(case_dir);
  if (!fs::is_directory(tpl / "system")) throw std::runtime_error(fmt::format("{}: not the foam_case template", template_dir));
  const double x0 = -s.length / 2, x1 = s.length / 2, z0 = -s.width / 2, z1 = s.width / 2;
  auto cells = [&](double extent) { return std::max(1, static_cast<int>(std::lround(extent / s.cell))); };
  // a point in the water, off every background cell face and away from the hull
  const std::string inside = fmt::format("{:.6g} {:.6g} {:.6g}", x1 - 1.37 * s.cell, -0.617 * s.depth, z1 - 1.29 * s.cell);
  const std::map<std::string, std::string> tokens{
      {"X0", fmt::format("{:.9g}", x0)}, {"X1", fmt::format("{:.9g}", x1)}, {"Y0", fmt::format("{:.9g}", -s.depth)},
      {"Z0", fmt::format("{:.9g}", z0)}, {"Z1", fmt::format("{:.9g}", z1)}, {"NX", std::to_string(cells(s.length))},
      {"NY", std::to_string(cells(s.depth))}, {"NZ", std::to_string(cells(s.width))},
      {"LEVEL", std::to_string(s.level)}, {"INSIDE", inside}};
  for (const auto& e : fs::recursive_directory_iterator(tpl)) {
    if (!e.is_regular_file()) continue;
    const fs::path rel = fs::relative(e.path(), tpl);
    if (rel.extension() == ".in") {
      fs::path out = dir / rel;
      out.replace_extension();
      write_file(out, fill(read_file(e.path()), tokens, e.path()));
    } else {
      fs::create_directories((dir / rel).parent_path());
      fs::copy_file(e.path(), dir / rel, fs::copy_options::overwrite_existing);
    }
  }
  fs::create_directories(dir / "constant" / "triSurface");
  write_stl(hull_surface(s.profile, s.segments), (dir / "constant" / "triSurface" / "structure.stl").string(),
            "structure");
  write_file(dir / "system" / "probesDict", probes_dict(foam_grid_axes(s)));
  write_file(dir / "case.inputs", foam_case_inputs(s));
  write_file(dir / "case.hash", foam_case_hash(s) + "\n");
}

}  // namespace icedem
