#include "coupling/flow_grid.hpp"

#include <H5Cpp.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace icedem {

FlowGrid::FlowGrid(GridAxes axes, std::vector<Eigen::Vector3d> velocity, std::vector<unsigned char> solid)
    : axes_(axes), velocity_(std::move(velocity)), solid_(std::move(solid)) {
  if (axes_.nx < 2 || axes_.ny < 2 || axes_.nz < 2 || axes_.dx <= 0 || axes_.dy <= 0 || axes_.dz <= 0)
    throw std::invalid_argument("FlowGrid: at least 2 points and a positive spacing along each axis");
  if (velocity_.size() != static_cast<std::size_t>(axes_.count()) || solid_.size() != velocity_.size())
    throw std::invalid_argument("FlowGrid: one velocity and one solid flag per grid point");
}

Eigen::Vector3d FlowGrid::relative_velocity(const Eigen::Vector3d& p) const {
  const GridAxes& a = axes_;
  const double fx = (p.x() - a.x0) / a.dx, fz = (p.z() - a.z0) / a.dz;
  if (fx < 0 || fz < 0 || fx > a.nx - 1 || fz > a.nz - 1) return {-1.0, 0.0, 0.0};  // undisturbed
  const double fy = std::clamp((p.y() - a.y0) / a.dy, 0.0, double(a.ny - 1));
  const int i = std::min(static_cast<int>(fx), a.nx - 2), j = std::min(static_cast<int>(fy), a.ny - 2),
            k = std::min(static_cast<int>(fz), a.nz - 2);
  const double tx = fx - i, ty = fy - j, tz = fz - k;
  // trilinear over the cell's water points only, their weights renormalised: beside
  // the hull the water's own velocity is extended to the wall instead of being
  // pulled towards the hull's; a cell with no water point moves with the structure
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  double weight = 0;
  for (int c = 0; c < 8; ++c) {
    const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
    const double w = (di ? tx : 1 - tx) * (dj ? ty : 1 - ty) * (dk ? tz : 1 - tz);
    const int n = a.index(i + di, j + dj, k + dk);
    if (solid_[n]) continue;
    u += w * velocity_[n];
    weight += w;
  }
  return weight > 1e-12 ? Eigen::Vector3d(u / weight) : Eigen::Vector3d::Zero();
}

namespace {

void attr(H5::H5Object& o, const std::string& name, double v) {
  o.createAttribute(name, H5::PredType::NATIVE_DOUBLE, H5::DataSpace()).write(H5::PredType::NATIVE_DOUBLE, &v);
}
void attr(H5::H5Object& o, const std::string& name, const std::string& v) {
  H5::StrType t(H5::PredType::C_S1, std::max<std::size_t>(v.size(), 1));
  o.createAttribute(name, t, H5::DataSpace()).write(t, v.c_str());
}
double read_attr(const H5::H5Object& o, const std::string& name) {
  double v = 0;
  o.openAttribute(name).read(H5::PredType::NATIVE_DOUBLE, &v);
  return v;
}

}  // namespace

void FlowGrid::write(const std::string& path, const std::string& case_hash, const std::string& mesh) const {
  H5::H5File f(path, H5F_ACC_TRUNC);
  H5::Group root = f.openGroup("/");
  const GridAxes& a = axes_;
  for (auto [name, v] : {std::pair<const char*, double>{"x0", a.x0}, {"dx", a.dx}, {"nx", a.nx}, {"y0", a.y0},
                         {"dy", a.dy}, {"ny", a.ny}, {"z0", a.z0}, {"dz", a.dz}, {"nz", a.nz}})
    attr(root, name, v);
  attr(root, "case_hash", case_hash);
  attr(root, "mesh", mesh);
  attr(root, "source", "OpenFOAM potentialFoam, U = -grad(Phi) (leastSquares), sampled with probes");
  const hsize_t dims[4] = {hsize_t(a.ny), hsize_t(a.nz), hsize_t(a.nx), 3};
  std::vector<double> flat(3 * velocity_.size());
  for (std::size_t n = 0; n < velocity_.size(); ++n)
    for (int c = 0; c < 3; ++c) flat[3 * n + c] = velocity_[n][c];
  H5::DataSet v = f.createDataSet("velocity", H5::PredType::IEEE_F64LE, H5::DataSpace(4, dims));
  v.write(flat.data(), H5::PredType::NATIVE_DOUBLE);
  attr(v, "units", "1");
  attr(v, "description", "water velocity relative to the structure per unit tow speed (+x), structure frame");
  H5::DataSet s = f.createDataSet("solid", H5::PredType::STD_U8LE, H5::DataSpace(3, dims));
  s.write(solid_.data(), H5::PredType::NATIVE_UINT8);
  attr(s, "description", "1 where the point is not in the water (inside the hull)");
}

FlowGrid FlowGrid::read(const std::string& path) {
  try {
    H5::H5File f(path, H5F_ACC_RDONLY);
    H5::Group root = f.openGroup("/");
    GridAxes a{read_attr(root, "x0"), read_attr(root, "dx"), static_cast<int>(read_attr(root, "nx")),
               read_attr(root, "y0"), read_attr(root, "dy"), static_cast<int>(read_attr(root, "ny")),
               read_attr(root, "z0"), read_attr(root, "dz"), static_cast<int>(read_attr(root, "nz"))};
    std::vector<double> flat(3 * static_cast<std::size_t>(a.count()));
    f.openDataSet("velocity").read(flat.data(), H5::PredType::NATIVE_DOUBLE);
    std::vector<unsigned char> solid(a.count());
    f.openDataSet("solid").read(solid.data(), H5::PredType::NATIVE_UINT8);
    std::vector<Eigen::Vector3d> velocity(a.count());
    for (int n = 0; n < a.count(); ++n) velocity[n] = {flat[3 * n], flat[3 * n + 1], flat[3 * n + 2]};
    return FlowGrid(a, std::move(velocity), std::move(solid));
  } catch (const H5::Exception& e) {
    throw std::runtime_error(fmt::format("{}: not a flow grid file ({})", path, e.getDetailMsg()));
  }
}

GridFlowField::GridFlowField(FlowGrid grid) : grid_(std::move(grid)) {}

Eigen::Vector3d GridFlowField::velocity(const Eigen::Vector3d& x) const {
  // the grid's relative velocity plus the structure's own: zero far away
  return speed_ * (grid_.relative_velocity(x - axis_point_) + Eigen::Vector3d::UnitX());
}

void GridFlowField::set_structure(const Eigen::Vector3d& axis_point, const Eigen::Vector3d& velocity) {
  axis_point_ = Eigen::Vector3d(axis_point.x(), 0.0, axis_point.z());  // the grid's y is the tank's
  speed_ = velocity.x();
}

}  // namespace icedem
