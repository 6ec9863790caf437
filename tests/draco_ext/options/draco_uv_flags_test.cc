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
#include "draco_ext/options/draco_uv_flags.h"

#include <cstdio>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "draco_ext/options/uv_compression_options.h"
#include "gtest/gtest.h"

namespace draco {
namespace {

UnhandledToolArg Classify(const std::string &arg, bool is_last = false) {
  return ClassifyUnhandledToolArg("draco_encoder", arg, is_last);
}

// The table of a build that has one more flag, -tangent_kinds.
UnhandledToolArg ClassifyWithNewFlag(const std::string &arg) {
  std::vector<const char *> flags = DracoUvFlagNames();
  flags.push_back("-tangent_kinds");
  return ClassifyUnhandledToolArg("draco_encoder", arg, false, flags,
                                  DracoUvFlagFamilies());
}

// Every flag of stock Draco 1.5.5's draco_encoder, draco_decoder and
// draco_transcoder.
const char *const kStockFlags[] = {
    "-h",           "-?",     "-i",         "-o",
    "-point_cloud", "-qp",    "-qt",        "-qn",
    "-qg",          "-qc",    "-qtg",       "-qw",
    "-cl",          "--skip", "--metadata", "-preserve_polygons"};

TEST(DracoUvFlagsTest, ValuesAndFileNamesAreIgnoredSilently) {
  for (const char *arg : {"mesh.obj", "auto", "3", "-1", "-0.5", "-1e-3", "-",
                          "", "uv_pred", "NORMAL"}) {
    const UnhandledToolArg verdict = Classify(arg);
    EXPECT_EQ(verdict.kind, UnhandledToolArg::kIgnore) << arg;
    EXPECT_EQ(verdict.message, "") << arg;
    EXPECT_EQ(Classify(arg, /*is_last=*/true).kind, UnhandledToolArg::kIgnore)
        << arg;
  }
}

TEST(DracoUvFlagsTest, OtherFlagsAreIgnoredWithAWarning) {
  for (const char *arg : {"-foo", "--verbose", "-x", "--", "-pred", "-uv",
                          "-texels", "-seam", "-tangents", "-quv_pred_x"}) {
    const UnhandledToolArg verdict = Classify(arg);
    EXPECT_EQ(verdict.kind, UnhandledToolArg::kWarn) << arg;
    EXPECT_EQ(verdict.message, "ignoring unknown flag " + std::string(arg));
    EXPECT_EQ(verdict.suggestion, "") << arg;
  }
}

TEST(DracoUvFlagsTest, NoStockFlagLooksLikeOurs) {
  for (const char *flag : kStockFlags) {
    EXPECT_EQ(Classify(flag).kind, UnhandledToolArg::kWarn) << flag;
    EXPECT_EQ(ClassifyWithNewFlag(flag).kind, UnhandledToolArg::kWarn) << flag;
  }
}

TEST(DracoUvFlagsTest, StockFlagWithoutItsValueAtTheEnd) {
  // draco_encoder ... -qp: the stock loop skips -qp, which needs a value.
  EXPECT_EQ(Classify("-qp", /*is_last=*/true).message,
            "ignoring -qp: no value follows it");
  EXPECT_EQ(Classify("-o", /*is_last=*/true).kind, UnhandledToolArg::kWarn);
  EXPECT_EQ(Classify("--skip", /*is_last=*/true).message,
            "ignoring --skip: no value follows it");
  EXPECT_EQ(Classify("-foo", /*is_last=*/true).message,
            "ignoring unknown flag -foo");
  // A boolean stock flag is never skipped: as the last argument it is still
  // an unknown flag when it reaches the hook (the other tool's flag).
  EXPECT_EQ(Classify("-point_cloud", /*is_last=*/true).message,
            "ignoring unknown flag -point_cloud");
}

TEST(DracoUvFlagsTest, MisspeltFlagIsAnErrorThatSuggestsTheFlag) {
  const UnhandledToolArg verdict = Classify("-uv_prd");
  EXPECT_EQ(verdict.kind, UnhandledToolArg::kError);
  EXPECT_EQ(verdict.suggestion, "-uv_pred");
  EXPECT_EQ(verdict.message, "unknown flag -uv_prd; did you mean -uv_pred?");
  // As the last argument too.
  EXPECT_EQ(Classify("-uv_prd", /*is_last=*/true).message, verdict.message);
}

TEST(DracoUvFlagsTest, NearMissesOfEveryKindSuggestTheirFlag) {
  const std::vector<std::pair<const char *, const char *>> cases = {
      {"-uvpred", "-uv_pred"},        // Missing underscore.
      {"--uv_pred", "-uv_pred"},      // Two dashes.
      {"-UV_PRED", "-uv_pred"},       // Case.
      {"-uv-pred", "-uv_pred"},       // Dash for underscore.
      {"-uv_prde", "-uv_pred"},       // Swapped letters.
      {"-v_pred", "-uv_pred"},        // Outside the family, one edit.
      {"-uvseams", "-uv_seams"},      // Outside the family, one edit.
      {"-uv_seam", "-uv_seams"},      // Singular.
      {"-uv_anchor", "-uv_anchors"},  // Singular.
      {"-uv_rms", "-uv_rmse"},
      {"-uv_texel", "-uv_texels"},
      {"-uv_texturesize", "-uv_texture_size"},
      {"-uv_texture", "-uv_texture_size"},  // Beginning of a longer flag.
      {"-uv_predict", "-uv_pred"},
  };
  for (const auto &[arg, flag] : cases) {
    const UnhandledToolArg verdict = Classify(arg);
    EXPECT_EQ(verdict.kind, UnhandledToolArg::kError) << arg;
    EXPECT_EQ(verdict.suggestion, flag) << arg;
    EXPECT_EQ(verdict.message, "unknown flag " + std::string(arg) +
                                   "; did you mean " + flag + "?");
  }
}

TEST(DracoUvFlagsTest, FlagWithEqualsSuggestsFlagAndValue) {
  EXPECT_EQ(Classify("-uv_pred=auto").message,
            "unknown flag -uv_pred=auto; did you mean -uv_pred auto?");
  EXPECT_EQ(Classify("--uv_seams=context").message,
            "unknown flag --uv_seams=context; did you mean -uv_seams context?");
  EXPECT_EQ(Classify("-uv_pred=").message,
            "unknown flag -uv_pred=; did you mean -uv_pred?");
}

// -qtg is draco_transcoder's own flag and draco_encoder's of draco-uv: the
// stock quantization flags a letter or two from it are no typos of it.
TEST(DracoUvFlagsTest, StockQuantizationFlagsAreNoNearMissesOfQtg) {
  for (const char *flag : {"-qp", "-qt", "-qn", "-qg", "-qc", "-qw"}) {
    EXPECT_EQ(Classify(flag, /*is_last=*/true).message,
              "ignoring " + std::string(flag) + ": no value follows it");
  }
  EXPECT_EQ(Classify("-qtg", /*is_last=*/true).message,
            "ignoring -qtg: no value follows it");
  for (const char *arg : {"-qx", "-qtgg", "-q"}) {
    EXPECT_EQ(Classify(arg).message,
              "ignoring unknown flag " + std::string(arg));
  }
}

TEST(DracoUvFlagsTest, FamilyFlagsAreOursWithoutAnEntry) {
  // No flag of that name in this build: still an error, never a stock file.
  for (const char *arg : {"-tangent_x", "-tangent_kinds", "-uv_quality",
                          "-UV_Something_else"}) {
    const UnhandledToolArg verdict = Classify(arg);
    EXPECT_EQ(verdict.kind, UnhandledToolArg::kError) << arg;
    EXPECT_EQ(verdict.suggestion, "") << arg;
    EXPECT_EQ(verdict.message,
              "unknown flag " + std::string(arg) +
                  "; this build's draco-uv flags are -uv_pred, -uv_anchors, "
                  "-uv_rmse, -uv_texels, -uv_texture_size, "
                  "-uv_decode_limit, -uv_seams, "
                  "-tangent_pred, -qtg.");
  }
}

TEST(DracoUvFlagsTest, TangentFlagNearMissesSuggestTheFlag) {
  EXPECT_EQ(Classify("-tangent_prd").message,
            "unknown flag -tangent_prd; did you mean -tangent_pred?");
  EXPECT_EQ(Classify("-tangentpred").suggestion, "-tangent_pred");
  EXPECT_EQ(Classify("--tangent_pred").suggestion, "-tangent_pred");
  EXPECT_EQ(Classify("-tangent_pred=auto").message,
            "unknown flag -tangent_pred=auto; did you mean -tangent_pred "
            "auto?");
}

TEST(DracoUvFlagsTest, AFlagIsOneEntryOfTheTable) {
  EXPECT_EQ(ClassifyWithNewFlag("-tangent_kind").message,
            "unknown flag -tangent_kind; did you mean -tangent_kinds?");
  EXPECT_EQ(ClassifyWithNewFlag("--tangent-kinds").suggestion,
            "-tangent_kinds");
  // The other flags are unaffected.
  EXPECT_EQ(ClassifyWithNewFlag("-uv_prd").suggestion, "-uv_pred");
  EXPECT_EQ(ClassifyWithNewFlag("-tangent_prd").suggestion, "-tangent_pred");
  EXPECT_EQ(ClassifyWithNewFlag("-foo").kind, UnhandledToolArg::kWarn);
}

TEST(DracoUvFlagsTest, FlagOfTheTableThatTheToolDoesNotTake) {
  // A flag of the table reaches the hook only when the tool has no branch
  // for it (a flag of the other tool).
  const UnhandledToolArg verdict = ClassifyWithNewFlag("-tangent_kinds");
  EXPECT_EQ(verdict.kind, UnhandledToolArg::kError);
  EXPECT_EQ(verdict.message, "-tangent_kinds is not a flag of draco_encoder");
  EXPECT_EQ(ClassifyUnhandledToolArg("", "-uv_pred", false).message,
            "-uv_pred is not a flag of this tool");
}

TEST(DracoUvFlagsTest, TableMatchesTheParsersAndTheHelp) {
  const std::string usage = UvCompressionUsage();
  const std::set<std::string> stock(std::begin(kStockFlags),
                                    std::end(kStockFlags));
  std::set<std::string> table;
  for (const char *flag : DracoUvFlagNames()) {
    EXPECT_TRUE(table.insert(flag).second) << "twice: " << flag;
    bool in_family = false;
    for (const char *family : DracoUvFlagFamilies()) {
      in_family |= std::string(flag).rfind(family, 0) == 0;
    }
    // A flag is of a family or has a stock tool's name (-qtg).
    EXPECT_NE(in_family, stock.count(flag) == 1) << flag;
    // A flag of the table is handled before the hook, so it is never
    // reported as unknown.
    EXPECT_TRUE(IsUvCompressionFlag(flag)) << flag;
    EXPECT_NE(usage.find(std::string(flag) + " "), std::string::npos) << flag;
  }
  // Every flag the help text names is in the table.
  const std::regex flag_pattern("-(uv|tangent)_[a-z][a-z_]*");
  for (auto it = std::sregex_iterator(usage.begin(), usage.end(), flag_pattern);
       it != std::sregex_iterator(); ++it) {
    EXPECT_EQ(table.count(it->str()), 1u) << it->str();
    EXPECT_TRUE(IsUvCompressionFlag(it->str().c_str())) << it->str();
  }
}

TEST(DracoUvFlagsTest, UsageExplainsUnknownFlags) {
  const std::string usage = UvCompressionUsage();
  EXPECT_NE(usage.find(UnknownToolFlagUsage()), std::string::npos);
  for (const char *family : DracoUvFlagFamilies()) {
    EXPECT_NE(UnknownToolFlagUsage().find(family), std::string::npos) << family;
  }
}

// CheckUnhandledToolArg()'s output and result for argv of |args|.
std::pair<bool, std::string> Check(std::vector<std::string> args, int index) {
  std::vector<char *> argv;
  for (std::string &arg : args) {
    argv.push_back(&arg[0]);
  }
  FILE *messages = std::tmpfile();
  EXPECT_NE(messages, nullptr);
  const bool go_on = CheckUnhandledToolArg(static_cast<int>(argv.size()),
                                           argv.data(), index, messages);
  std::rewind(messages);
  std::string text;
  for (int c; (c = std::fgetc(messages)) != EOF;) {
    text += static_cast<char>(c);
  }
  std::fclose(messages);
  return {go_on, text};
}

TEST(DracoUvFlagsTest, HookPrintsAndTellsTheToolWhetherToGoOn) {
  const std::vector<std::string> argv = {"/usr/local/bin/draco_transcoder",
                                         "-foo",
                                         "3",
                                         "-uv_prd",
                                         "auto",
                                         "-tangent_pred",
                                         "-qp"};
  EXPECT_EQ(Check(argv, 1),
            std::make_pair(
                true, std::string("Warning: ignoring unknown flag -foo\n")));
  EXPECT_EQ(Check(argv, 2), std::make_pair(true, std::string()));
  EXPECT_EQ(
      Check(argv, 3),
      std::make_pair(false, std::string("Error: unknown flag -uv_prd; did you "
                                        "mean -uv_pred?\n")));
  EXPECT_FALSE(Check(argv, 5).first);
  EXPECT_EQ(Check(argv, 6),
            std::make_pair(true, std::string("Warning: ignoring -qp: no value "
                                             "follows it\n")));
  // The tool's name is argv[0]'s base name.
  EXPECT_EQ(
      ClassifyUnhandledToolArg("draco_encoder", "-uv_rmse", false).message,
      "-uv_rmse is not a flag of draco_encoder");
  EXPECT_EQ(Check({"bin/draco_encoder", "-uv_rmse"}, 1).second,
            "Error: -uv_rmse is not a flag of draco_encoder\n");
  // Out of range: nothing to check.
  EXPECT_EQ(Check(argv, 0), std::make_pair(true, std::string()));
  EXPECT_EQ(Check(argv, 7), std::make_pair(true, std::string()));
}

}  // namespace
}  // namespace draco
