// Unit tests of floe layouts (dem/floe_layout.hpp): generated square-floe
// layouts (count, concentration, no overlap, containment, yaw range,
// reproducibility) and layout files (CSV/JSON round trips and error messages).
#include "dem/floe_layout.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <string>

#include "dem/constants.hpp"
#include "dem/errors.hpp"

namespace icedem {
namespace {

// the design channel: x in [6, 30] m, z in [-2.4, 2.4] m (docs/model/architecture.md, seed paper Figure 4)
const Channel kChannel{6.0, 30.0, -2.4, 2.4};

LayoutParams params(double floe_size, double concentration, uint64_t seed = 1) {
  LayoutParams p;
  p.channel = kChannel;
  p.floe_size = floe_size;
  p.concentration = concentration;
  p.seed = seed;
  p.max_yaw = 0.2;
  p.sweeps = 30;
  p.min_gap = 0.002;
  return p;
}

// index of the first pair of floes closer than `gap` (all pairs), or "" if none
std::string first_overlap(const std::vector<Floe>& floes, double gap) {
  std::vector<Polygon> world;
  for (const auto& f : floes) world.push_back(transformed(f.shape, f.centre, f.yaw));
  for (size_t i = 0; i < world.size(); ++i) {
    for (size_t j = i + 1; j < world.size(); ++j) {
      if (overlap(world[i], world[j], gap)) {
        return std::to_string(i) + " and " + std::to_string(j);
      }
    }
  }
  return "";
}

// index of the first floe with a vertex outside the channel (exact), or -1
long first_outside(const std::vector<Floe>& floes, const Channel& ch) {
  for (size_t i = 0; i < floes.size(); ++i) {
    for (const auto& v : transformed(floes[i].shape, floes[i].centre, floes[i].yaw)) {
      if (v.x() < ch.x_min || v.x() > ch.x_max || v.y() < ch.z_min || v.y() > ch.z_max) {
        return static_cast<long>(i);
      }
    }
  }
  return -1;
}

std::string tmp_path(const std::string& name) { return std::string(ICEDEM_TEST_TMP) + "/" + name; }

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = tmp_path(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// the InputError message of read_layout_file, or "" if it did not throw
std::string read_error(const std::string& path) {
  try {
    read_layout_file(path, kChannel);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// ------------------------------------------------------------ generated layouts

struct Case {
  double floe_size;      // m
  double concentration;  // fraction
  size_t floes;          // expected count round(C A / L^2), A = 24 x 4.8 m^2
};

class SquareLayout : public ::testing::TestWithParam<Case> {};

TEST_P(SquareLayout, HasTheTargetConcentrationWithinOnePercent) {
  const Case c = GetParam();
  const Layout layout = generate_square_layout(params(c.floe_size, c.concentration));
  EXPECT_EQ(layout.floes.size(), c.floes);
  EXPECT_NEAR(layout.channel_area, 24.0 * 4.8, 1e-12);  // rounding of the product
  // the design requirement: within 1 % (relative) of the target
  EXPECT_NEAR(layout.achieved_concentration / c.concentration, 1.0, 0.01);
  EXPECT_DOUBLE_EQ(layout.achieved_concentration, concentration(layout.floes, kChannel));
}

TEST_P(SquareLayout, NoTwoFloesOverlapOrComeCloserThanTheGap) {
  const Case c = GetParam();
  const LayoutParams p = params(c.floe_size, c.concentration);
  const Layout layout = generate_square_layout(p);
  EXPECT_EQ(first_overlap(layout.floes, 0.0), "");
  EXPECT_EQ(first_overlap(layout.floes, p.min_gap), "");
}

TEST_P(SquareLayout, EveryFloeLiesInsideTheChannel) {
  const Case c = GetParam();
  const Layout layout = generate_square_layout(params(c.floe_size, c.concentration));
  EXPECT_EQ(first_outside(layout.floes, kChannel), -1);
}

TEST_P(SquareLayout, FloesAreSquaresOfTheRequestedSizeCentredOnTheirCentroid) {
  const Case c = GetParam();
  const Layout layout = generate_square_layout(params(c.floe_size, c.concentration));
  for (const auto& f : layout.floes) {
    ASSERT_EQ(f.shape.size(), 4u);
    // rounding of L^2 and of a 4-term centroid sum at 0.3 m
    EXPECT_NEAR(area(f.shape), c.floe_size * c.floe_size, 1e-14);
    EXPECT_NEAR(centroid(f.shape).norm(), 0.0, 1e-14);
    EXPECT_GT(signed_area(f.shape), 0.0);
  }
}

TEST_P(SquareLayout, YawStaysWithinTheLimitAndUsesItsRange) {
  const Case c = GetParam();
  const LayoutParams p = params(c.floe_size, c.concentration);
  const Layout layout = generate_square_layout(p);
  double largest = 0.0;
  for (const auto& f : layout.floes) {
    EXPECT_LE(std::abs(f.yaw), p.max_yaw);
    largest = std::max(largest, std::abs(f.yaw));
  }
  EXPECT_GT(largest, 0.5 * p.max_yaw);
}

TEST_P(SquareLayout, MonteCarloAcceptsRoughlyThirtyToFiftyPercent) {
  const Case c = GetParam();
  const Layout layout = generate_square_layout(params(c.floe_size, c.concentration));
  // the step adapts towards 40 %; averaged over 30 sweeps including the first
  // ones before the step has settled, 25-55 % is the band "roughly 30-50 %"
  EXPECT_GT(layout.acceptance_rate, 0.25);
  EXPECT_LT(layout.acceptance_rate, 0.55);
}

INSTANTIATE_TEST_SUITE_P(DesignChannel, SquareLayout,
                         ::testing::Values(Case{0.3, 0.75, 960}, Case{0.6, 0.75, 240},
                                           Case{0.3, 0.5, 640}),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return "L" + std::to_string(static_cast<int>(
                                            std::lround(info.param.floe_size * 100))) +
                                  "cm_C" +
                                  std::to_string(static_cast<int>(
                                      std::lround(info.param.concentration * 100)));
                         });

TEST(SquareLayout, SameSeedGivesABitwiseIdenticalLayout) {
  const Layout a = generate_square_layout(params(0.3, 0.75, 42));
  const Layout b = generate_square_layout(params(0.3, 0.75, 42));
  ASSERT_EQ(a.floes.size(), b.floes.size());
  for (size_t i = 0; i < a.floes.size(); ++i) {
    EXPECT_EQ(std::memcmp(a.floes[i].centre.data(), b.floes[i].centre.data(), 2 * sizeof(double)),
              0)
        << "floe " << i;
    EXPECT_EQ(std::memcmp(&a.floes[i].yaw, &b.floes[i].yaw, sizeof(double)), 0) << "floe " << i;
  }
}

TEST(SquareLayout, DifferentSeedsGiveDifferentLayouts) {
  const Layout a = generate_square_layout(params(0.3, 0.75, 1));
  const Layout b = generate_square_layout(params(0.3, 0.75, 2));
  ASSERT_EQ(a.floes.size(), b.floes.size());
  size_t differing = 0;
  for (size_t i = 0; i < a.floes.size(); ++i) {
    if (a.floes[i].centre != b.floes[i].centre || a.floes[i].yaw != b.floes[i].yaw) ++differing;
  }
  // every floe moves in the relaxation, so independent streams differ everywhere
  EXPECT_EQ(differing, a.floes.size());
}

TEST(SquareLayout, ZeroYawLimitKeepsEveryFloeAligned) {
  LayoutParams p = params(0.6, 0.75);
  p.max_yaw = 0.0;
  const Layout layout = generate_square_layout(p);
  for (const auto& f : layout.floes) EXPECT_EQ(f.yaw, 0.0);
  EXPECT_EQ(first_overlap(layout.floes, p.min_gap), "");
}

TEST(SquareLayout, LargeYawLimitIsExploredBeyondTheGridCell) {
  // a 0.3 m floe in its 0.34 m start cell can turn only ~0.13 rad; the
  // relaxation must take floes well beyond that when the limit allows
  LayoutParams p = params(0.3, 0.5);
  p.max_yaw = kPi / 4.0;
  const Layout layout = generate_square_layout(p);
  double largest = 0.0;
  for (const auto& f : layout.floes) largest = std::max(largest, std::abs(f.yaw));
  EXPECT_GT(largest, 0.5 * p.max_yaw);
  EXPECT_LE(largest, p.max_yaw);
}

TEST(SquareLayout, ZeroSweepsGivesTheValidStartingGrid) {
  LayoutParams p = params(0.3, 0.75);
  p.sweeps = 0;
  const Layout layout = generate_square_layout(p);
  EXPECT_EQ(layout.floes.size(), 960u);
  EXPECT_EQ(first_overlap(layout.floes, p.min_gap), "");
  EXPECT_EQ(first_outside(layout.floes, kChannel), -1);
  EXPECT_EQ(layout.acceptance_rate, 0.0);
}

TEST(SquareLayout, OpenWaterHasNoFloes) {
  const Layout layout = generate_square_layout(params(0.3, 0.0));
  EXPECT_TRUE(layout.floes.empty());
  EXPECT_EQ(layout.achieved_concentration, 0.0);
}

TEST(SquareLayout, ConcentrationAboveWhatTheGridHoldsIsAnInputError) {
  // 0.95 needs 1216 floes of 0.3 m; with the 2 mm gap a grid holds 79 x 15 = 1185
  try {
    generate_square_layout(params(0.3, 0.95));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("ice.concentration = 0.95"), std::string::npos) << m;
    EXPECT_NE(m.find("ice.floe_size = 0.3"), std::string::npos) << m;
    EXPECT_NE(m.find("1185"), std::string::npos) << m;
  }
}

TEST(SquareLayout, FloeWiderThanTheChannelIsAnInputError) {
  try {
    generate_square_layout(params(5.0, 0.5));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("ice.floe_size = 5"), std::string::npos) << m;
  }
}

TEST(SquareLayout, ConcentrationOutsideZeroToOneIsAnInputError) {
  EXPECT_THROW(generate_square_layout(params(0.3, 1.2)), InputError);
  EXPECT_THROW(generate_square_layout(params(0.3, -0.1)), InputError);
  EXPECT_THROW(generate_square_layout(params(-0.3, 0.5)), InputError);
}

// ------------------------------------------------------------ layout files

// compares two floe lists: same order, centres/yaws/vertices equal within tol
void expect_same_floes(const std::vector<Floe>& a, const std::vector<Floe>& b, double tol) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR((a[i].centre - b[i].centre).norm(), 0.0, tol) << "floe " << i;
    EXPECT_NEAR(a[i].yaw, b[i].yaw, tol) << "floe " << i;
    ASSERT_EQ(a[i].shape.size(), b[i].shape.size()) << "floe " << i;
    for (size_t k = 0; k < a[i].shape.size(); ++k) {
      EXPECT_NEAR((a[i].shape[k] - b[i].shape[k]).norm(), 0.0, tol) << "floe " << i;
    }
  }
}

