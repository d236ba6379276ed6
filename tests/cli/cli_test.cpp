// The impasto program run as a user runs it: each sub-command's options, exit status,
// messages and outputs; progress in a log; --json that parses; old spellings that still work.
// Every run is small (a 240x160-cell session of three strokes, a 64x48-cell painting).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "../common/short_session.hpp"
#include "command_catalogue.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/render/image.hpp"
#include "vocabulary_words.hpp"

namespace impasto::app {
namespace {

namespace fs = std::filesystem;

struct CommandRun {
  int status = -1;
  std::string out, err;
};

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

int count_of(const std::string& text, const std::string& part) {
  int n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("impasto_cli_" + std::string(info->name()) + "_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // `impasto ARGS` with the environment assignments `env` (e.g. "IMPASTO_PROGRESS=lines"),
  // standard output and error apart. The recovery folder is this test's own.
  CommandRun impasto(const std::string& args, const std::string& env = "") const {
    const fs::path out = dir_ / "stdout.txt", err = dir_ / "stderr.txt";
    const std::string command = "cd '" + dir_.string() + "' && env -u IMPASTO_PROGRESS " +
                                "XDG_STATE_HOME='" + (dir_ / "state").string() + "' " + env +
                                " '" IMPASTO_EXECUTABLE "' " + args + " >'" + out.string() +
                                "' 2>'" + err.string() + "' </dev/null";
    const int status = std::system(command.c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_text(out), read_text(err)};
  }

  // The short session (tests/common/short_session.hpp), written once per test.
  fs::path session() const {
    const fs::path path = dir_ / "short.strokes";
    return fs::exists(path) ? path : test::write_short_session(path);
  }

  // A 64x48-cell painting of that session, made once per test.
  fs::path painting() const {
    const fs::path path = dir_ / "small.impasto";
    if (!fs::exists(path)) {
      session();
      const CommandRun r = impasto("replay short.strokes --size 64x48 --save small.impasto -q");
      EXPECT_EQ(r.status, 0) << r.err;
    }
    return path;
  }

  fs::path dir_;
};

TEST_F(Cli, TopLevelHelpListsEveryCommandAndPointsToTheVocabulary) {
  const CommandRun r = impasto("--help");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const std::string& path : command_paths()) {
    if (path.find(' ') == std::string::npos) {  // a command of the program's own
      EXPECT_NE(r.out.find("  " + path + " "), std::string::npos) << path;
    }
  }
  EXPECT_NE(r.out.find("impasto help vocabulary"), std::string::npos);
  EXPECT_NE(r.out.find("-q,--quiet"), std::string::npos);
  EXPECT_EQ(impasto("help").out, r.out);
}

TEST_F(Cli, VersionNamesTheLicence) {
  const CommandRun r = impasto("--version");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("impasto ", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("Apache License 2.0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("NOTICE"), std::string::npos) << r.out;
}

// The memory budget follows the process's limits, not the machine's RAM: under `ulimit -v`
// a 55-byte stroke file varnishing a 16384² canvas fails at once naming its line and the
// limit (it once took 3.9 GB and ended with a bare std::bad_alloc).
TEST_F(Cli, AHugeVarnishFailsByLineUnderAnAddressSpaceLimit) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer maps terabytes of shadow memory: no RLIMIT_AS fits it";
#else
  std::ofstream(dir_ / "v.strokes")
      << "impasto-strokes 1\ncanvas 16384 16384 150\nvarnish gloss 0.5\n";
  const CommandRun r = impasto("replay v.strokes -q", "prlimit --as=2000000000");
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("v.strokes:3: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("more than the memory budget of"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ulimit -v (RLIMIT_AS)"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("bad_alloc"), std::string::npos) << r.err;
#endif
}

// A tiny painting that declares a large canvas renders a band of rows at a time, so under
// `ulimit -v` of 1 GB its 26-megapixel PNG is written (the whole canvas's render state, 40
// bytes a cell, was 1.05 GB: refused).
TEST_F(Cli, AHugeBareCanvasRendersByBandsUnderAnAddressSpaceLimit) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer maps terabytes of shadow memory: no RLIMIT_AS fits it";
#else
  std::ofstream(dir_ / "big.strokes") << "impasto-strokes 2\ncanvas 5120 5120 300\n";
  const CommandRun r = impasto("replay big.strokes -o big.png -q", "prlimit --as=1000000000");
  EXPECT_EQ(r.status, 0) << r.err;
  const render::Image image = render::read_png(dir_ / "big.png");
  EXPECT_EQ(image.width, 5120);
  EXPECT_EQ(image.height, 5120);
#endif
}

// A numeric option refuses NaN and infinities by name (CLI11's range check lets NaN through):
// `--history-mb nan` once reached the save.
TEST_F(Cli, NumericOptionsRefuseNanAndInfinity) {
  const std::string small = painting().string();
  for (const std::string& args : {"edit " + small + " --dry 0.1 --save e.impasto --history-mb nan",
                                  "render " + small + " -o r.png --ambient inf",
                                  "export " + small + " -o x.png --scale nan"}) {
    const CommandRun r = impasto(args);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_TRUE(r.err.find("is not a finite number") != std::string::npos ||
                r.err.find("could not be converted") != std::string::npos)
        << args << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "e.impasto"));
}

// WxH is read by one parser wherever a canvas size is taken (--size of replay and bench
// render, --canvas of bench window), and its message names the option once.
TEST_F(Cli, ACanvasSizeIsReadByOneParserEverywhere) {
  for (const std::string& args : {std::string("replay short.strokes --size 64by48"),
                                  std::string("bench render --size 64by48")}) {
    session();
    const CommandRun r = impasto(args);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_NE(r.err.find("impasto: --size: expected WIDTHxHEIGHT in cells (1..131072 each)"),
              std::string::npos)
        << args << ": " << r.err;
  }
}

TEST_F(Cli, EverySubCommandHasAHelpWithoutOldSpellings) {
  // The help texts in process (a program run each would take seconds), then two as run.
  for (const std::string& path : command_paths()) {
    const std::string help = command_help(path);
    EXPECT_NE(help.find("--quiet"), std::string::npos) << path;
    for (const char* old : {"--png", "--stats", "--illuminant", "--width ", "Deprecated"})
      EXPECT_EQ(help.find(old), std::string::npos) << path << " shows " << old;
  }
  for (const char* path : {"replay", "bench marks"}) {
    const CommandRun r = impasto(std::string(path) + " --help");
    EXPECT_EQ(r.status, 0) << path << ": " << r.err;
    EXPECT_NE(r.out.find("Usage:"), std::string::npos) << path;
  }
}

TEST_F(Cli, ACommandWithNothingToDoSaysWhatItCouldDo) {
  // A group alone lists its commands.
  CommandRun r = impasto("bench");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("Usage: impasto bench"), std::string::npos) << r.out;
  for (const char* sub : {"  sim ", "  marks ", "  color "})
    EXPECT_NE(r.out.find(sub), std::string::npos) << sub;
  // A command missing what it needs: the error, its usage and where its options are.
  r = impasto("render");
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(
      r.err.rfind("impasto: painting is required\nUsage: impasto render [OPTIONS] painting\n", 0),
      0u)
      << r.err;
  EXPECT_NE(r.err.find("`impasto render --help` lists its options."), std::string::npos) << r.err;
  r = impasto("--no-such-option");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("`impasto --help` lists the commands."), std::string::npos) << r.err;
}

