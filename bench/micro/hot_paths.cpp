// Microbenchmarks of the hot paths of a step (Google Benchmark): buoyancy
// clipping, the water wrench (buoyancy, drag, damping), the load-cell sum over
// a compacted field's manifolds, joint-load decomposition, and layout
// generation, and the checkpoint's digest beside the copy it is taken of. Run: build/bench/micro/icedem_micro (scripts/bench.sh --micro).
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

#include "dem/core/hdf5_io.hpp"
#include "dem/fracture/joint_loads.hpp"
#include "dem/input/scenario.hpp"
#include "dem/layout/floe_layout.hpp"
#include "dem/output/file_digest.hpp"
#include "dem/step/initial_state.hpp"
#include "dem/step/step.hpp"
#include "dem/water/flow_field.hpp"
#include "dem/water/hydrostatics.hpp"
#include "dem/water/water_forces.hpp"
#include "dem/world/load_cell.hpp"
#include "dem/world/world.hpp"

using namespace icedem;

namespace {

// a floe of the paper's small ones, heeled and heaving a little: the clipping's usual case
const std::vector<Eigen::Vector2d> kSquare{{-0.15, -0.15}, {0.15, -0.15}, {0.15, 0.15}, {-0.15, 0.15}};

Eigen::Isometry3d heeled_pose() {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(0.05, Eigen::Vector3d::UnitX()) *
                   Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()))
                      .toRotationMatrix();
  pose.translation() = Eigen::Vector3d(5.0, -0.012, 0.3);
  return pose;
}

void BM_BuoyancyClipping(benchmark::State& s) {
  const ConvexPolyhedron prism = make_prism(kSquare, 0.033);
  const Eigen::Isometry3d pose = heeled_pose();
  Submersion sub;
  for (auto _ : s) {
    submerge(prism, pose, 0.0, sub);
    benchmark::DoNotOptimize(sub.volume);
  }
}
BENCHMARK(BM_BuoyancyClipping);

void BM_WaterWrench(benchmark::State& s) {
  const ConvexPolyhedron prism = make_prism(kSquare, 0.033);
  const WaterParams water{};
  const double mass = 930.0 * 0.3 * 0.3 * 0.033;
  const DampingCoefficients d = damping_coefficients(prism, mass, mass * (0.09 + 0.033 * 0.033) / 12, water);
  StillWater flow;
  BodyMotion motion{heeled_pose(), Eigen::Vector3d(0.05, -0.01, 0.02), Eigen::Vector3d(0.1, 0.2, -0.05)};
  for (auto _ : s) benchmark::DoNotOptimize(water_wrench(prism, motion, flow, water, d));
}
BENCHMARK(BM_WaterWrench);

void BM_JointLoadDecomposition(benchmark::State& s) {
  const Eigen::Vector3d F(1.5, -3.0, 0.25), T(0.05, 0.1, -0.2), c(1, 0, 2), mid(1.075, 0, 2);
  const Eigen::Vector3d n(1, 0, 0), up(0, 1, 0);
  for (auto _ : s) benchmark::DoNotOptimize(decompose_joint_load(F, T, c, mid, n, up));
}
BENCHMARK(BM_JointLoadDecomposition);

void BM_LayoutGeneration(benchmark::State& s) {
  LayoutParams p;  // the paper's small floes: 960 floes at 75 % in 24 m x 4.8 m
  p.channel = Channel{6.0, 30.0, -2.4, 2.4};
  for (auto _ : s) benchmark::DoNotOptimize(generate_square_layout(p).floes.size());
  s.SetLabel("960 floes");
}
BENCHMARK(BM_LayoutGeneration)->Unit(benchmark::kMillisecond);

// the load-cell sum over every manifold of a compacted field: the small-floe scenario
// after 60 s of towing (structure in the ice, about 3000 contact points)
void BM_LoadCellSum(benchmark::State& s) {
  const Scene scene = load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/paper/small_floes.toml");
  State state = initial_state(scene, scene_layout(scene).floes);
  while (state.time < 60.0) step(scene, state);
  const btDispatcher& dispatcher = *state.world->dynamics().getDispatcher();
  for (auto _ : s) {
    LoadCell cell;
    cell.accumulate(dispatcher, state.world->structure(), state.structure_position);
    benchmark::DoNotOptimize(cell.finish(scene.time.dt));
  }
  s.SetLabel(std::to_string(dispatcher.getNumManifolds()) + " manifolds");
}
BENCHMARK(BM_LoadCellSum)->Unit(benchmark::kMicrosecond);

// A file the size of the paper small-floe run's output (12 MB): 6000 steps of 250 floes' positions,
// compressed as the recorder writes them. A checkpoint copies it and then digests it: the digest's
// cost is read against the copy's, in the same run
const std::string& output_like_file() {
  static const std::string path = [] {
    const std::string p = (std::filesystem::temp_directory_path() / "icedem_micro_digest.h5").string();
    H5::H5File file(p, H5F_ACC_TRUNC);
    const H5::Group g = file.createGroup("/floes");
    Series positions = create_series(g, "position", H5::PredType::IEEE_F64LE, {250, 3}, 64, "m", "positions", true);
    std::vector<double> row(250 * 3);
    for (int step = 0; step < 6000; ++step) {
      for (std::size_t k = 0; k < row.size(); ++k) row[k] = std::sin(0.001 * step * (k % 17 + 1)) + 1e-7 * k * step;
      positions.write(row.data(), 1, H5::PredType::NATIVE_DOUBLE);
    }
    return p;
  }();
  return path;
}

void BM_CheckpointCopy(benchmark::State& s) {
  const std::string from = output_like_file(), to = from + ".copy";
  for (auto _ : s) std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing);
  s.SetLabel(std::to_string(std::filesystem::file_size(from) >> 20) + " MB file");
}
BENCHMARK(BM_CheckpointCopy)->Unit(benchmark::kMillisecond);

void BM_CheckpointDigest(benchmark::State& s) {
  const H5::H5File file(output_like_file(), H5F_ACC_RDONLY);
  for (auto _ : s) benchmark::DoNotOptimize(file_digest(file).size());
  s.SetLabel("36 MB of values");
}
BENCHMARK(BM_CheckpointDigest)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
