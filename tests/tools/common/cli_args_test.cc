#include "common/cli_args.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace hullpack {
namespace {

// A parser with one option of each kind, as the programs declare them.
struct Example {
  std::vector<std::string> inputs;
  std::string output, mode = "auto";
  bool force = false;
  double error = 0.5;
  uint32_t count = 7;
  std::string preset = "none";
  CliArgs cli{"example", "INPUT... -o OUTPUT [options]", "An example."};

  Example() {
    cli.Positional("INPUT", &inputs, 1, 2);
    cli.String("-o, --output", "OUTPUT", &output, "where").Required();
    cli.Flag("--force", &force, "replace");
    cli.Double("--max-error", "F", 0, 1, &error, "error");
    cli.Int("--count, -n", "N", 1, 100, &count, "count");
    cli.Choice("--mode", {"auto", "all", "none"}, &mode, "mode");
    cli.Value("--preset", "NAME", "preset", [this](const std::string& v) {
      preset = v;
      count = 50;  // a preset the other options refine
      return std::string();
    });
    cli.First();
  }
};

TEST(CliArgsTest, ParsesOptionsAndOperands) {
  Example e;
  EXPECT_FALSE(e.cli.Parse({"a.obj", "-o", "out.glb", "--force", "--max-error=0.25", "-n", "9",
                            "--mode", "none", "b.obj"}));
  EXPECT_EQ(e.inputs, (std::vector<std::string>{"a.obj", "b.obj"}));
  EXPECT_EQ(e.output, "out.glb");
  EXPECT_TRUE(e.force);
  EXPECT_DOUBLE_EQ(e.error, 0.25);
  EXPECT_EQ(e.count, 9u);
  EXPECT_EQ(e.mode, "none");
  EXPECT_TRUE(e.cli.Seen("--count"));
  EXPECT_TRUE(e.cli.Seen("-n"));
  EXPECT_FALSE(e.cli.Seen("--preset"));
}

TEST(CliArgsTest, FirstOptionAppliesBeforeTheOthersWhereverItStands) {
  Example e;
  EXPECT_FALSE(e.cli.Parse({"a.obj", "-o", "x", "--count", "3", "--preset", "p"}));
  EXPECT_EQ(e.preset, "p");
  EXPECT_EQ(e.count, 3u);
}

TEST(CliArgsTest, DoubleDashEndsOptions) {
  Example e;
  EXPECT_FALSE(e.cli.Parse({"-o", "x", "--", "--force"}));
  EXPECT_EQ(e.inputs, (std::vector<std::string>{"--force"}));
  EXPECT_FALSE(e.force);
}

TEST(CliArgsTest, HelpAndVersionExitZero) {
  Example help;
  testing::internal::CaptureStdout();
  EXPECT_EQ(help.cli.Parse({"--bogus", "--help"}), 0);
  const std::string text = testing::internal::GetCapturedStdout();
  EXPECT_EQ(text.rfind("usage: example INPUT... -o OUTPUT [options]\n", 0), 0u) << text;
  for (const char* line : {"  -o, --output OUTPUT", "  --count, -n N", "  --mode auto|all|none",
                           "  -h, --help", "  --version"}) {
    EXPECT_NE(text.find(line), std::string::npos) << line;
  }
  Example version;
  testing::internal::CaptureStdout();
  EXPECT_EQ(version.cli.Parse({"--version"}), 0);
  EXPECT_EQ(testing::internal::GetCapturedStdout().rfind("example (hullpack) ", 0), 0u);
}

// Each mistake: exit 64 and exactly one line on stderr that names the problem.
TEST(CliArgsTest, UsageErrorsExit64WithOneLine) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"a.obj"}, "missing --output OUTPUT"},
      {{"-o", "x"}, "missing INPUT"},
      {{"a", "b", "c", "-o", "x"}, "unexpected argument 'c'"},
      {{"a", "-o", "x", "--frob"}, "unknown option '--frob'"},
      {{"a", "-o"}, "-o needs a value (OUTPUT)"},
      {{"a", "-o", "x", "--force=yes"}, "--force takes no value"},
      {{"a", "-o", "x", "--max-error", "2"}, "--max-error takes a number in [0, 1], not '2'"},
      {{"a", "-o", "x", "--max-error", "nan"}, "not 'nan'"},
      {{"a", "-o", "x", "-n", "1.5"}, "-n takes a whole number in [1, 100], not '1.5'"},
      {{"a", "-o", "x", "--count", "0"}, "--count takes a whole number in [1, 100]"},
      {{"a", "-o", "x", "--mode", "some"}, "--mode takes auto, all, none, not 'some'"},
  };
  for (const auto& c : cases) {
    Example e;
    testing::internal::CaptureStderr();
    EXPECT_EQ(e.cli.Parse(c.first), kExitUsage) << c.second;
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(err.rfind("example: ", 0), 0u) << err;
    EXPECT_NE(err.find(c.second), std::string::npos) << err;
    EXPECT_EQ(err.find('\n'), err.size() - 1) << err;
  }
}

TEST(CliArgsTest, NumberParsers) {
  long long n = 0;
  EXPECT_EQ(CliArgs::ParseWholeNumber("42", 0, 100, &n), "");
  EXPECT_EQ(n, 42);
  EXPECT_NE(CliArgs::ParseWholeNumber("", 0, 100, &n), "");
  EXPECT_NE(CliArgs::ParseWholeNumber("99999999999999999999", 0, 100, &n), "");
  double d = 0;
  EXPECT_EQ(CliArgs::ParseNumber("1e-3", 0, 1, &d), "");
  EXPECT_DOUBLE_EQ(d, 1e-3);
  EXPECT_NE(CliArgs::ParseNumber("inf", -1e300, 1e300, &d), "");
  EXPECT_NE(CliArgs::ParseNumber("0.5x", 0, 1, &d), "");
}

}  // namespace
}  // namespace hullpack