TEST_F(Cli, HelpVocabularyPrintsTheProgramsTables) {
  const CommandRun r = impasto("help vocabulary");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, vocabulary_markdown());
}

TEST_F(Cli, ReplayWithNothingToWriteSaysWhatItDidAndWhatWouldWrite) {
  session();
  const CommandRun r = impasto("replay short.strokes");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("replayed short.strokes: 3 strokes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("240x160 cells"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nothing written"), std::string::npos) << r.out;
  for (const char* hint : {"-o FILE.png", "--save FILE.impasto", "--json"})
    EXPECT_NE(r.out.find(hint), std::string::npos) << hint;
  // A job under a second in a log shows no progress; on a loaded machine (the sanitizers, other
  // builds) the same replay can pass a second, and then only progress lines may appear.
  std::istringstream err(r.err);
  for (std::string line; std::getline(err, line);) {
    EXPECT_EQ(line.rfind("replay: ", 0), 0u) << line;
    EXPECT_NE(line.find(" records"), std::string::npos) << line;
  }
}

TEST_F(Cli, ReplayWritesTheImageToOutAndThePaintingToSave) {
  session();
  const CommandRun r =
      impasto("replay short.strokes -o image.png --save painting.impasto --wavelengths 4");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("wrote image.png"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wrote painting.impasto"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("nothing written"), std::string::npos);
  const render::Image image = render::read_png(dir_ / "image.png");
  EXPECT_EQ(image.width, 240);
  EXPECT_EQ(image.height, 160);
  EXPECT_EQ(paintcore::Painting::load(dir_ / "painting.impasto").canvas().width_cells(), 240);
}

TEST_F(Cli, ReplayJsonIsTheStatisticsAloneOnStandardOutput) {
  session();
  const CommandRun r = impasto("replay short.strokes --json --save s.impasto");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json stats = nlohmann::json::parse(r.out);  // throws on anything else
  EXPECT_EQ(stats.at("strokes"), 3);
  EXPECT_EQ(stats.at("canvas").at("width_cells"), 240);
  EXPECT_TRUE(stats.at("state_hash").is_string());
}

TEST_F(Cli, ReplayOldSpellingsStillWorkWithAWarning) {
  session();
  const CommandRun r = impasto("replay short.strokes --out old.impasto --png old.png --stats");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("--png is deprecated: use -o/--out"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--stats is deprecated: use --json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--out old.impasto: --out is now the rendered image"), std::string::npos)
      << r.err;
  EXPECT_NO_THROW(nlohmann::json::parse(r.out));
  EXPECT_EQ(paintcore::Painting::load(dir_ / "old.impasto").canvas().height_cells(), 160);
  EXPECT_EQ(render::read_png(dir_ / "old.png").height, 160);
}

TEST_F(Cli, ReplayRefusesASaveThatIsNoPaintingAndTwoImages) {
  session();
  CommandRun r = impasto("replay short.strokes --save picture.png");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("--save picture.png: a painting is saved as FILE.impasto"),
            std::string::npos)
      << r.err;
  r = impasto("replay short.strokes -o picture.tif --save p.impasto");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("picture.tif: unknown image type '.tif'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "p.impasto"));  // refused before anything ran
  r = impasto("replay short.strokes -o a.png --png b.png");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("two images"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "a.png"));
}

TEST_F(Cli, WavelengthsAreOneToSixteenOrFullEverywhere) {
  session();
  CommandRun r = impasto("replay short.strokes --wavelengths 17");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("expected 1..16 or full, not '17'"), std::string::npos) << r.err;
  r = impasto("render " + painting().string() + " -o full.png --wavelengths full");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "full.png"));
  r = impasto("render " + painting().string() + " -o zero.png --wavelengths 0");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("--wavelengths 0 is deprecated: use --wavelengths full"), std::string::npos)
      << r.err;
  r = impasto("render " + painting().string() + " -o x.png --wavelengths many");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("--wavelengths"), std::string::npos) << r.err;
}

