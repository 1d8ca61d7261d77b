// The output schema (dem/output/schema.hpp) is the file: a run with breaks writes exactly the
// datasets the schema declares, with its shapes' ranks, element types and units, and the
// attributes it lists; /stats repeats the summary's numbers. A dataset added to the recorder
// but not to the schema (or the reverse) fails here, so docs/user/output.md cannot drift.
#include <gtest/gtest.h>

#include <H5Cpp.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "dem/input/scenario.hpp"
#include "dem/output/schema.hpp"
#include "dem/run/simulation.hpp"
#include "tests/support/scenes.hpp"

using namespace icedem;

namespace {

struct Found {
  std::string units;
  int rank;
  H5T_class_t type_class;
  std::size_t type_size;
};

// every dataset in the file, by path
herr_t collect(hid_t object, const char* name, const H5O_info_t* info, void* data) {
  if (info->type != H5O_TYPE_DATASET) return 0;
  auto& found = *static_cast<std::map<std::string, Found>*>(data);
  H5::DataSet set(H5Dopen(object, name, H5P_DEFAULT));
  std::string units;
  H5::Attribute a = set.openAttribute("units");
  a.read(a.getStrType(), units);
  found[std::string("/") + name] = {units, set.getSpace().getSimpleExtentNdims(), set.getDataType().getClass(),
                                    set.getDataType().getSize()};
  return 0;
}

// the rank of a schema shape: "k x nb x 3" has three dimensions
int rank_of(const std::string& shape) {
  int rank = 1;
  for (std::size_t i = 0; i + 2 < shape.size(); ++i) rank += shape.compare(i, 3, " x ") == 0;
  return rank;
}

void expect_element(const std::string& path, const Found& f, Element e) {
  switch (e) {
    case Element::f8: EXPECT_EQ(f.type_class, H5T_FLOAT) << path; EXPECT_EQ(f.type_size, 8u) << path; break;
    case Element::i4: EXPECT_EQ(f.type_class, H5T_INTEGER) << path; EXPECT_EQ(f.type_size, 4u) << path; break;
    case Element::i8: EXPECT_EQ(f.type_class, H5T_INTEGER) << path; EXPECT_EQ(f.type_size, 8u) << path; break;
    case Element::u1: EXPECT_EQ(f.type_class, H5T_INTEGER) << path; EXPECT_EQ(f.type_size, 1u) << path; break;
    case Element::compound: EXPECT_EQ(f.type_class, H5T_COMPOUND) << path; break;
    case Element::text: EXPECT_EQ(f.type_class, H5T_STRING) << path; break;
  }
}

}  // namespace

TEST(OutputSchema, ABreakableRunWritesExactlyTheDeclaredDatasetsAndAttributes) {
  // the golden breakable case, shortened: joints break within a second of the first contact
  const Scene scene = load_scene(
      std::string(ICEDEM_SOURCE_DIR) + "/scenarios/paper/large_floes_breakable_015.toml",
      {"time.duration=3", "channel.start_x=3.0", "channel.length=3.6", "channel.width=3.0", "ice.concentration=0.6",
       "structure.start_x=2.2", "structure.speed=0.2", "ice.bending_strength=12e3", "stats.window_start_travel=0.1"});
  const std::string out = std::string(ICEDEM_TEST_TMP) + "/output_schema.h5";
  const RunSummary s = run_simulation(scene, icedem::testing::test_run("output_schema.h5", "test"));
  ASSERT_EQ(s.status, "complete");
  ASSERT_GT(s.breaks, 0) << "the case must break joints, so that /fracture/events has rows";

  H5::H5File file(out, H5F_ACC_RDONLY);
  std::map<std::string, Found> found;
  H5Ovisit(file.getId(), H5_INDEX_NAME, H5_ITER_NATIVE, collect, &found);

  std::set<std::string> declared;
  for (const SeriesColumn& c : series_columns()) {
    declared.insert(c.path);
    if (c.moored) {  // a moored structure's columns: not in a towed run's file
      EXPECT_FALSE(found.count(c.path)) << c.path << " is a moored run's, but a towed run wrote it";
      continue;
    }
    ASSERT_TRUE(found.count(c.path)) << c.path << " is declared but not written";
    const Found& f = found.at(c.path);
    EXPECT_EQ(f.units, c.unit) << c.path;
    EXPECT_EQ(f.rank, c.width == 1 ? 1 : 2) << c.path;
    expect_element(c.path, f, c.element);
  }
  for (const DatasetEntry& e : other_datasets()) {
    declared.insert(e.path);
    if (e.moored || e.sheet) {  // a moored structure's, or the analytic level sheet's: not in this run's file
      EXPECT_FALSE(found.count(e.path)) << e.path << " is another kind of run's, but this run wrote it";
      continue;
    }
    ASSERT_TRUE(found.count(e.path)) << e.path << " is declared but not written";
    const Found& f = found.at(e.path);
    if (e.element != Element::compound) {
      EXPECT_EQ(f.units, e.unit) << e.path;
    }
    EXPECT_EQ(f.rank, rank_of(e.shape)) << e.path;
    expect_element(e.path, f, e.element);
  }
  for (const auto& [path, f] : found) EXPECT_TRUE(declared.count(path)) << path << " is written but not declared";

  // the break rows carry every declared field
  const H5::CompType events = file.openDataSet("/fracture/events").getCompType();
  ASSERT_EQ(events.getNmembers(), static_cast<int>(event_fields().size()));
  for (std::size_t i = 0; i < event_fields().size(); ++i)
    EXPECT_EQ(events.getMemberName(static_cast<unsigned>(i)), event_fields()[i].name);

  // the attributes: every declared one is there (/stats note only without statistics,
  // /meta resumed_utc and resumed_build only in a resumed run)
  for (const AttributeEntry& a : file_attributes()) {
    if (std::string(a.object) == "/stats" && std::string(a.name) == "note") continue;
    if (std::string(a.object) == "/meta" && std::string(a.name).rfind("resumed_", 0) == 0) continue;
    const bool exists = std::string(a.object) == "/fracture/events"
                            ? file.openDataSet(a.object).attrExists(a.name)
                            : file.openGroup(a.object).attrExists(a.name);
    EXPECT_TRUE(exists) << a.object << " " << a.name;
  }
  // /stats holds the summary's numbers marked for it, with their values
  const nlohmann::json summary = summary_json(s);
  const H5::Group stats = file.openGroup("/stats");
  for (const SummaryField& f : summary_fields()) {
    if (!f.stats || !summary[f.key].is_number()) continue;
    ASSERT_TRUE(stats.attrExists(f.key)) << f.key;
    double value = 0;
    stats.openAttribute(f.key).read(H5::PredType::NATIVE_DOUBLE, &value);
    EXPECT_EQ(value, summary[f.key].get<double>()) << f.key;
  }
  // and the summary JSON holds every declared key (validation only in validation cases)
  for (const SummaryField& f : summary_fields()) {
    if (!f.omit_if_null) {
      EXPECT_TRUE(summary.contains(f.key)) << f.key;
    }
  }
}