TEST(LayoutFile, CsvRoundTripReproducesTheLayout) {
  const Layout layout = generate_square_layout(params(0.6, 0.75));
  const std::string path = tmp_path("roundtrip.csv");
  write_layout_file(path, layout.floes);
  const Layout back = read_layout_file(path, kChannel);
  // numbers are written with round-trip precision; only the degree conversion
  // of yaw and the re-centring of the square (~1e-17 m) add rounding
  expect_same_floes(layout.floes, back.floes, 1e-12);
  EXPECT_NEAR(back.achieved_concentration, layout.achieved_concentration, 1e-12);
}

TEST(LayoutFile, JsonRoundTripReproducesTheLayout) {
  const Layout layout = generate_square_layout(params(0.3, 0.5));
  const std::string path = tmp_path("roundtrip.json");
  write_layout_file(path, layout.floes);
  const Layout back = read_layout_file(path, kChannel);
  // as for CSV: round-trip decimals, degree conversion and re-centring only
  expect_same_floes(layout.floes, back.floes, 1e-12);
  EXPECT_NEAR(back.achieved_concentration, layout.achieved_concentration, 1e-12);
}

TEST(LayoutFile, CsvWithCommentsAnyColumnOrderAndCrLfIsRead) {
  const std::string path = write_file(
      "hand.csv",
      "# two floes\r\n"
      "yaw_deg, x ,z,polygon\r\n"
      "\r\n"
      "0,7,0,\"-0.15 -0.15; 0.15 -0.15; 0.15 0.15; -0.15 0.15\"\r\n"
      "  # a comment between floes\r\n"
      "+30,8,1.5,\"0 0; 0.4 0; 0 0.3;\"\r\n");
  const Layout layout = read_layout_file(path, kChannel);
  ASSERT_EQ(layout.floes.size(), 2u);
  // re-centring the symmetric square moves it by rounding only (~1e-17 m)
  EXPECT_NEAR((layout.floes[0].centre - Eigen::Vector2d(7.0, 0.0)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(layout.floes[1].yaw, 30.0 * kPi / 180.0, 1e-15);  // one rounding of pi/6
  EXPECT_NEAR(layout.achieved_concentration, (0.09 + 0.06) / (24.0 * 4.8), 1e-15);
}

TEST(LayoutFile, OffCentrePolygonIsRecentredWithoutMovingTheFloe) {
  // a right triangle with its corner at the local origin, turned by 30 degrees
  const std::string path = write_file(
      "offcentre.json",
      R"({"floes": [{"centre": [10, 1], "yaw_deg": 30, "polygon": [[0, 0], [0.6, 0], [0, 0.3]]}]})");
  const Layout layout = read_layout_file(path, kChannel);
  ASSERT_EQ(layout.floes.size(), 1u);
  const Floe& f = layout.floes[0];
  const double yaw = 30.0 * kPi / 180.0;
  // the shape's centroid is at the origin, the centre is the world centroid
  EXPECT_NEAR(centroid(f.shape).norm(), 0.0, 1e-15);  // rounding at 0.1 m scale
  const Eigen::Vector2d expected = Eigen::Vector2d(10, 1) + rotate({0.2, 0.1}, yaw);
  EXPECT_NEAR((f.centre - expected).norm(), 0.0, 1e-14);  // rounding at 10 m scale
  // same world outline (as a set of vertices, the order may be reversed to ccw)
  const Polygon given = transformed({{0, 0}, {0.6, 0}, {0, 0.3}}, {10, 1}, yaw);
  const Polygon read = transformed(f.shape, f.centre, f.yaw);
  for (const auto& v : given) {
    double nearest = 1e9;
    for (const auto& w : read) nearest = std::min(nearest, (v - w).norm());
    EXPECT_LT(nearest, 1e-14);  // rounding at 10 m scale
  }
  EXPECT_GT(signed_area(f.shape), 0.0);
}

TEST(LayoutFile, TouchingFloesAreAccepted) {
  // a tiling of squares sharing edges, as a user would type it
  const std::string path = write_file(
      "tiling.csv",
      "x,z,yaw_deg,polygon\n"
      "6.15,0.15,0,\"-0.15 -0.15; 0.15 -0.15; 0.15 0.15; -0.15 0.15\"\n"
      "6.45,0.15,0,\"-0.15 -0.15; 0.15 -0.15; 0.15 0.15; -0.15 0.15\"\n"
      "6.15,0.45,90,\"-0.15 -0.15; 0.15 -0.15; 0.15 0.15; -0.15 0.15\"\n");
  EXPECT_EQ(read_layout_file(path, kChannel).floes.size(), 3u);
}

TEST(LayoutFile, NonConvexPolygonNamesFileLineAndField) {
  const std::string path = write_file(
      "nonconvex.csv",
      "# comment\n"
      "x,z,yaw_deg,polygon\n"
      "7,0,0,\"-0.15 -0.15; 0.15 -0.15; 0.15 0.15; -0.15 0.15\"\n"
      "8,0,0,\"0 0; 0.4 0; 0.4 0.2; 0.2 0.1; 0 0.2\"\n");
  const std::string m = read_error(path);
  EXPECT_NE(m.find("nonconvex.csv:4:"), std::string::npos) << m;
  EXPECT_NE(m.find("'polygon'"), std::string::npos) << m;
  EXPECT_NE(m.find("0.2 0.1"), std::string::npos) << m;
  EXPECT_NE(m.find("convex"), std::string::npos) << m;
}

TEST(LayoutFile, OverlapNamesFileBothLinesAndField) {
  const std::string path = write_file(
      "overlap.csv",
      "x,z,yaw_deg,polygon\n"
      "7,0,0,\"-0.15 -0.15; 0.15 -0.15; 0.15 0.15; -0.15 0.15\"\n"
      "9,0,0,\"-0.15 -0.15; 0.15 -0.15; 0.15 0.15; -0.15 0.15\"\n"
      "7.25,0.1,10,\"-0.15 -0.15; 0.15 -0.15; 0.15 0.15; -0.15 0.15\"\n");
  const std::string m = read_error(path);
  EXPECT_NE(m.find("overlap.csv:4:"), std::string::npos) << m;
  EXPECT_NE(m.find("'polygon'"), std::string::npos) << m;
  EXPECT_NE(m.find("line 2"), std::string::npos) << m;
  EXPECT_NE(m.find("overlaps"), std::string::npos) << m;
}

TEST(LayoutFile, FloeOutsideTheChannelNamesFileLineAndFields) {
  const std::string path = write_file(
      "outside.csv",
      "x,z,yaw_deg,polygon\n"
      "7,0,0,\"-0.15 -0.15; 0.15 -0.15; 0.15 0.15; -0.15 0.15\"\n"
      "8,2.3,0,\"-0.15 -0.15; 0.15 -0.15; 0.15 0.15; -0.15 0.15\"\n");
  const std::string m = read_error(path);
  EXPECT_NE(m.find("outside.csv:3:"), std::string::npos) << m;
  EXPECT_NE(m.find("'z'"), std::string::npos) << m;
  EXPECT_NE(m.find("8, 2.3"), std::string::npos) << m;
  EXPECT_NE(m.find("outside the channel"), std::string::npos) << m;
}

TEST(LayoutFile, MalformedNumberNamesFileLineFieldAndValue) {
  const std::string path = write_file(
      "badnumber.csv",
      "x,z,yaw_deg,polygon\n"
      "7,0,0,\"-0.15 -0.15; 0.15 -0.15; 0.15 0.15; -0.15 0.15\"\n"
      "8.1x,0,0,\"-0.15 -0.15; 0.15 -0.15; 0.15 0.15; -0.15 0.15\"\n");
  const std::string m = read_error(path);
  EXPECT_NE(m.find("badnumber.csv:3:"), std::string::npos) << m;
  EXPECT_NE(m.find("field 'x' = \"8.1x\""), std::string::npos) << m;
  EXPECT_NE(m.find("number"), std::string::npos) << m;
}

TEST(LayoutFile, MalformedVertexNamesTheVertex) {
  const std::string path = write_file(
      "badvertex.csv",
      "x,z,yaw_deg,polygon\n"
      "7,0,0,\"-0.15 -0.15; 0.15 -0,15; 0.15 0.15\"\n");
  const std::string m = read_error(path);
  EXPECT_NE(m.find("badvertex.csv:2: field 'polygon'"), std::string::npos) << m;
  EXPECT_NE(m.find("vertex 2 \"0.15 -0,15\""), std::string::npos) << m;
}

TEST(LayoutFile, WrongFieldCountNamesTheLine) {
  // an unquoted polygon containing commas splits into extra fields
  const std::string path = write_file(
      "fieldcount.csv",
      "x,z,yaw_deg,polygon\n"
      "7,0,0,0 0, 0.1 0, 0 0.1\n");
  const std::string m = read_error(path);
  EXPECT_NE(m.find("fieldcount.csv:2: 6 fields"), std::string::npos) << m;
}

TEST(LayoutFile, JsonNonConvexPolygonNamesFloeIndexAndField) {
  const std::string path = write_file(
      "nonconvex.json",
      R"({"floes": [
  {"centre": [7, 0], "yaw_deg": 0, "polygon": [[-0.15, -0.15], [0.15, -0.15], [0.15, 0.15]]},
  {"centre": [8, 0], "yaw_deg": 0, "polygon": [[0, 0], [0.4, 0.2], [0.4, 0], [0, 0.2]]}
]})");
  const std::string m = read_error(path);
  EXPECT_NE(m.find("nonconvex.json: floes[1].polygon"), std::string::npos) << m;
  EXPECT_NE(m.find("convex"), std::string::npos) << m;
}