TEST_F(Cli, TheWindowRefusesFullWavelengthsBeforeOpening) {
  const std::vector<std::string> paths = command_paths();
  if (std::find(paths.begin(), paths.end(), "paint") == paths.end())
    GTEST_SKIP() << "built without the window";
  const CommandRun r = impasto("paint --wavelengths full", "DISPLAY=");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("full (every nm) is the CPU render's"), std::string::npos) << r.err;
}

TEST_F(Cli, SizeIsWidthByHeightInCells) {
  session();
  CommandRun r = impasto("replay short.strokes --size 120");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("expected WIDTHxHEIGHT in cells"), std::string::npos) << r.err;
  r = impasto("replay short.strokes --size 120x80 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out).at("canvas").at("height_cells"), 80);
  r = impasto("cracks generate --size 64x32 --out cracks.png --seed 3");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out).at("tiles"), 1);
  const render::Image image = render::read_png(dir_ / "cracks.png");
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 32);
  // The old spellings: the same canvas, with a warning each.
  r = impasto("cracks generate --width 64 --height 32 --seed 3");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(count_of(r.err, "is deprecated: use --size WxH"), 2) << r.err;
}

TEST_F(Cli, ProgressInALogIsPlainLinesEndingWithTheTotal) {
  session();
  const CommandRun r =
      impasto("replay short.strokes -o p.png --wavelengths 3", "IMPASTO_PROGRESS=lines");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos);
  std::istringstream lines(r.err);
  std::string line, last_replay, last_render;
  int replay_lines = 0, render_lines = 0;
  while (std::getline(lines, line)) {
    if (line.rfind("replay: ", 0) == 0) ++replay_lines, last_replay = line;
    if (line.rfind("render: ", 0) == 0) ++render_lines, last_render = line;
  }
  EXPECT_GE(replay_lines, 2) << r.err;  // the first record, then the total
  EXPECT_GE(render_lines, 2) << r.err;
  EXPECT_NE(last_replay.find("100% "), std::string::npos) << last_replay;
  EXPECT_NE(last_replay.find(" records, "), std::string::npos) << last_replay;
  EXPECT_NE(last_replay.find("records/s, done"), std::string::npos) << last_replay;
  EXPECT_NE(last_render.find("tiles/s, done"), std::string::npos) << last_render;
}