TEST(OutputSchema, AMooredRunWritesItsMotionsAndEveryLinesTension) {
  // the catenary's four lines: /mooring/tension is n x 4, the other moored columns n x 3, every row
  // written, and the lines hold the structure (each pulls)
  const Scene scene = load_scene(std::string(ICEDEM_SOURCE_DIR) + "/scenarios/moored/small_floes_moored.toml",
                                 {"time.duration=2", "mooring.model=\"catenary\"", "output.snapshot_interval=0.5"});
  const RunSummary s = run_simulation(scene, icedem::testing::test_run("output_schema_moored.h5", "test"));
  ASSERT_EQ(s.status, "complete");
  H5::H5File file(std::string(ICEDEM_TEST_TMP) + "/output_schema_moored.h5", H5F_ACC_RDONLY);
  const hsize_t steps = static_cast<hsize_t>(s.steps);
  for (const SeriesColumn& c : series_columns()) {
    if (!c.moored) continue;
    ASSERT_TRUE(file.nameExists(c.path.substr(0, c.path.rfind('/')))) << c.path;
    const H5::DataSet d = file.openDataSet(c.path);
    hsize_t dims[2] = {0, 0};
    ASSERT_EQ(d.getSpace().getSimpleExtentDims(dims), 2) << c.path;
    EXPECT_EQ(dims[0], steps) << c.path;
    EXPECT_EQ(dims[1], c.per_line ? 4u : 3u) << c.path;
  }
  std::vector<double> tension(4 * steps);
  file.openDataSet("/mooring/tension").read(tension.data(), H5::PredType::NATIVE_DOUBLE);
  for (double t : tension) EXPECT_GT(t, 0.0);
  // the lines' shapes at each snapshot (t = 0, 0.5, ..., 2 s), k x 4 x 16 x 3: each from its anchor on the
  // tank's floor to its fairlead on the hull, which rests before the ice arrives (1 mm: its settling)
  const H5::DataSet lines = file.openDataSet("/snapshots/mooring_lines");
  hsize_t dims[4] = {0, 0, 0, 0};
  ASSERT_EQ(lines.getSpace().getSimpleExtentDims(dims), 4);
  EXPECT_EQ(dims[0], 5u);
  EXPECT_EQ(dims[1], 4u);
  EXPECT_EQ(dims[2], static_cast<hsize_t>(kMooringShapePoints));
  EXPECT_EQ(dims[3], 3u);
  std::vector<double> p(dims[0] * dims[1] * dims[2] * 3);
  lines.read(p.data(), H5::PredType::NATIVE_DOUBLE);
  std::vector<double> xs(3 * steps);  // the reference point, one row a step, from t = dt
  file.openDataSet("/structure/position").read(xs.data(), H5::PredType::NATIVE_DOUBLE);
  for (hsize_t k = 0; k < dims[0]; ++k)
    for (hsize_t l = 0; l < dims[1]; ++l) {
      const double* first = &p[((k * dims[1] + l) * dims[2]) * 3];
      const double* last = first + 3 * (dims[2] - 1);
      EXPECT_NEAR(first[1], -scene.channel.tank_depth, 1e-12) << "an anchor on the floor, snapshot " << k;
      const long row = std::lround(0.5 * k / scene.time.dt) - 1;
      const double* at = &xs[3 * std::clamp<long>(row, 0, static_cast<long>(steps) - 1)];
      EXPECT_NEAR(std::hypot(last[0] - at[0], last[2] - at[2]), scene.mooring.fairlead_radius, 1e-3) << k << " " << l;
      EXPECT_NEAR(last[1] - at[1], scene.mooring.fairlead_y, 1e-3) << k << " " << l;
    }
}

