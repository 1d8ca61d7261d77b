// The run summary: the warning for an element that rocks unstably, and the JSON key.
#include <gtest/gtest.h>

#include "dem/core/constants.hpp"
#include "dem/output/summary.hpp"

using namespace icedem;

TEST(Summary, WarnsWhenAnElementTurnsFasterThanTheRockingThreshold) {
  RunSummary s;
  s.status = "complete";
  s.health.max.max_angular_speed = 1.5;  // a stable run: floes turn at a few rad/s at most
  EXPECT_EQ(summary_table(s).find("warning"), std::string::npos);
  EXPECT_DOUBLE_EQ(summary_json(s)["max_angular_speed_rad_s"].get<double>(), 1.5);

  s.health.add(165.2, StepDiagnostics{kRockingAngularSpeed + 25.0});
  const std::string table = summary_table(s);
  EXPECT_NE(table.find("warning: a floe or element turned at 40.0 rad/s (t = 165.20 s)"), std::string::npos)
      << table;
}

TEST(SummaryTable, AValidationCaseWithoutAResultSaysSoInsteadOfThrowing) {
  // a cantilever whose beam did not break: value and error are null (JSON), with a note
  RunSummary s;
  s.validation = {{"case", "cantilever"}, {"metric", "bending stress at failure, kPa"}, {"value", nullptr},
                  {"reference", 36.4}, {"rel_error", nullptr}, {"tolerance", 0.1}, {"passed", false},
                  {"note", "the beam did not break within time.duration"}};
  const std::string table = summary_table(s);
  EXPECT_NE(table.find("validation cantilever: no result, FAILED: the beam did not break"), std::string::npos) << table;
}
