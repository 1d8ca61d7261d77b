// The crushing contact's nominal areas (dem/contact/contact_area.hpp): icedem's own hull and
// clipping against Boost.Geometry's on the sections of the paper's floes, the case a crushing
// run meets once or twice per contact manifold and substep. Run: build/bench/micro/icedem_micro
// --benchmark_filter=Section.
#include <benchmark/benchmark.h>

#include <vector>

#include <Eigen/Geometry>

#include "dem/contact/contact_area.hpp"
#include "tests/support/boost_section.hpp"

using namespace icedem;

namespace {

// a 0.3 m floe turned 45 degrees about the vertical (its corner along x) and a second one
// overlapping it edge on, and the cone's 45-degree face cutting the first's corner 3 mm deep
std::vector<Eigen::Vector3d> floe(double yaw, const Eigen::Vector3d& centre) {
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix();
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < 8; ++i)
    v.push_back(centre + turn * Eigen::Vector3d((i & 1 ? 0.15 : -0.15), (i & 2 ? 0.0165 : -0.0165), (i & 4 ? 0.15 : -0.15)));
  return v;
}
const std::vector<Eigen::Vector3d> kFloe = floe(M_PI / 4, Eigen::Vector3d::Zero());
const std::vector<Eigen::Vector3d> kNeighbour = floe(0.1, Eigen::Vector3d(0.36, 0.0, 0.05));
const Plane kFace{Eigen::Vector3d(0.2121 - 0.003 / std::sqrt(0.5), 0, 0),
                  Eigen::Vector3d(std::sqrt(0.5), -std::sqrt(0.5), 0)};
const Plane kBetween{Eigen::Vector3d(0.2, 0, 0), Eigen::Vector3d::UnitX()};

void BM_SectionOwn(benchmark::State& s) {
  for (auto _ : s) benchmark::DoNotOptimize(section_area(kFloe, kFace));
}
void BM_SectionBoost(benchmark::State& s) {
  for (auto _ : s) benchmark::DoNotOptimize(testing::boost_section_area(kFloe, kFace));
}
void BM_CommonSectionOwn(benchmark::State& s) {
  for (auto _ : s) benchmark::DoNotOptimize(common_section_area(kFloe, kNeighbour, kBetween));
}
void BM_CommonSectionBoost(benchmark::State& s) {
  for (auto _ : s) benchmark::DoNotOptimize(testing::boost_common_section_area(kFloe, kNeighbour, kBetween));
}
BENCHMARK(BM_SectionOwn);
BENCHMARK(BM_SectionBoost);
BENCHMARK(BM_CommonSectionOwn);
BENCHMARK(BM_CommonSectionBoost);

}  // namespace
