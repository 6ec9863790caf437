// Copyright 2026 The draco-uv Authors.
//
// Licensed under the Apache License, Version 2.0 (the "License");
// you may not use this file except in compliance with the License.
// You may obtain a copy of the License at
//
//      http://www.apache.org/licenses/LICENSE-2.0
//
// Unless required by applicable law or agreed to in writing, software
// distributed under the License is distributed on an "AS IS" BASIS,
// WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
// See the License for the specific language governing permissions and
// limitations under the License.
//
#include "draco_ext/eval/uv_eval_report.h"

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "gtest/gtest.h"
#include "tests/draco_uv_test_utils.h"

namespace draco {
namespace {

TangentEvalRow Row(const std::string &tangents, int64_t tangent_bytes,
                   bool round_trip_ok = true) {
  TangentEvalRow row;
  row.mesh = "spot";
  row.scheme = "auto";
  row.tangents = tangents;
  row.qt = 12;
  row.qtg = 8;
  row.tangent_values = 100;
  row.tangent_bytes = tangent_bytes;
  row.stock_tangent_bytes = 400;
  row.bytes = 1000 + tangent_bytes;
  row.stock_bytes = 1400;
  row.round_trip_ok = round_trip_ok;
  return row;
}

// Bits per value and ratios follow from the row's bytes: 100 bytes for 100
// values are 8 bits, a quarter of stock's 400.
TEST(UvEvalReportTest, TangentTableShowsBitsRatiosAndMismatches) {
  const std::string table =
      FormatTangentTable({Row("auto", 100), Row("draco", 400, false)});
  EXPECT_NE(table.find("spot: 100 tangent values"), std::string::npos) << table;
  EXPECT_NE(table.find("8.000   0.250"), std::string::npos) << table;
  EXPECT_NE(table.find("MISMATCH"), std::string::npos) << table;
  EXPECT_EQ(FormatTangentTable({}), "");
}

TEST(UvEvalReportTest, TangentMismatchFailsTheReport) {
  UvEvalReport report({});
  report.AddTangents({Row("auto", 100)});
  EXPECT_TRUE(report.AllRoundTripsOk());
  report.AddTangents({Row("auto", 100, false)});
  EXPECT_FALSE(report.AllRoundTripsOk());
}

TEST(UvEvalReportTest, SummaryHasTangentLinesOnlyWithTangentRows) {
  UvEvalReport report({});
  EXPECT_EQ(report.FormatSummary().find("tangent"), std::string::npos);
  report.AddTangents({Row("auto", 100), Row("draco", 400)});
  const std::string summary = report.FormatSummary();
  EXPECT_NE(summary.find("qt 12 qtg 8 auto auto"), std::string::npos)
      << summary;
  EXPECT_NE(summary.find("qt 12 qtg 8 auto draco"), std::string::npos)
      << summary;
}

TEST(UvEvalReportTest, TangentCsvHasAHeaderAndARowEach) {
  UvEvalReport report({});
  report.AddTangents({Row("auto", 100), Row("draco", 400)});
  const std::string path = UvTempPath("tangents.csv");
  ASSERT_TRUE(report.WriteTangentCsv(path));
  std::ifstream file(path);
  const std::string text((std::istreambuf_iterator<char>(file)),
                         std::istreambuf_iterator<char>());
  EXPECT_EQ(text.rfind(TangentCsvHeader(), 0), 0u);
  EXPECT_NE(text.find(TangentCsvLine(Row("auto", 100))), std::string::npos);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 3);
}

}  // namespace
}  // namespace draco
