// The conventions of a command-line tool, as CLI11 gives them: --version, --opt=value, --, help
// with the library's real defaults, usage errors on stderr with exit 2, and numbers read exactly
// (no octal, no silent wrap-around of hole ids).
#include <sstream>

#include "cli_test_util.h"
#include "holefill/fill.h"
#include "holefill/holes.h"
#include "holefill/io.h"
#include "holefill/version.h"
#include "progress_lines.h"

namespace holefill {
namespace {
using namespace holefill::testing;

TEST_F(Cli, HelpForEachCommandOnStdout) {
  for (const auto& args :
       {std::vector<std::string>{"--help"}, {"help", "fill"}, {"fill", "--help"}, {"info", "-h"}}) {
    const CliRun run = run_cli(args);
    EXPECT_EQ(run.code, cli::kOk);
    EXPECT_NE(run.out.find("Usage: holefill"), std::string::npos) << run.out;
    EXPECT_TRUE(run.err.empty());
  }
}

// The defaults printed are the option structs' own, not a copy typed into the help.
TEST_F(Cli, FillHelpPrintsTheLibrarysDefaults) {
  const FillOptions defaults;
  const std::string help = run_cli({"help", "fill"}).out;
  std::ostringstream tau, iterations, restricted, weight;
  tau << "--tau FLOAT=" << defaults.refine.tau;
  iterations << "--smooth-iterations INT=" << defaults.smooth.iterations;
  restricted << "--restricted-above UINT=" << defaults.triangulate.restricted.above_edges;
  weight << "}=" << to_string(defaults.triangulate.weight) << "\n";
  for (const std::string& expected :
       {tau.str(), iterations.str(), restricted.str(), weight.str()}) {
    EXPECT_NE(help.find(expected), std::string::npos) << expected << "\n" << help;
  }
}

TEST_F(Cli, VersionPrintsTheProjectVersion) {
  const CliRun run = run_cli({"--version"});
  EXPECT_EQ(run.code, cli::kOk);
  EXPECT_EQ(run.out, "holefill " HOLEFILL_VERSION "\n");
}

TEST_F(Cli, NoArgumentsIsAUsageErrorOnStderr) {
  const CliRun run = run_cli({});
  EXPECT_EQ(run.code, cli::kUsage);
  EXPECT_TRUE(run.out.empty());
  EXPECT_NE(run.err.find("holefill --help"), std::string::npos) << run.err;
}

TEST_F(Cli, OptionEqualsValueAndDoubleDash) {
  // "--" ends the options: a mesh whose name starts with '-' can be given after it.
  const std::string odd = in_dir("-odd.obj");
  std::filesystem::copy_file(bunny(), odd);
  const std::string out = in_dir("out.obj");
  const CliRun run = run_cli({"fill", "--stage=triangulate", "--holes=1,2", "-o", out, "--", odd});
  ASSERT_EQ(run.code, cli::kOk) << run.err;
  EXPECT_EQ(find_holes(load_mesh(out)).size(), 1u);
}

// -q before or after the command's name; it silences the table, never a warning.
TEST_F(Cli, QuietPrintsNoTable) {
  const std::string quad = in_dir("quad.obj");
  std::ofstream(quad) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
                         "f 1 2 3 4\nf 1 2 5\nf 2 3 5\nf 3 4 5\n";
  for (const auto& args : {std::vector<std::string>{"-q", "fill", bunny(), "-o", in_dir("q.obj")},
                           {"fill", quad, "-o", in_dir("q.obj"), "-q"}}) {
    const CliRun run = run_cli(args);
    EXPECT_EQ(run.code, cli::kOk) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
    EXPECT_EQ(run.err.find("triangulated") != std::string::npos, args[1] == quad) << run.err;
  }
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// A long run showed nothing until the end; -v shows progress lines from the start, -q none.
// (The holes are triangulated on two threads, whose reports may cross: a step reported after a
// later one prints nothing, so a phase of 3 holes prints 1 to 3 lines, its 100 % always.)
TEST_F(Cli, VerboseShowsALineAsEachHoleIsTriangulatedAndAdded) {
  const CliRun verbose = run_cli({"fill", bunny(), "-o", in_dir("v.obj"), "-v"});
  ASSERT_EQ(verbose.code, cli::kOk) << verbose.err;
  EXPECT_GE(count(verbose.err, "holes triangulated"), 1u) << verbose.err;
  EXPECT_LE(count(verbose.err, "holes triangulated"), 3u) << verbose.err;
  EXPECT_NE(verbose.err.find("holes triangulated 100 %"), std::string::npos) << verbose.err;
  EXPECT_EQ(count(verbose.err, "patches added"), 3u) << verbose.err;  // added one by one
  EXPECT_NE(verbose.err.find("patches added 100 %"), std::string::npos) << verbose.err;
  const CliRun quiet = run_cli({"fill", bunny(), "-o", in_dir("q.obj"), "-q"});
  EXPECT_EQ(count(quiet.err, "holefill:"), 0u) << quiet.err;
  EXPECT_EQ(run_cli({"fill", bunny(), "-o", in_dir("x.obj"), "-q", "-v"}).code, cli::kUsage);
}

// Hole ids were read as int: 4294967296 filled hole 0 and 4294967298 hole 2; "010" is not 8.
TEST_F(Cli, HoleIdsAreReadExactlyAndOutOfRangeIdsRefused) {
  const std::string out = in_dir("x.obj");
  for (const char* ids :
       {"4294967296", "4294967298", "2147483648", "-1", "99999999999999999999", "0x1", "1e0"}) {
    const CliRun run = run_cli({"fill", bunny(), "-o", out, "--holes", std::string(ids)});
    EXPECT_EQ(run.code, cli::kUsage) << ids;
    EXPECT_NE(run.err.find("--holes"), std::string::npos) << run.err;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
  const CliRun leading_zero =
      run_cli({"fill", bunny(), "-o", out, "--holes", "010", "--stage", "triangulate"});
  EXPECT_EQ(leading_zero.code, cli::kUsage);  // hole 10, not 8: the bunny has 3
  EXPECT_NE(leading_zero.err.find("no hole 10"), std::string::npos) << leading_zero.err;
}

// A whole number past int64's range said "must be >= 0", which it is: the limit it passed is
// the one to name.
TEST_F(Cli, WholeNumbersTooLargeSayTheLargestAccepted) {
  const std::string out = in_dir("x.obj");
  for (const char* option : {"--max-boundary", "--restricted-above", "--remove-small-components"}) {
    const CliRun run = run_cli({"fill", bunny(), "-o", out, option, "99999999999999999999"});
    EXPECT_EQ(run.code, cli::kUsage) << option;
    EXPECT_NE(run.err.find(std::string(option) +
                           ": must be at most 9223372036854775807, got 99999999999999999999"),
              std::string::npos)
        << run.err;
    const CliRun negative = run_cli({"fill", bunny(), "-o", out, option, "-99999999999999999999"});
    EXPECT_NE(negative.err.find(std::string(option) + ": must be >= 0"), std::string::npos)
        << negative.err;
  }
  const CliRun iterations = run_cli({"fill", bunny(), "-o", out, "--smooth-iterations", "2000000"});
  EXPECT_NE(iterations.err.find("must be at most 1000000, got 2000000"), std::string::npos)
      << iterations.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// 4e-324 is a positive double (the smallest): it was refused as "needs a number".
TEST_F(Cli, NumbersAreRefusedWithTheirRange) {
  const std::string out = in_dir("x.obj");
  const CliRun tiny = run_cli({"fill", bunny(), "-o", out, "--tau", "4e-324", "--stage", "refine"});
  EXPECT_EQ(tiny.err.find("needs a number"), std::string::npos) << tiny.err;
  EXPECT_EQ(tiny.code, cli::kOk) << tiny.err;
  for (const char* tau : {"1e400", "inf", "nan", "0", "-1", "1e-400"}) {
    const CliRun run = run_cli({"fill", bunny(), "-o", out, "--tau", std::string(tau)});
    EXPECT_EQ(run.code, cli::kUsage) << tau;
    EXPECT_NE(run.err.find("> 0"), std::string::npos) << run.err;
  }
}

}  // namespace
}  // namespace holefill

namespace holefill {
namespace {

// 20,000 holes printed 40,000 lines with -v (one per hole and phase, most of them repeating the
// last): now a line per whole percentage, never one that goes back.
TEST(ProgressLines, ALineWhenThePercentageMovesOnHoweverManyHoles) {
  std::ostringstream err;
  cli::ProgressLines lines(err, "in.obj", true);
  constexpr int kHoles = 1000;
  for (int i = 1; i <= kHoles; ++i) lines.progress().set_fraction(0.5 * i / kHoles);
  lines.progress().set_fraction(0.5 * 10 / kHoles);  // another thread's late report
  for (int i = 1; i <= kHoles; ++i) lines.progress().set_fraction(0.5 + 0.5 * i / kHoles);
  std::istringstream text(err.str());
  std::vector<std::string> printed;
  for (std::string line; std::getline(text, line);) printed.push_back(line);
  ASSERT_EQ(printed.size(), 202u) << err.str();  // 0 ... 100 % in each phase
  for (int p = 0; p <= 100; ++p) {
    const std::string percent = " " + std::to_string(p) + " % (";
    EXPECT_EQ(printed[p].rfind("holefill: in.obj: holes triangulated" + percent, 0), 0u)
        << printed[p];
    EXPECT_EQ(printed[101 + p].rfind("holefill: in.obj: patches added" + percent, 0), 0u)
        << printed[101 + p];
  }
}

}  // namespace
}  // namespace holefill