TEST_F(Cli, QuietPrintsOnlyResultsAndWarnings) {
  session();
  CommandRun r = impasto("replay short.strokes --quiet --save q.impasto", "IMPASTO_PROGRESS=lines");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "");
  EXPECT_TRUE(fs::exists(dir_ / "q.impasto"));
  r = impasto("-q replay short.strokes --json --stats", "IMPASTO_PROGRESS=lines");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NO_THROW(nlohmann::json::parse(r.out));
  EXPECT_EQ(r.err, "impasto: warning: --stats is deprecated: use --json\n");
}

TEST_F(Cli, RenderSaysWhatItWroteOrPrintsJson) {
  CommandRun r = impasto("render " + painting().string() + " -o r.png --wavelengths 3");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("wrote r.png (64x48, rendered in ", 0), 0u) << r.out;
  r = impasto("render " + painting().string() + " -o r.exr --wavelengths 3 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("out"), "r.exr");
  EXPECT_EQ(j.at("width"), 64);
  EXPECT_EQ(j.at("height"), 48);
  EXPECT_EQ(j.at("wavelengths"), 3);
  EXPECT_GE(j.at("render_seconds").get<double>(), 0.0);
  EXPECT_GE(j.at("load_seconds").get<double>(), 0.0);
}

TEST_F(Cli, RenderRefusesUnknownChoicesNamingThem) {
  struct Case {
    const char* option;
    const char* a_choice;
  };
  for (const Case c :
       {Case{"--display adobe-rgb", "display-p3"}, Case{"--adaptation cat02", "bradford"},
        Case{"--storage double", "half"}, Case{"--flake-depth deep", "no-masking"},
        Case{"--crack-model exact", "gouffe"}, Case{"--light-type laser", "spot"}}) {
    // Refused while parsing, before the file is read: any existing file will do.
    const CommandRun r = impasto("render " + session().string() + " -o x.png " + c.option);
    EXPECT_NE(r.status, 0) << c.option;
    EXPECT_NE(r.err.find(c.a_choice), std::string::npos) << c.option << ": " << r.err;
  }
  const CommandRun missing = impasto("render " + painting().string());
  EXPECT_NE(missing.status, 0);
  EXPECT_NE(missing.err.find("--out"), std::string::npos) << missing.err;
}

