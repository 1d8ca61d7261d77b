// Unit tests of layout files (dem/layout/layout_file.hpp, layout_csv, layout_json; read through
// read_layout_file of dem/layout/floe_layout.hpp): CSV and JSON round trips, hand-written files, and
// error messages that name the file, line (or floe) and field.
#include "dem/layout/floe_layout.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "dem/core/constants.hpp"
#include "dem/core/errors.hpp"
#include "tests/support/layouts.hpp"

namespace icedem {
namespace {

using testing::kDesignChannel;
const Channel& kChannel = kDesignChannel;

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
  const Layout layout = generate_square_layout(testing::layout_params(0.6, 0.75));
  const std::string path = tmp_path("roundtrip.csv");
  write_layout_file(path, layout.floes);
  const Layout back = read_layout_file(path, kChannel);
  // numbers are written with round-trip precision; only the degree conversion
  // of yaw and the re-centring of the square (~1e-17 m) add rounding
  expect_same_floes(layout.floes, back.floes, 1e-12);
  EXPECT_NEAR(back.achieved_concentration, layout.achieved_concentration, 1e-12);
}

TEST(LayoutFile, JsonRoundTripReproducesTheLayout) {
  const Layout layout = generate_square_layout(testing::layout_params(0.3, 0.5));
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
