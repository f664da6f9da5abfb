// The course's command line (issue 19): every flag of handleGraphicsArgs (umdcs4212/starterCode
// src/handleGraphicsArgs.cpp) parses to the vkrt option with the course's meaning, -d is refused
// naming depth of field, and bad values are refused.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "command_line.h"
#include "input_limits.h"

namespace vkrt {
namespace {

struct Parsed {
    ParseResult result;
    std::string err, out;  // what the parser printed
};

Parsed parse(std::vector<std::string> args) {
    args.insert(args.begin(), "vkrt");
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    testing::internal::CaptureStderr();
    testing::internal::CaptureStdout();
    Parsed p{parseCommandLine(static_cast<int>(argv.size()), argv.data()), "", ""};
    p.out = testing::internal::GetCapturedStdout();
    p.err = testing::internal::GetCapturedStderr();
    return p;
}

CommandLine parseOk(const std::vector<std::string>& args) {
    Parsed p = parse(args);
    EXPECT_TRUE(p.result.commandLine.has_value()) << p.err;
    return p.result.commandLine.value_or(CommandLine{});
}

// A usage error: no command line, exit code 2, and the message printed; returns the message.
std::string parseRefused(const std::vector<std::string>& args) {
    Parsed p = parse(args);
    EXPECT_FALSE(p.result.commandLine.has_value());
    EXPECT_EQ(p.result.exitCode, 2);
    return p.err;
}

TEST(CourseCommandLine, TheCourseScriptSpellingsSetTheirOptions) {
    const CommandLine cl = parseOk({"-i", "in.xml", "-o", "out.png", "-w", "320", "-h", "200", "-r", "9", "-k", "3"});
    EXPECT_EQ(cl.scenePath, "in.xml");
    EXPECT_EQ(cl.outputPath, "out.png");
    EXPECT_EQ(cl.render.width, 320);
    EXPECT_EQ(cl.render.height, 200);
    EXPECT_EQ(cl.render.samplesPerPixel, 9);
    EXPECT_EQ(cl.render.maxDepth, 3);
}

TEST(CourseCommandLine, LongCourseNamesAreAliases) {
    const CommandLine cl = parseOk({"--inputfile", "in.xml", "--outputfile", "out.exr", "--numcpus", "3",
                                    "--recursionDepth", "2", "--aspect", "2", "--verbose"});
    EXPECT_EQ(cl.scenePath, "in.xml");
    EXPECT_EQ(cl.outputPath, "out.exr");
    EXPECT_EQ(cl.render.threads, 3);
    EXPECT_EQ(cl.render.maxDepth, 2);
    EXPECT_EQ(cl.render.height, 125);
    EXPECT_TRUE(cl.verbose);
}

TEST(CourseCommandLine, NumCpusSetsTheCpuThreadCount) {
    EXPECT_EQ(parseOk({"s.xml", "-n", "2"}).render.threads, 2);
    EXPECT_EQ(parseOk({"s.xml", "--threads", "5"}).render.threads, 5);
    EXPECT_EQ(parseOk({"s.xml"}).render.threads, 0);  // all cores
    EXPECT_NE(parseRefused({"s.xml", "-n", "two"}), "");
    EXPECT_NE(parseRefused({"s.xml", "-n", "-1"}), "");
}

TEST(CourseCommandLine, CpuCountIsGivenOnce) {
    EXPECT_NE(parseRefused({"s.xml", "-n", "2", "--threads", "3"}), "");
}

TEST(CourseCommandLine, AspectSetsTheHeightFromTheWidth) {
    const CommandLine cl = parseOk({"s.xml", "-w", "500", "-a", "1.7777778"});
    EXPECT_EQ(cl.render.width, 500);
    EXPECT_EQ(cl.render.height, 281);  // 500 / (16/9) = 281.25
}

TEST(CourseCommandLine, AspectAloneKeepsTheDefaultWidth) {
    const CommandLine cl = parseOk({"s.xml", "-a", "0.5"});
    EXPECT_EQ(cl.render.width, 250);
    EXPECT_EQ(cl.render.height, 500);
}

TEST(CourseCommandLine, AspectSetsTheWidthFromTheHeightWhenOnlyHeightIsGiven) {
    const CommandLine cl = parseOk({"s.xml", "-h", "300", "-a", "1.5"});
    EXPECT_EQ(cl.render.width, 450);
    EXPECT_EQ(cl.render.height, 300);
}

TEST(CourseCommandLine, AspectThatMatchesBothSidesIsAccepted) {
    const CommandLine cl = parseOk({"s.xml", "-w", "500", "-h", "281", "-a", "1.7777778"});
    EXPECT_EQ(cl.render.width, 500);
    EXPECT_EQ(cl.render.height, 281);
}

TEST(CourseCommandLine, AspectThatContradictsBothSidesIsRefused) {
    const std::string err = parseRefused({"s.xml", "-w", "500", "-h", "500", "-a", "2"});
    EXPECT_NE(err.find("-a 2"), std::string::npos) << err;
    EXPECT_NE(err.find("contradicts -w 500 -h 500"), std::string::npos) << err;
}

TEST(CourseCommandLine, BadAspectsAreRefused) {
    EXPECT_NE(parseRefused({"s.xml", "-a", "0"}), "");
    EXPECT_NE(parseRefused({"s.xml", "-a", "-1"}), "");
    EXPECT_NE(parseRefused({"s.xml", "-a", "wide"}), "");
    const std::string err = parseRefused({"s.xml", "-w", "60000", "-a", "0.5"});
    EXPECT_NE(err.find("height of 120000"), std::string::npos) << err;
}

TEST(CourseCommandLine, VerboseIsAFlagAndExcludesQuiet) {
    EXPECT_TRUE(parseOk({"s.xml", "-v"}).verbose);
    EXPECT_FALSE(parseOk({"s.xml"}).verbose);
    EXPECT_NE(parseRefused({"s.xml", "-v", "-q"}), "");
}

TEST(CourseCommandLine, VerboseSettingsNameTheResolvedValues) {
    const std::string text = describeSettings(parseOk({"s.xml", "-w", "400", "-a", "2", "-n", "3", "-r", "4", "-k", "5"}));
    EXPECT_NE(text.find("scene: s.xml"), std::string::npos) << text;
    EXPECT_NE(text.find("output: s.png"), std::string::npos) << text;
    EXPECT_NE(text.find("image: 400x200 (aspect 2)"), std::string::npos) << text;
    EXPECT_NE(text.find("rays per pixel: 4 (jittered)"), std::string::npos) << text;
    EXPECT_NE(text.find("recursion depth: 5"), std::string::npos) << text;
    EXPECT_NE(text.find("CPU threads: 3"), std::string::npos) << text;
}

// Issue 21: the course's -d is the focus distance; --aperture the lens diameter. Unset, neither
// overrides the scene's camera.
TEST(CourseCommandLine, DepthOfFieldTakesTheFocusDistanceAndAperture) {
    const CommandLine cl = parseOk({"s.xml", "-d", "5", "--aperture", "0.25"});
    EXPECT_EQ(cl.focusDistance, 5.0f);
    EXPECT_EQ(cl.aperture, 0.25f);
    EXPECT_EQ(parseOk({"s.xml", "--depth", "2.5"}).focusDistance, 2.5f);
    EXPECT_EQ(parseOk({"s.xml", "--focus-distance", "0"}).focusDistance, 0.0f);
    const CommandLine none = parseOk({"s.xml"});
    EXPECT_FALSE(none.focusDistance.has_value());
    EXPECT_FALSE(none.aperture.has_value());
    EXPECT_NE(parseRefused({"s.xml", "-d", "-1"}), "");
    EXPECT_NE(parseRefused({"s.xml", "--aperture", "-0.5"}), "");
    // Issue 38: beyond float, as a scene file's <aperture> refuses it (it was read as inf).
    EXPECT_NE(parseRefused({"s.xml", "--aperture", "1e39"}).find("beyond what a float holds"), std::string::npos);
    EXPECT_NE(parseRefused({"s.xml", "-d", "1e300"}).find("beyond what a float holds"), std::string::npos);
    EXPECT_EQ(parseOk({"s.xml", "-d", "1e30", "--aperture", "3e38"}).aperture, 3e38f);
    EXPECT_NE(parseRefused({"s.xml", "-d"}), "");  // a value is required
    EXPECT_NE(describeSettings(cl).find("focus distance: 5\naperture: 0.25"), std::string::npos) << describeSettings(cl);
}

// Issue 21: --shutter OPEN,CLOSE in the motion's time; unset, the renderers use the whole motion.
TEST(CommandLineOptions, ShutterTakesOpenAndClose) {
    const CommandLine cl = parseOk({"s.xml", "--shutter", "0.25,0.75"});
    ASSERT_TRUE(cl.render.shutter.has_value());
    EXPECT_EQ(*cl.render.shutter, glm::vec2(0.25f, 0.75f));
    EXPECT_EQ(shutterOf(cl.render), glm::vec2(0.25f, 0.75f));
    EXPECT_FALSE(parseOk({"s.xml"}).render.shutter.has_value());
    EXPECT_EQ(shutterOf(parseOk({"s.xml"}).render), glm::vec2(0.0f, 1.0f));
    EXPECT_EQ(*parseOk({"s.xml", "--shutter", "0,0"}).render.shutter, glm::vec2(0.0f));
    EXPECT_NE(parseRefused({"s.xml", "--shutter", "1,0"}).find("closes (0) before it opens (1)"), std::string::npos);
    EXPECT_NE(parseRefused({"s.xml", "--shutter", "0.5"}), "");      // two values
    EXPECT_NE(parseRefused({"s.xml", "--shutter", "0,1,2"}), "");
    EXPECT_NE(parseRefused({"s.xml", "--shutter", "a,b"}), "");
    EXPECT_NE(parseRefused({"s.xml", "--shutter", "0,inf"}), "");
    EXPECT_NE(describeSettings(cl).find("shutter: 0.25,0.75"), std::string::npos) << describeSettings(cl);
    EXPECT_EQ(parseOk({"compare", "s.xml", "--shutter", "0,0.5"}).render.shutter, glm::vec2(0.0f, 0.5f));
    RenderOptions backwards;
    backwards.shutter = glm::vec2(1.0f, 0.0f);
    EXPECT_THROW(shutterOf(backwards), std::invalid_argument);
}

TEST(CommandLineOptions, SweepTakesAListOfEstimators) {
    EXPECT_EQ(parseOk({"sweep", "s.xml", "--out", "d"}).sweep.estimators, std::vector<Estimator>{RenderOptions{}.estimator})
        << "by default only the renders' default: a sweep costs what it did";
    const CommandLine all = parseOk({"sweep", "s.xml", "--out", "d", "--estimators", "bounce,nee,mis-balance,mis"});
    EXPECT_EQ(all.sweep.estimators,
              (std::vector<Estimator>{Estimator::Bounce, Estimator::Nee, Estimator::MisBalance, Estimator::MisPower}));
    EXPECT_NE(describeSettings(all).find("estimators: bounce nee mis-balance mis\n"), std::string::npos);
    EXPECT_EQ(parseOk({"sweep", "s.xml", "--out", "d", "--estimator", "nee"}).sweep.estimators, std::vector<Estimator>{Estimator::Nee})
        << "render's spelling";
    EXPECT_NE(parseRefused({"sweep", "s.xml", "--out", "d", "--estimators", "bounce,path"}).find("path"), std::string::npos);
}

TEST(CommandLineOptions, WatchAndProgressiveAreRenderOptionsOfOneProcess) {
    const CommandLine cl = parseOk({"s.xml", "--watch", "--progressive", "4"});
    EXPECT_TRUE(cl.watch);
    EXPECT_EQ(cl.render.checkpoints, 4);
    EXPECT_FALSE(parseOk({"s.xml"}).watch);
    EXPECT_EQ(parseOk({"s.xml"}).render.checkpoints, 0);
    EXPECT_NE(parseRefused({"s.xml", "--progressive", "0"}), "");
    EXPECT_NE(parseRefused({"s.xml", "--watch", "--part", "1/2", "-o", "p.exr"}).find("a --part is one process's share"),
              std::string::npos);
    EXPECT_NE(parseRefused({"s.xml", "--progressive", "2", "--part", "1/2", "-o", "p.exr"}).find("--progressive"),
              std::string::npos);
    EXPECT_NE(parseRefused({"compare", "s.xml", "--watch"}), "");  // compare and sweep do not watch
    EXPECT_NE(parseRefused({"sweep", "s.xml", "--out", "d", "--progressive", "2"}), "");
}

TEST(CourseCommandLine, SplitMethodIsAcceptedWithANotice) {
    const CommandLine cl = parseOk({"s.xml", "-s", "objectMedian"});
    ASSERT_EQ(cl.notices.size(), 1u);
    EXPECT_NE(cl.notices[0].find("-s objectMedian ignored"), std::string::npos) << cl.notices[0];
    EXPECT_NE(cl.notices[0].find("binned-SAH"), std::string::npos) << cl.notices[0];
    EXPECT_EQ(parseOk({"s.xml", "--split", "SAH"}).notices.size(), 1u);
}

TEST(CourseCommandLine, PreviewWindowSizesAreAcceptedWithANotice) {
    const CommandLine cl = parseOk({"s.xml", "-x", "640", "-y", "480"});
    ASSERT_EQ(cl.notices.size(), 2u);
    EXPECT_NE(cl.notices[0].find("-x 640 ignored"), std::string::npos) << cl.notices[0];
    EXPECT_NE(cl.notices[1].find("-y 480 ignored"), std::string::npos) << cl.notices[1];
    EXPECT_NE(cl.notices[0].find("preview window"), std::string::npos) << cl.notices[0];
    EXPECT_EQ(cl.render.width, 250);  // the image keeps its size
    EXPECT_EQ(parseOk({"s.xml", "--winwidth", "10", "--winheight", "20"}).notices.size(), 2u);
    EXPECT_NE(parseRefused({"s.xml", "-x", "0"}), "");
    EXPECT_NE(parseRefused({"s.xml", "-y", "tall"}), "");
}

TEST(CourseCommandLine, HonouredFlagsGiveNoNotice) {
    EXPECT_TRUE(parseOk({"-i", "s.xml", "-n", "2", "-a", "2", "-v"}).notices.empty());
}

TEST(CourseCommandLine, QuestionMarkPrintsTheHelpAndExitsZero) {
    const Parsed p = parse({"-?"});
    EXPECT_FALSE(p.result.commandLine.has_value());
    EXPECT_EQ(p.result.exitCode, 0);
    for (const char* flag : {"-i", "-o", "-w", "-h", "-a", "-n", "-r", "-k", "-v", "-d", "-s", "-x", "-y", "-?"})
        EXPECT_NE(p.out.find(std::string(flag) + ","), std::string::npos) << flag << " missing from the help:\n" << p.out;
    EXPECT_NE(p.out.find("--aperture"), std::string::npos) << p.out;
}

// Issue 39: --version prints one line naming the program and its version, and exits 0.
TEST(CommandLineOptions, VersionPrintsTheVersionLineAndExitsZero) {
    const Parsed p = parse({"--version"});
    EXPECT_FALSE(p.result.commandLine.has_value());
    EXPECT_EQ(p.result.exitCode, 0);
    EXPECT_EQ(p.out.rfind("vkrt ", 0), 0u) << p.out;
    EXPECT_EQ(p.out.find('\n'), p.out.size() - 1) << "one line: " << p.out;
    EXPECT_NE(parse({"-?"}).out.find("--version"), std::string::npos);
}

// Issue 39: --exposure EV in stops, negative values included; anything but a finite number within
// +-20 stops is refused, naming the option and the value.
TEST(CommandLineOptions, ExposureTakesStopsAndRefusesWhatIsNotAFiniteSmallNumber) {
    EXPECT_EQ(parseOk({"s.xml"}).exposure, 0.0f);
    EXPECT_EQ(parseOk({"s.xml", "--exposure", "1.5"}).exposure, 1.5f);
    EXPECT_EQ(parseOk({"s.xml", "--exposure", "-1"}).exposure, -1.0f);
    EXPECT_EQ(parseOk({"s.xml", "--exposure=-20"}).exposure, -20.0f);
    for (const char* bad : {"21", "-20.5", "nan", "inf", "-inf", "1e39"})
        EXPECT_NE(parseRefused({"s.xml", "--exposure", bad}).find(std::string("--exposure: '") + bad + "': must be finite and within -20..20 stops"),
                  std::string::npos)
            << bad;
    for (const char* bad : {"bright", "1x", ""})
        EXPECT_NE(parseRefused({"s.xml", "--exposure", bad}).find(std::string("--exposure: '") + bad + "': expected a number of stops"),
                  std::string::npos)
            << bad;
    EXPECT_NE(describeSettings(parseOk({"s.xml", "--exposure", "-1"})).find("exposure: -1 stops (x0.5)"), std::string::npos);
}

// --input-limit sets the process-wide limits (input_limits.h) in every command that reads files,
// and each command line starts from the defaults again.
TEST(CommandLineOptions, InputLimitIsRepeatableInEveryCommandAndResetsPerParse) {
    parseOk({"s.xml", "--input-limit", "scene-bytes=1K", "--input-limit", "read-pixels=2M"});
    EXPECT_EQ(inputLimits().sceneFileBytes, 1024u);
    EXPECT_EQ(inputLimits().readPixels, 2u << 20);
    parseOk({"s.xml"});
    EXPECT_EQ(inputLimits().sceneFileBytes, 64u << 20);
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"compare", "s.xml"}, {"check", "s.xml", "i.png"}, {"sweep", "s.xml", "--out", "d"},
          {"convert", "s.xml", "-o", "t.json"}, {"merge", "a.exr", "-o", "m.png"}}) {
        std::vector<std::string> with = args;
        with.insert(with.end(), {"--input-limit", "mesh-bytes=5"});
        resetInputLimits();
        parseOk(with);
        EXPECT_EQ(inputLimits().meshFileBytes, 5u) << args[0];
    }
    resetInputLimits();
    EXPECT_NE(parseRefused({"s.xml", "--input-limit", "texels=5"}).find("no input limit 'texels'"), std::string::npos);
    EXPECT_NE(parseRefused({"s.xml", "--input-limit", "scene-bytes=0"}).find("would refuse every file"), std::string::npos);
}