TEST(LayoutFile, JsonOverlapNamesBothFloes) {
  const std::string path = write_file(
      "overlap.json",
      R"({"floes": [
  {"centre": [7, 0], "yaw_deg": 0, "polygon": [[-0.15, -0.15], [0.15, -0.15], [0.15, 0.15], [-0.15, 0.15]]},
  {"centre": [7.2, 0.2], "yaw_deg": 45, "polygon": [[-0.15, -0.15], [0.15, -0.15], [0.15, 0.15], [-0.15, 0.15]]}
]})");
  const std::string m = read_error(path);
  EXPECT_NE(m.find("overlap.json: floes[1].polygon"), std::string::npos) << m;
  EXPECT_NE(m.find("overlaps floes[0]"), std::string::npos) << m;
}

TEST(LayoutFile, JsonFloeOutsideTheChannelNamesTheCentre) {
  const std::string path = write_file(
      "outside.json",
      R"({"floes": [{"centre": [5.9, 0], "yaw_deg": 0, "polygon": [[-0.15, -0.15], [0.15, -0.15], [0.15, 0.15]]}]})");
  const std::string m = read_error(path);
  EXPECT_NE(m.find("outside.json: floes[0].centre = [5.9,0]"), std::string::npos) << m;
  EXPECT_NE(m.find("outside the channel"), std::string::npos) << m;
}

