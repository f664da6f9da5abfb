// --up x,y,z (issue 39): the rendered camera's up vector from the command line. The parser refuses
// what can orient no camera (zero, not finite, not three numbers); once the scene is loaded
// (render_steps.h: loadWithWarnings) one parallel to the camera's gaze is an error naming the flag,
// the camera and its gaze; otherwise it replaces the scene's and turns the image as stated.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "command_line.h"
#include "cpu_renderer.h"
#include "render_steps.h"

namespace vkrt {
namespace {

struct Parsed {
    ParseResult result;
    std::string err;  // what the parser printed
};

Parsed run(std::vector<std::string> args) {
    args.insert(args.begin(), "vkrt");
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    testing::internal::CaptureStderr();
    Parsed p{parseCommandLine(static_cast<int>(argv.size()), argv.data()), ""};
    p.err = testing::internal::GetCapturedStderr();
    return p;
}

ParseResult parse(const std::vector<std::string>& args) {
    Parsed p = run(args);
    EXPECT_TRUE(p.result.commandLine.has_value()) << p.err;
    return p.result;
}

// A usage error (exit code 2); returns what the parser printed.
std::string refusal(const std::vector<std::string>& args) {
    const Parsed p = run(args);
    EXPECT_FALSE(p.result.commandLine.has_value()) << "accepted";
    EXPECT_EQ(p.result.exitCode, 2);
    return p.err;
}

// A grey floor seen from straight above, a red marker at world +x; the side of the image the
// marker lands on (tests/cpu/camera_up_test.cpp has the scene built in code).
class UpFlag : public ::testing::Test {
protected:
    void SetUp() override {
        dir = std::filesystem::temp_directory_path() / ("vkrt_up_flag_" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir);
        scenePath = (dir / "from_above.xml").string();
        std::ofstream(scenePath) << "<scene bgColor=\"0 0 0\">\n"
                                    "<camera name=\"top\"><position>0 5 0</position><viewDir>0 -1 0</viewDir><imagePlaneWidth>1</imagePlaneWidth></camera>\n"
                                    "<light type=\"point\"><position>0 10 0</position><intensity>1 1 1</intensity></light>\n"
                                    "<shader name=\"grey\" type=\"Lambertian\"><diffuse>0.5 0.5 0.5</diffuse></shader>\n"
                                    "<shader name=\"red\" type=\"Lambertian\"><diffuse>1 0 0</diffuse></shader>\n"
                                    "<shape type=\"box\"><shader ref=\"grey\"/><minPt>-3 -1 -3</minPt><maxPt>3 0 3</maxPt></shape>\n"
                                    "<shape type=\"sphere\"><shader ref=\"red\"/><center>1.2 0.3 0</center><radius>0.4</radius></shape>\n"
                                    "</scene>\n";
    }
    void TearDown() override { std::filesystem::remove_all(dir); }

    std::string markerSide(const std::vector<std::string>& flags) const {
        std::vector<std::string> args = {scenePath, "-w", "32", "-h", "32", "-r", "1", "--device", "cpu"};
        args.insert(args.end(), flags.begin(), flags.end());
        ParseResult p = parse(args);
        if (!p.commandLine) return "refused";
        CommandLine& cl = *p.commandLine;
        const Scene scene = loadWithWarnings(cl);
        const Image image = renderCpu(scene, prepareCpuScene(scene), cl.render);
        double x = 0.0, y = 0.0;
        int count = 0;
        for (int j = 0; j < image.height; ++j)
            for (int i = 0; i < image.width; ++i)
                if (image.at(i, j).r > 0.2f && image.at(i, j).g < 0.05f) {
                    x += i + 0.5 - image.width / 2.0;
                    y += j + 0.5 - image.height / 2.0;
                    ++count;
                }
        if (count == 0) return "nowhere";
        if (std::abs(y) >= std::abs(x)) return y < 0.0 ? "top" : "bottom";
        return x < 0.0 ? "left" : "right";
    }

    std::filesystem::path dir;
    std::string scenePath;
};

TEST(UpFlagParsing, TakesThreeNumbersAndRefusesWhatOrientsNoCamera) {
    ParseResult p = parse({"s.xml", "--up", "0,0,-1"});
    ASSERT_TRUE(p.commandLine && p.commandLine->up);
    EXPECT_EQ(*p.commandLine->up, glm::vec3(0.0f, 0.0f, -1.0f));
    p = parse({"s.xml", "--up", "1 2 3"});  // as --bg, spaces too
    ASSERT_TRUE(p.commandLine && p.commandLine->up);
    EXPECT_EQ(*p.commandLine->up, glm::vec3(1.0f, 2.0f, 3.0f));
    EXPECT_FALSE(parse({"s.xml"}).commandLine->up.has_value());
    EXPECT_NE(describeSettings(*parse({"s.xml", "--up", "0,0,-1"}).commandLine).find("up: 0,0,-1\n"), std::string::npos);

    EXPECT_NE(refusal({"s.xml", "--up", "0,0,0"}).find("--up: '0,0,0': the up vector has zero length"), std::string::npos);
    EXPECT_NE(refusal({"s.xml", "--up", "1,nan,0"}).find("expected three numbers x,y,z, got '1,nan,0'"), std::string::npos);
    EXPECT_NE(refusal({"s.xml", "--up", "1e39,0,0"}).find("'1e39,0,0': each number must be finite and within float"), std::string::npos);
    EXPECT_NE(refusal({"s.xml", "--up", "0,1"}).find("expected three numbers x,y,z, got '0,1'"), std::string::npos);
    EXPECT_NE(refusal({"s.xml", "--up", "0,1,0,4"}).find("expected three numbers"), std::string::npos);
}

TEST_F(UpFlag, TurnsTheImageOfAStraightDownCamera) {
    EXPECT_EQ(markerSide({}), "top");  // the rule: world +x at the top
    EXPECT_EQ(markerSide({"--up", "0,0,-1"}), "right");
    EXPECT_EQ(markerSide({"--up", "0,0,1"}), "left");
    EXPECT_EQ(markerSide({"--up", "-1,0,0"}), "bottom");
}

TEST_F(UpFlag, ReplacesTheScenesUpVector) {
    std::string text;
    {
        std::ifstream in(scenePath);
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    const std::string camera = "<imagePlaneWidth>1</imagePlaneWidth>";
    text.replace(text.find(camera), camera.size(), camera + "<up>0 0 -1</up>");
    std::ofstream(scenePath) << text;
    EXPECT_EQ(markerSide({}), "right");
    EXPECT_EQ(markerSide({"--up", "0,0,1"}), "left");
}

TEST_F(UpFlag, ParallelToTheGazeIsAnErrorNamingTheFlagAndTheCamera) {
    ParseResult p = parse({scenePath, "--up", "0,-2,0"});
    ASSERT_TRUE(p.commandLine.has_value());
    try {
        loadWithWarnings(*p.commandLine);
        ADD_FAILURE() << "accepted";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("--up 0 -2 0: up vector is parallel to the view direction"), std::string::npos) << what;
        EXPECT_NE(what.find("camera 0 of " + scenePath + " looks along 0 -1 0"), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace vkrt
