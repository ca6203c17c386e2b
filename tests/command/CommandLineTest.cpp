// A command as one line of text: split as a shell splits words (no expansions), canonical text,
// placeholders, and the command parameter's checks.

#include "parksim/usercode/CommandLine.h"

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"

namespace parksim {
namespace {

using Words = std::vector<std::string>;

TEST(CommandLineTest, SplitsWithAShellsQuotingAndNoExpansion) {
  EXPECT_EQ(splitCommandLine("  python3   plan.py\t{problem} {out} ", "c"),
            (Words{"python3", "plan.py", "{problem}", "{out}"}));
  EXPECT_EQ(splitCommandLine("a 'b c' \"d \\\"e\\\" \\n\" f\\ g '' $HOME *", "c"),
            (Words{"a", "b c", "d \"e\" \\n", "f g", "", "$HOME", "*"}));
  EXPECT_EQ(splitCommandLine("x'y'\"z\"", "c"), (Words{"xyz"}));
}

TEST(CommandLineTest, RefusesWhatItCannotSplitNamingTheOption) {
  auto message = [](const std::string& text) {
    try {
      splitCommandLine(text, "--planner-command");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("a 'b"), "--planner-command: unterminated ' quote");
  EXPECT_EQ(message("a \"b"), "--planner-command: unterminated \" quote");
  EXPECT_EQ(message("a \\"), "--planner-command: a backslash ends the command");
  EXPECT_EQ(message("   "), "--planner-command: no command given");
  std::string many;
  for (std::size_t i = 0; i <= kMaxCommandWords; ++i) many += "w ";
  EXPECT_EQ(message(many),
            "--planner-command: the command has 257 words, more than the limit "
            "of 256 (docs/limits.md)");
}

TEST(CommandLineTest, QuotingIsCanonicalAndSplitsBack) {
  const Words words = {"python3", "my planner.py", "it's", "", "a\"b\\c", "{out}", "--x=1"};
  const std::string text = quoteCommandLine(words);
  EXPECT_EQ(text, "python3 'my planner.py' 'it'\\''s' '' 'a\"b\\c' {out} --x=1");
  EXPECT_EQ(splitCommandLine(text, "c"), words);
  // Two spellings of one command have one canonical text.
  EXPECT_EQ(quoteCommandLine(splitCommandLine("a  \"b\"", "c")), "a b");
}

TEST(CommandLineTest, ReplacesPlaceholdersInsideWordsAndLeavesOtherBraces) {
  EXPECT_EQ(substitutePlaceholders({"p", "{problem}", "--out={out}/x", "{other}", "{out", "{}"},
                                   {{"problem", "/t/problem.json"}, {"out", "/t/out"}}),
            (Words{"p", "/t/problem.json", "--out=/t/out/x", "{other}", "{out", "{}"}));
}

TEST(CommandLineTest, TheCommandParameterIsCheckedBeforeAnythingRuns) {
  auto message = [](const ParamMap& params) {
    try {
      commandParam(params, "planner command", "{out}");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message({}),
            "planner command: parameter command is required: the command line to run, with "
            "{out}");
  EXPECT_EQ(message({{"command", "parksim-no-such-program {out}"}}),
            "planner command: parameter command: parksim-no-such-program is no program in PATH");
  EXPECT_EQ(message({{"command", "/dev/null {out}"}}),
            "planner command: parameter command: /dev/null is not an executable file");
  EXPECT_EQ(message({{"command", "sh -c true {problem}"}}),
            "planner command: parameter command: the command has no {out}");
  EXPECT_EQ(message({{"command", "sh -c true {out}"}}), "accepted");
}

TEST(CommandLineTest, KnownParametersAreAppliedAndTheRestPassedOn) {
  double timeout = 1.0;
  ParamSet known("planner command");
  known.add("timeout_s", &timeout, "s", 0.001, 10.0);
  const ParamMap passed =
      applyKnownParams({{"command", "x"}, {"timeout_s", "2.5"}, {"waypoints", "0 1"}}, known);
  EXPECT_EQ(timeout, 2.5);
  EXPECT_EQ(passed, (ParamMap{{"waypoints", "0 1"}}));
  EXPECT_THROW(applyKnownParams({{"timeout_s", "-1"}}, known), Error);
}

}  // namespace
}  // namespace parksim