TEST_F(Cli, PigmentsListAndCheckPrintJson) {
  CommandRun r = impasto("pigments list --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json list = nlohmann::json::parse(r.out);
  bool white = false;
  for (const auto& p : list) white |= p.at("name") == "White";
  EXPECT_TRUE(white);
  // A folder with one good pigment (exported from the library) and one broken file.
  fs::create_directories(dir_ / "mine");
  r = impasto("pigments export \"Red Oxide\" -o mine/sienna.csv");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "exported Red Oxide: mine/sienna.csv\n");
  r = impasto("pigments export \"Red Oxide\" -o quiet.csv --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "");  // the note left out
  EXPECT_TRUE(fs::exists(dir_ / "quiet.csv"));
  std::ofstream(dir_ / "mine" / "broken.csv") << "# quantity: kubelka_munk\nwavelength_nm,K\n";
  r = impasto("pigments check mine --json");
  EXPECT_EQ(r.status, 1);
  const nlohmann::json check = nlohmann::json::parse(r.out);
  ASSERT_EQ(check.at("pigments").size(), 1u) << r.out;
  EXPECT_EQ(check.at("pigments")[0].at("name"), "Red Oxide");
  ASSERT_EQ(check.at("errors").size(), 1u) << r.out;
  EXPECT_NE(check.at("errors")[0].get<std::string>().find("broken.csv"), std::string::npos);
  r = impasto("pigments show \"Red Oxide\" --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json show = nlohmann::json::parse(r.out);
  EXPECT_EQ(show.at("K").size(), show.at("nm").size());
  EXPECT_EQ(show.at("S").size(), show.at("nm").size());
  EXPECT_GT(show.at("nm").size(), 10u);
  r = impasto("pigments swatch \"Red Oxide\" --json --tint 1:4");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out).at("swatches").size(), 1u);
}