TEST(LayoutFile, JsonMalformedNumberNamesFloeIndexFieldAndValue) {
  const std::string path = write_file(
      "badnumber.json",
      R"({"floes": [
  {"centre": [7, 0], "yaw_deg": "ten", "polygon": [[-0.15, -0.15], [0.15, -0.15], [0.15, 0.15]]}
]})");
  const std::string m = read_error(path);
  EXPECT_NE(m.find("badnumber.json: floes[0].yaw_deg = \"ten\""), std::string::npos) << m;
  EXPECT_NE(m.find("expected a number"), std::string::npos) << m;
}

TEST(LayoutFile, JsonSyntaxErrorGivesTheParserLine) {
  const std::string path = write_file("syntax.json", "{\"floes\": [\n  {\"centre\": [7, 0],,}\n]}");
  const std::string m = read_error(path);
  EXPECT_NE(m.find("syntax.json"), std::string::npos) << m;
  EXPECT_NE(m.find("line 2"), std::string::npos) << m;
}

TEST(LayoutFile, JsonUnknownOrMissingKeyIsNamed) {
  const std::string unknown = write_file(
      "unknownkey.json",
      R"({"floes": [{"centre": [7, 0], "yaw": 0, "polygon": [[0, 0], [0.1, 0], [0, 0.1]]}]})");
  EXPECT_NE(read_error(unknown).find("floes[0].yaw"), std::string::npos) << read_error(unknown);
  const std::string missing = write_file(
      "missingkey.json", R"({"floes": [{"centre": [7, 0], "polygon": [[0, 0], [0.1, 0], [0, 0.1]]}]})");
  EXPECT_NE(read_error(missing).find("floes[0].yaw_deg is missing"), std::string::npos)
      << read_error(missing);
}

