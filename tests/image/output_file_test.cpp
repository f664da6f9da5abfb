// Writing output files (output_file.h, issue 38 item 7): -o through a symbolic link writes the
// file the link points to and keeps the link; SIGTERM and SIGHUP during a write leave no
// ".NAME.partial-PID" temporary behind.
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "image.h"
#include "output_file.h"
#include "test_paths.h"

namespace vkrt::test {
namespace {

namespace fs = std::filesystem;

// writeAtomically keeps a disposition someone else set; under `nohup` SIGHUP is ignored. The
// tests restore the defaults before the first write, which is what a plain shell gives vkrt.
const bool kDefaultDispositions = [] {
    std::signal(SIGTERM, SIG_DFL);
    std::signal(SIGHUP, SIG_DFL);
    return true;
}();

TEST(OutputFile, WritingThroughASymlinkKeepsTheLink) {
    const fs::path dir = freshArtifactDir("output_symlink");
    fs::create_directories(dir / "real");
    std::ofstream(dir / "real" / "out.png") << "old";
    fs::create_symlink("real/out.png", dir / "link.png");        // relative, as `ln -s` makes them
    fs::create_symlink(dir / "link.png", dir / "link2.png");     // a chain
    Image image(3, 2);
    image.at(2, 1) = glm::vec3(1.0f, 0.5f, 0.0f);
    writeImage(image, (dir / "link2.png").string());
    EXPECT_TRUE(fs::is_symlink(dir / "link.png"));
    EXPECT_TRUE(fs::is_symlink(dir / "link2.png"));
    const Image back = readImage((dir / "real" / "out.png").string());
    ASSERT_EQ(back.width, 3);
    EXPECT_EQ(back.at(2, 1).x, 1.0f);
    for (const auto& entry : fs::directory_iterator(dir / "real"))
        EXPECT_EQ(entry.path().filename(), "out.png") << "left behind: " << entry.path();
}

// A child process starts a write and is killed by `signal` in the middle of it: it must die by
// that signal (the default action still happens) and its temporary must be gone.
void expectNoTemporaryAfter(int signal) {
    const fs::path dir = freshArtifactDir("output_signal_" + std::to_string(signal));
    const std::string target = (dir / "out.exr").string();
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        writeAtomically(target, [&](const std::string& temporary) {
            std::ofstream(temporary) << "half an image";
            ::kill(::getpid(), signal);
            ::sleep(10);  // the handler ends the process long before
            ::_exit(7);
        });
        ::_exit(0);  // not reached when the signal ends the write
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the child exited with " << WEXITSTATUS(status);
    EXPECT_EQ(WTERMSIG(status), signal);
    EXPECT_FALSE(fs::exists(target));
    for (const auto& entry : fs::directory_iterator(dir)) ADD_FAILURE() << "left behind: " << entry.path();
}

TEST(OutputFile, SigtermDuringAWriteLeavesNoTemporary) { expectNoTemporaryAfter(SIGTERM); }
TEST(OutputFile, SighupDuringAWriteLeavesNoTemporary) { expectNoTemporaryAfter(SIGHUP); }

}  // namespace
}  // namespace vkrt::test
