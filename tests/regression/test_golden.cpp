// Golden runs: short runs whose load series, breaks and summary are stored under
// tests/regression/data and compared with every build, so that a change that
// moves results fails here unless it is meant to (then regenerate, below).
//
// How the tolerances separate round-off from a real change. The runs are
// chaotic: two runs that differ by round-off follow each other closely for a
// while after the first ice contact, then diverge. So the stored data carries
// its own horizon, measured when it is generated: the case is run again with
// the structure's start moved by k x 1e-13 of its value (k = 1..6; a thousand
// times the round-off of one operation) and the horizon is the last time up to
// which every one of those twins stays within 1e-6 N of the stored load on
// every force component, with the same breaks. Up to the horizon a build must
// do the same; a real change, even friction 0.200 -> 0.201, moves the load by
// 1e-3 N at the first contact (test below). Beyond the horizon two runs are two
// samples of the same process, so the summary (mean, max and std of the surge
// load, over the whole record) is compared within three times the root mean
// square deviation of the twins from the stored run.
//
// Regenerate (after a change meant to move results; say why in CHANGELOG.md):
//   ICEDEM_REGENERATE_GOLDEN=1 build/tests/test_golden
#include <gtest/gtest.h>

#include <H5Cpp.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "coupling/coupled_flow.hpp"
#include "dem/input/scenario.hpp"
#include "dem/run/simulation.hpp"

using namespace icedem;