TEST(CourseCommandLine, CourseFlagsWorkInCompareAndSweep) {
    const CommandLine compare = parseOk({"compare", "s.xml", "-n", "2", "-a", "2"});
    EXPECT_EQ(compare.command, Command::Compare);
    EXPECT_EQ(compare.render.threads, 2);
    EXPECT_EQ(compare.render.height, 125);
    const CommandLine sweep = parseOk({"sweep", "s.xml", "--out", "d", "-h", "100", "-a", "2", "-v"});
    EXPECT_EQ(sweep.render.width, 200);
    EXPECT_TRUE(sweep.verbose);
    EXPECT_EQ(parseOk({"sweep", "s.xml", "--out", "d", "-d", "1", "--aperture", "0.1"}).focusDistance, 1.0f);
}

// Issue 22: `-o ""` used to write <scene>.png without a word; an explicit empty path is refused,
// while no -o at all keeps the default.
TEST(OutputPath, AnExplicitEmptyOutputIsRefused) {
    EXPECT_NE(parseRefused({"s.xml", "-o", ""}).find("the output path is empty"), std::string::npos);
    EXPECT_EQ(parseOk({"s.xml"}).outputPath, "s.png");
}

// Issue 22: `-i a.xml b.xml` rendered b.xml and dropped a.xml silently.
TEST(OutputPath, TwoScenesAreRefusedNamingBoth) {
    const std::string message = parseRefused({"-i", "a.xml", "b.xml"});
    EXPECT_NE(message.find("2 scene files given"), std::string::npos) << message;
    EXPECT_NE(message.find("'a.xml'"), std::string::npos) << message;
    EXPECT_NE(message.find("'b.xml'"), std::string::npos) << message;
    EXPECT_EQ(parseOk({"-i", "a.xml"}).scenePath, "a.xml");
}