TEST_F(Cli, ColorXyzTakesTheLightAndTheOldIlluminant) {
  std::ofstream(dir_ / "grey.csv") << "# quantity: reflectance\nwavelength_nm,grey\n380,0.5\n"
                                      "780,0.5\n";
  CommandRun r = impasto("color xyz grey.csv --light A --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json a = nlohmann::json::parse(r.out);
  EXPECT_NEAR(a.at("samples")[0].at("Lab")[0].get<double>(), 76.07, 0.5);  // L* of 0.5
  r = impasto("color xyz grey.csv -i A --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out), a);
  EXPECT_NE(r.err.find("-i is deprecated: use --light"), std::string::npos) << r.err;
}

TEST_F(Cli, ColorRecipeNamesThePigmentsNearestAColour) {
  CommandRun r = impasto("color recipe '#2E8B57' --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json out = nlohmann::json::parse(r.out);
  const nlohmann::json& recipes = out.at("recipes");
  ASSERT_GE(recipes.size(), 2u);
  // Each offered recipe has a pigment more and comes nearer than the one before.
  for (std::size_t k = 1; k < recipes.size(); ++k) {
    EXPECT_EQ(recipes[k].at("parts").size(), k + 1);
    EXPECT_LT(recipes[k].at("delta_e00").get<double>(),
              recipes[k - 1].at("delta_e00").get<double>());
  }
  EXPECT_EQ(impasto("color recipe 46,139,87 --json").out, r.out);
  r = impasto("color recipe '#2E8B' --json");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("colour '#2E8B': expected #RRGGBB or R,G,B"), std::string::npos) << r.err;
}

TEST_F(Cli, RecoverSavesToSaveAndStillTakesOut) {
  const CommandRun r = impasto("recover --apply latest --out x.impasto");
  EXPECT_EQ(r.status, 1);  // no session to recover in this test's folder
  EXPECT_NE(r.err.find("--out is deprecated: use --save"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no session to recover"), std::string::npos) << r.err;
  EXPECT_EQ(impasto("recover").status, 0);
  const CommandRun list = impasto("recover --json");
  ASSERT_EQ(list.status, 0) << list.err;
  EXPECT_TRUE(nlohmann::json::parse(list.out).at("sessions").empty());
}

TEST_F(Cli, HidListPrintsJson) {
  const CommandRun r = impasto("hid list --json");
  if (r.err.find("without hidapi") != std::string::npos) GTEST_SKIP() << r.err;
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json tablets = nlohmann::json::parse(r.out);  // this machine's: maybe none
  ASSERT_TRUE(tablets.is_array());
  for (const auto& t : tablets) EXPECT_TRUE(t.at("path").is_string());
}

TEST_F(Cli, ThumbnailWritesASmallPng) {
  const CommandRun r = impasto("thumbnail " + painting().string() + " thumb.png 32");
  ASSERT_EQ(r.status, 0) << r.err;
  const render::Image image = render::read_png(dir_ / "thumb.png");
  EXPECT_EQ(image.width, 32);  // the longer side of 64x48
  EXPECT_EQ(image.height, 24);
}

TEST_F(Cli, CracksCommandsPrintOneJsonObject) {
  CommandRun r = impasto("cracks cavity --shape cone-pit --depth-mm 0.2 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json cavity = nlohmann::json::parse(r.out);
  EXPECT_EQ(cavity.at("shape"), "cone-pit");
  EXPECT_GT(cavity.at("F").get<double>(), 0.0);
  r = impasto("cracks cavity --shape hexagon");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("cylinder-pit"), std::string::npos) << r.err;  // the choices
  r = impasto("cracks brush " + painting().string() + " --points \"1,1 4,3\"");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("--save"), std::string::npos) << r.err;
  r = impasto("cracks brush " + painting().string() + " --points \"1,1 4,3\" --save c.impasto");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_GT(nlohmann::json::parse(r.out).at("crack_cells").get<int>(), 0);
}

TEST_F(Cli, RenderAndReplayDefaultToTheOptimisedRule) {
  for (const char* command : {"render", "replay"}) {
    const CommandRun r = impasto(std::string(command) + " --help");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("{impasto,interpolatory,fitted,optimised}=optimised"), std::string::npos)
        << command << ":\n"
        << r.out;
  }
}

TEST_F(Cli, BenchColorPrintsOneJsonRowPerRule) {
  const CommandRun r = impasto(
      "bench color --nodes 3 --lights D65 --cells 0 --no-half --weights interpolatory --json");
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream lines(r.out);
  std::vector<int> nodes;
  for (std::string line; std::getline(lines, line);)
    nodes.push_back(nlohmann::json::parse(line).at("n"));
  EXPECT_EQ(nodes, (std::vector<int>{3, 0}));  // 0: the full spectrum
}

TEST_F(Cli, BenchSimPrintsOneJsonRowPerBrush) {
  const CommandRun r = impasto("bench sim --json --runs 1 --steps 2 --brush 8 --brush 12");
  ASSERT_EQ(r.status, 0) << r.err;
  std::istringstream lines(r.out);
  std::string line;
  std::vector<int> brushes;
  while (std::getline(lines, line)) brushes.push_back(nlohmann::json::parse(line).at("brush"));
  EXPECT_EQ(brushes, (std::vector<int>{8, 12}));
}

TEST_F(Cli, BenchMarksHeadWidthIsHeadMm) {
  const CommandRun r = impasto("bench marks --size 0.1");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("--size is deprecated: use --head-mm"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("expected the head's width in mm"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace impasto::app
