// The State is declared once (dem/step/state.hpp): every field of its values and of the run loop's
// history is in the list a checkpoint is written and read by, and comes back from a checkpoint
// file bit for bit. A field added to StateValues but not to visit_fields fails the first tests
// (the check is shown to catch such a field on a struct made to have one).
#include <gtest/gtest.h>

#include <H5Cpp.h>

#include <cstring>
#include <filesystem>
#include <map>
#include <string>
#include <type_traits>

#include "dem/core/field_count.hpp"
#include "dem/output/checkpoint.hpp"

namespace icedem {
namespace {

template <typename T>
struct IsOptional : std::false_type {};
template <typename T>
struct IsOptional<std::optional<T>> : std::true_type {};

TEST(StateFields, EveryValueIsInTheCheckpointsList) {
  EXPECT_EQ(field_count<StateValues>(), visited_count<StateValues>())
      << "a field of StateValues is missing from visit_fields (dem/step/state.hpp): a checkpoint would not keep it";
}

TEST(StateFields, EveryFractureFieldIsInTheCheckpointsList) {
  EXPECT_EQ(field_count<FractureState>(), visited_count<FractureState>())
      << "a field of FractureState is missing from visit_fields (dem/fracture/fracture_state.hpp)";
}

TEST(StateFields, EveryLoadFieldIsInTheCheckpointsList) {
  EXPECT_EQ(field_count<LoadReading>(), visited_count<LoadReading>())
      << "a field of LoadReading is missing from visit_fields (dem/world/load_cell.hpp)";
}

TEST(StateFields, EveryStructureMotionFieldIsInTheCheckpointsList) {
  EXPECT_EQ(field_count<StructureMotionState>(), visited_count<StructureMotionState>())
      << "a field of StructureMotionState is missing from visit_fields (dem/mooring/structure_motion.hpp)";
}

TEST(StateFields, EveryHistoryFieldIsInTheCheckpointsList) {
  EXPECT_EQ(field_count<RunHistory>(), visited_count<RunHistory>())
      << "a field of RunHistory is missing from visit_fields (dem/output/checkpoint.hpp)";
}

// a struct with a field its list leaves out, as a StateValues with a new field would be
struct WithAnUnlistedField {
  double time = 0;
  std::vector<int> counts;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  std::optional<double> first;
  int forgotten = 0;
};
template <typename V, typename Visit>  // V: WithAnUnlistedField or const WithAnUnlistedField
std::enable_if_t<std::is_same_v<std::remove_const_t<V>, WithAnUnlistedField>> visit_fields(V& v, Visit&& visit) {
  visit("time", v.time);
  visit("counts", v.counts);
  visit("position", v.position);
  visit("first", v.first);
}

TEST(StateFields, TheCheckCatchesAnUnlistedField) {
  EXPECT_EQ(field_count<WithAnUnlistedField>(), 5u);
  EXPECT_EQ(visited_count<WithAnUnlistedField>(), 4u);
}

// sets every field to values no default has, different for each field (`seed`)
struct Fill {
  unsigned char seed = 1;
  template <typename T>
  void bytes(T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    unsigned char* p = reinterpret_cast<unsigned char*>(&v);
    for (std::size_t i = 0; i < sizeof(T); ++i) p[i] = static_cast<unsigned char>(seed + 7 * i);
  }
  template <typename T>
  void operator()(const char*, T& v) {
    ++seed;
    if constexpr (HasFields<T>::value) {
      visit_fields(v, *this);
    } else if constexpr (IsVector<T>::value) {
      v.resize(3);
      for (auto& x : v) bytes(x), ++seed;
    } else if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
      v = Eigen::Vector3d(seed, -0.5 * seed, 1e-3 * seed);
    } else if constexpr (IsOptional<T>::value) {
      v = 0.25 * seed;
    } else if constexpr (std::is_arithmetic_v<T>) {
      v = static_cast<T>(seed);
    } else {
      bytes(v);
    }
  }
};

// every field by name as its bytes (Eigen's vectors and the load by their numbers; the fields
// of a part with fields of its own as "part.field")
struct Bytes {
  std::map<std::string, std::string> fields;
  std::string prefix;
  template <typename T>
  static std::string of(const T& v) {
    return std::string(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  template <typename T>
  void operator()(const char* name, const T& v) {
    if constexpr (HasFields<T>::value) {
      Bytes part{{}, prefix + name + "."};
      visit_fields(v, part);
      fields.insert(part.fields.begin(), part.fields.end());
      return;
    }
    std::string& out = fields[prefix + name];
    if constexpr (IsVector<T>::value) {
      for (const auto& x : v) out += of(x);
    } else if constexpr (std::is_same_v<T, Eigen::Vector3d>) {
      out = std::string(reinterpret_cast<const char*>(v.data()), 3 * sizeof(double));
    } else if constexpr (IsOptional<T>::value) {
      out = v ? "some " + of(*v) : "none";
    } else {
      out = of(v);
    }
  }
};

TEST(StateFields, EveryFieldComesBackFromACheckpointFile) {
  Checkpoint written;
  written.version = ICEDEM_VERSION;
  Fill fill;
  visit_fields(written.values, fill);
  visit_fields(written.history, fill);

  const std::string dir = std::string(ICEDEM_TEST_TMP) + "/state_fields";
  std::filesystem::create_directories(dir);
  const std::string output = dir + "/run.h5";
  H5::H5File(output, H5F_ACC_TRUNC).close();  // the output a checkpoint is a copy of
  write_checkpoint(output, written);
  const Checkpoint read = read_checkpoint(checkpoint_path(output));

  Bytes a, b, defaults;
  visit_fields(written.values, a);
  visit_fields(read.values, b);
  StateValues fresh;
  visit_fields(fresh, defaults);
  // the fracture stage's part, the load and a moored structure's motion are groups of their own fields
  ASSERT_EQ(a.fields.size(), field_count<StateValues>() - 3 + field_count<FractureState>() + field_count<LoadReading>() +
                                 field_count<StructureMotionState>());
  for (const auto& [name, bytes] : a.fields) {
    EXPECT_NE(bytes, defaults.fields[name]) << name << ": the test should set it to a value other than its default";
    EXPECT_EQ(bytes, b.fields[name]) << name << " does not come back from the checkpoint";
  }
  Bytes c, d;
  visit_fields(written.history, c);
  visit_fields(read.history, d);
  for (const auto& [name, bytes] : c.fields) EXPECT_EQ(bytes, d.fields[name]) << "history " << name;
}

}  // namespace
}  // namespace icedem