// Issue 36: --target-error / --time turn adaptive sampling on with sobol2, and what cannot go with
// it is refused naming the option.
TEST(AdaptiveCommandLine, TargetErrorSelectsSobol2AndTheBounds) {
    const CommandLine cl = parseOk({"s.xml", "--target-error", "0.01", "--max-rpp", "512"});
    EXPECT_TRUE(cl.adaptiveSampling);
    EXPECT_EQ(cl.render.sampler, SamplerKind::Sobol2);
    EXPECT_EQ(cl.adaptive.targetError, 0.01);
    EXPECT_EQ(cl.adaptive.maxRpp, 512u);
    EXPECT_EQ(cl.render.samplesPerPixel, 512);
    EXPECT_EQ(parseOk({"s.xml", "--time", "2", "--sampler", "random"}).render.sampler, SamplerKind::Random);
    EXPECT_FALSE(parseOk({"s.xml"}).adaptiveSampling);
}

TEST(AdaptiveCommandLine, ConflictsAndBadValuesAreRefused) {
    const auto refusedWith = [](const std::vector<std::string>& args, const std::string& text) {
        const std::string message = parseRefused(args);
        EXPECT_NE(message.find(text), std::string::npos) << message;
    };
    refusedWith({"s.xml", "--target-error", "0"}, "--target-error 0: must be a relative RMSE of at least 0.0001");
    refusedWith({"s.xml", "--target-error", "0.00001"}, "float per-pixel sums cannot resolve less");
    refusedWith({"s.xml", "--time", "-3"}, "--time -3: must be a number of seconds above 0");
    refusedWith({"s.xml", "--target-error", "0.01", "--min-rpp", "7"}, "--min-rpp 7: must be an even number");
    refusedWith({"s.xml", "--target-error", "0.01", "-r", "64"}, "bound it with --min-rpp and --max-rpp");
    refusedWith({"s.xml", "--target-error", "0.01", "--sampler", "jittered"}, "adaptive sampling needs sobol2");
    refusedWith({"s.xml", "--target-error", "0.01", "--part", "1/2", "-o", "p.exr"}, "render it in one process");
    refusedWith({"s.xml", "--max-rpp", "64"}, "belongs to adaptive sampling");
    refusedWith({"s.xml", "--time", "0"}, "--time 0: must be a number of seconds above 0");
    refusedWith({"s.xml", "--watch", "--time", "5", "--sample-map", "n.png"}, "--watch writes the image only");
    EXPECT_TRUE(parseOk({"s.xml", "--watch", "--target-error", "0.01"}).adaptiveSampling);  // --watch shows the rounds
}

}  // namespace
}  // namespace vkrt