TEST(LayoutFile, UnknownExtensionOrMissingFileIsAnInputError) {
  const std::string txt = write_file("layout.txt", "x,z,yaw_deg,polygon\n");
  EXPECT_NE(read_error(txt).find("expected .csv or .json"), std::string::npos);
  EXPECT_NE(read_error(tmp_path("does_not_exist.csv")).find("does_not_exist.csv"),
            std::string::npos);
}

TEST(LayoutFile, BadCsvHeaderIsNamed) {
  const std::string path = write_file("badheader.csv", "x,z,yaw,polygon\n7,0,0,\"0 0; 1 0; 0 1\"\n");
  const std::string m = read_error(path);
  EXPECT_NE(m.find("badheader.csv:1:"), std::string::npos) << m;
  EXPECT_NE(m.find("'yaw'"), std::string::npos) << m;
}


// Malformed layout files found by fuzzing: refused with the file named, never a crash,
// a raw library message or NaN in the run.

TEST(LayoutFile, AYawBeyondOneTurnIsRefused) {
  // yaw_deg = 1e308 passed and put NaN into the run's snapshots
  const std::string path = write_file("yaw.csv", "x,z,yaw_deg,polygon\n1.0,0.0,1e308,\"0 0; 0.3 0; 0.3 0.3; 0 0.3\"\n");
  const std::string msg = read_error(path);
  EXPECT_NE(msg.find("yaw.csv:2"), std::string::npos) << msg;
  EXPECT_NE(msg.find("expected an angle in [-360, 360] degrees"), std::string::npos) << msg;
}

TEST(LayoutFile, JsonNestedTooDeepOrWithANumberOverflowIsRefused) {
  // 100,000 levels crashed the recursive error path; 1e309 gave a raw library message
  const std::string deep = write_file("deep.json", "{\"floes\": " + std::string(100000, '[') + std::string(100000, ']') + "}");
  EXPECT_NE(read_error(deep).find("nested 100001 levels deep"), std::string::npos);
  const std::string big =
      write_file("big.json", "{\"floes\": [{\"centre\": [1e309, 0], \"yaw_deg\": 0, \"polygon\": [[0,0],[1,0],[1,1]]}]}");
  const std::string msg = read_error(big);
  EXPECT_NE(msg.find("big.json: invalid JSON"), std::string::npos) << msg;
  EXPECT_NE(msg.find("number overflow"), std::string::npos) << msg;
}

}  // namespace
}  // namespace icedem