namespace {

constexpr double kTolerance = 1e-6;  // N, on every force component up to the horizon
constexpr int kTwins = 6;
constexpr double kTwinShift = 1e-13;  // relative shift of structure.start_x per twin step

struct GoldenCase {
  std::string name;
  std::string scenario;  // relative to the source tree
  std::vector<std::string> sets;
};

const std::string kTmp = ICEDEM_TEST_TMP;
const std::string kData = std::string(ICEDEM_SOURCE_DIR) + "/tests/regression/data";

const std::vector<GoldenCase>& cases() {
  static const std::vector<GoldenCase> c{
      // rigid floes, the default numerics; first contact at 5.7 s, statistics from 7.1 s
      {"small_rigid", "scenarios/examples/short_tow.toml", {"time.duration=16", "stats.window_start_travel=0.1"}},
      // 0.6 m floes of 0.15 m elements hit fast (0.2 m/s) with weak joints (6 kPa), so that
      // joints break inside the horizon: the twins of a solve stopped at a merit of 1e-3 part
      // 0.2 s after the first contact (1.26 s), and the first joints break at 1.28 s
      {"breakable",
       "scenarios/paper/large_floes_breakable_015.toml",
       {"time.duration=4", "channel.start_x=3.0", "channel.length=3.6", "channel.width=3.0",
        "ice.concentration=0.6", "structure.start_x=2.2", "structure.speed=0.2", "ice.bending_strength=6e3",
        "stats.window_start_travel=0.2"}},
      // the OpenFOAM potential flow (field mode) instead of the analytic one
      {"coupled_field",
       "scenarios/examples/short_tow.toml",
       {"time.duration=16", "stats.window_start_travel=0.1", "flow.model=coupled",
        "coupling.cache_dir=" + kTmp + "/golden_foam_cache"}},  // its own: ctest runs the OpenFOAM tests beside
  };
  return c;
}

struct Sample {
  double time, fx, fy, fz;
  int contacts;
};

struct Break {
  double time;
  int floe, joint, mode, mechanism;
  bool operator==(const Break& o) const {
    return time == o.time && floe == o.floe && joint == o.joint && mode == o.mode && mechanism == o.mechanism;
  }
};

struct Result {
  std::vector<Sample> load;
  std::vector<Break> breaks;
  RunSummary summary;
};

template <typename T>
std::vector<T> read_vector(const H5::H5File& f, const std::string& path, const H5::PredType& type) {
  H5::DataSet d = f.openDataSet(path);
  H5::DataSpace space = d.getSpace();
  std::vector<hsize_t> dims(space.getSimpleExtentNdims());
  space.getSimpleExtentDims(dims.data());
  std::size_t n = 1;
  for (hsize_t x : dims) n *= x;
  std::vector<T> v(n);
  if (n) d.read(v.data(), type);
  return v;
}

// `tag` names the output file: ctest runs the tests of this file in parallel
Result run_case(const GoldenCase& c, std::vector<std::string> extra = {}, const std::string& tag = "") {
  std::vector<std::string> sets = c.sets;
  sets.insert(sets.end(), extra.begin(), extra.end());
  const Scene scene = load_scene(std::string(ICEDEM_SOURCE_DIR) + "/" + c.scenario, sets);
  const std::string out = kTmp + "/golden_" + c.name + tag + ".h5";
  Result r;
  r.summary = run_simulation(scene, RunOptions{out, false, "test_golden", openfoam_coupling(), {}});
  H5::H5File f(out, H5F_ACC_RDONLY);
  const auto t = read_vector<double>(f, "/load/time", H5::PredType::NATIVE_DOUBLE);
  const auto force = read_vector<double>(f, "/load/force", H5::PredType::NATIVE_DOUBLE);
  const auto contacts = read_vector<int>(f, "/load/cone_contacts", H5::PredType::NATIVE_INT);
  for (std::size_t i = 0; i < t.size(); ++i)
    r.load.push_back({t[i], force[3 * i], force[3 * i + 1], force[3 * i + 2], contacts[i]});
  // the events as stored: a compound, read member by member
  H5::DataSet ev = f.openDataSet("/fracture/events");
  const hsize_t n = ev.getSpace().getSimpleExtentNpoints();
  if (n) {
    H5::CompType type(sizeof(Break));
    type.insertMember("time", HOFFSET(Break, time), H5::PredType::NATIVE_DOUBLE);
    type.insertMember("floe", HOFFSET(Break, floe), H5::PredType::NATIVE_INT);
    type.insertMember("joint", HOFFSET(Break, joint), H5::PredType::NATIVE_INT);
    type.insertMember("mode", HOFFSET(Break, mode), H5::PredType::NATIVE_INT);
    type.insertMember("mechanism", HOFFSET(Break, mechanism), H5::PredType::NATIVE_INT);
    r.breaks.resize(n);
    ev.read(r.breaks.data(), type);
  }
  return r;
}

// the last time up to which `b` follows `a` within the tolerance, with the same breaks
double agreement_horizon(const Result& a, const Result& b) {
  double first_bad = INFINITY;
  for (std::size_t i = 0; i < std::min(a.load.size(), b.load.size()); ++i) {
    const Sample &x = a.load[i], &y = b.load[i];
    if (std::abs(x.fx - y.fx) > kTolerance || std::abs(x.fy - y.fy) > kTolerance ||
        std::abs(x.fz - y.fz) > kTolerance || x.contacts != y.contacts) {
      first_bad = x.time;
      break;
    }
  }
  for (std::size_t i = 0; i < std::max(a.breaks.size(), b.breaks.size()); ++i) {
    if (i < a.breaks.size() && i < b.breaks.size() && a.breaks[i] == b.breaks[i]) continue;
    const double ta = i < a.breaks.size() ? a.breaks[i].time : INFINITY;
    const double tb = i < b.breaks.size() ? b.breaks[i].time : INFINITY;
    first_bad = std::min(first_bad, std::min(ta, tb));
    break;
  }
  if (!std::isfinite(first_bad)) return a.load.empty() ? 0.0 : a.load.back().time;
  // the sample before the first disagreement
  double last_good = 0.0;
  for (const Sample& s : a.load)
    if (s.time < first_bad) last_good = s.time;
  return last_good;
}

double summary_value(const RunSummary& s, const std::string& key) {
  if (key == "mean") return s.surge.mean;
  if (key == "max") return s.surge.max;
  return s.surge.std;
}
const std::vector<std::string> kSummaryKeys{"mean", "max", "std"};

std::string csv_path(const GoldenCase& c) { return kData + "/golden_" + c.name + ".csv"; }
std::string json_path(const GoldenCase& c) { return kData + "/golden_" + c.name + ".json"; }

void regenerate(const GoldenCase& c) {
  const Result base = run_case(c);
  ASSERT_TRUE(base.summary.has_statistics) << c.name << ": " << base.summary.statistics_note;
  const Scene scene = load_scene(std::string(ICEDEM_SOURCE_DIR) + "/" + c.scenario, c.sets);
  double horizon = INFINITY;
  std::vector<std::vector<double>> deviation(kSummaryKeys.size());
  for (int k = 1; k <= kTwins; ++k) {
    const double x = scene.structure.start_x * (1.0 + k * kTwinShift);
    const Result twin = run_case(c, {fmt::format("structure.start_x={:.17g}", x)}, "_twin");
    horizon = std::min(horizon, agreement_horizon(base, twin));
    for (std::size_t j = 0; j < kSummaryKeys.size(); ++j)
      deviation[j].push_back(summary_value(twin.summary, kSummaryKeys[j]) -
                             summary_value(base.summary, kSummaryKeys[j]));
  }
  std::ofstream csv(csv_path(c));
  csv << "time_s,fx_N,fy_N,fz_N,cone_contacts\n";
  for (const Sample& s : base.load)
    csv << fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{}\n", s.time, s.fx, s.fy, s.fz, s.contacts);
  nlohmann::json j;
  j["case"] = c.name;
  j["scenario"] = c.scenario;
  j["tolerance_N"] = kTolerance;
  j["horizon_s"] = horizon;
  j["first_contact_s"] = base.summary.first_contact_s;
  j["steps"] = base.summary.steps;
  for (const Break& b : base.breaks)
    j["breaks"].push_back({{"time", b.time}, {"floe", b.floe}, {"joint", b.joint}, {"mode", b.mode},
                           {"mechanism", b.mechanism}});
  for (std::size_t k = 0; k < kSummaryKeys.size(); ++k) {
    double ss = 0;
    for (double d : deviation[k]) ss += d * d;
    const double value = summary_value(base.summary, kSummaryKeys[k]);
    // three RMS deviations of the twins, and never below 1e-9 of the value
    j["summary"][kSummaryKeys[k]] = {{"value", value},
                                     {"band", std::max(3.0 * std::sqrt(ss / kTwins), 1e-9 * std::abs(value))}};
  }
  std::ofstream(json_path(c)) << j.dump(2) << "\n";
  std::cout << fmt::format("regenerated {}: horizon {:.2f} s (first contact {:.2f} s), {} breaks\n", c.name, horizon,
                           base.summary.first_contact_s, base.breaks.size());
}

struct Golden {
  std::vector<Sample> load;
  nlohmann::json meta;
};

Golden load_golden(const GoldenCase& c) {
  Golden g;
  std::ifstream csv(csv_path(c));
  std::string line;
  std::getline(csv, line);  // header
  while (std::getline(csv, line)) {
    std::istringstream row(line);
    Sample s{};
    char comma;
    row >> s.time >> comma >> s.fx >> comma >> s.fy >> comma >> s.fz >> comma >> s.contacts;
    g.load.push_back(s);
  }
  std::ifstream(json_path(c)) >> g.meta;
  return g;
}

// compares a run with a case's stored data; the failures as text ("" if it agrees)
std::string compare(const GoldenCase& c, const Result& r) {
  const Golden g = load_golden(c);
  const double horizon = g.meta["horizon_s"].get<double>();
  std::string failures;
  if (!r.summary.has_statistics) failures += "no load statistics: " + r.summary.statistics_note + "\n";
  if (static_cast<long>(r.load.size()) != g.meta["steps"].get<long>())
    failures += fmt::format("{} steps, stored {}\n", r.load.size(), g.meta["steps"].get<long>());
  for (std::size_t i = 0; i < std::min(r.load.size(), g.load.size()) && g.load[i].time <= horizon; ++i) {
    const Sample &a = r.load[i], &b = g.load[i];
    const double d = std::max({std::abs(a.fx - b.fx), std::abs(a.fy - b.fy), std::abs(a.fz - b.fz)});
    if (d > kTolerance || a.contacts != b.contacts) {
      failures += fmt::format("load at t = {:.2f} s (horizon {:.2f} s) off by {:.3g} N, contacts {} against {}\n",
                              b.time, horizon, d, a.contacts, b.contacts);
      break;
    }
  }
  std::vector<Break> stored;
  for (const auto& b : g.meta.value("breaks", nlohmann::json::array()))
    stored.push_back({b["time"].get<double>(), b["floe"].get<int>(), b["joint"].get<int>(), b["mode"].get<int>(),
                      b["mechanism"].get<int>()});
  for (std::size_t i = 0; i < stored.size() && stored[i].time <= horizon; ++i)
    if (i >= r.breaks.size() || !(r.breaks[i] == stored[i])) {
      failures += fmt::format("break {} (t = {:.2f} s, floe {}, joint {}) not repeated\n", i, stored[i].time,
                              stored[i].floe, stored[i].joint);
      break;
    }
  for (const std::string& key : kSummaryKeys) {
    const double want = g.meta["summary"][key]["value"].get<double>();
    const double band = g.meta["summary"][key]["band"].get<double>();
    const double got = summary_value(r.summary, key);
    if (!(std::abs(got - want) <= band))
      failures += fmt::format("surge {} {:.6g} N, stored {:.6g} +- {:.3g} N\n", key, got, want, band);
  }
  return failures;
}

bool regenerating() { return std::getenv("ICEDEM_REGENERATE_GOLDEN") != nullptr; }

class GoldenRun : public ::testing::TestWithParam<GoldenCase> {};

}  // namespace

TEST_P(GoldenRun, RepeatsTheStoredLoadsBreaksAndSummary) {
  const GoldenCase& c = GetParam();
  if (regenerating()) {
    regenerate(c);
    return;
  }
  const Result r = run_case(c);
  EXPECT_EQ(compare(c, r), "") << "golden run " << c.name << " moved; if the change is meant to move results, "
                               << "regenerate (tests/regression/test_golden.cpp) and say why in CHANGELOG.md";
}

INSTANTIATE_TEST_SUITE_P(Cases, GoldenRun, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

TEST(GoldenRun, AHalfPercentFrictionChangeFailsTheComparison) {
  // the comparison must catch a small real change: ice-structure friction 0.200 -> 0.201
  if (regenerating()) GTEST_SKIP() << "regenerating";
  const GoldenCase& c = cases().front();
  const Result r = run_case(c, {"friction.ice_structure=0.201"}, "_friction");
  EXPECT_NE(compare(c, r), "");
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
