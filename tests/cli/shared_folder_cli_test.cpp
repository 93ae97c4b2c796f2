// SPDX-License-Identifier: Apache-2.0
// Outputs in a folder other users can write (issue #34, docs/robustness.md): a link planted
// at an output's name is replaced, never written through; an output that names a device, a
// FIFO, a socket or a directory is refused and left as it is; the cache's lock is never
// taken through a link. A file outside the folder ("victim") must come through unchanged.
#include "cli_fixture.h"

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

namespace {

class SharedFolder : public Cli {
protected:
    void SetUp() override
    {
        Cli::SetUp();
        outside = dir.parent_path() / (dir.filename().string() + "_outside");
        fs::remove_all(outside);
        fs::create_directories(outside);
        spit(outside / "victim.exr", "the victim's own file");
    }
    void TearDown() override
    {
        fs::remove_all(outside);
        Cli::TearDown();
    }
    std::string victim() const { return slurp(outside / "victim.exr"); }

    fs::path outside;
    const std::string run = "stucco.png --pyramid:size=32x32:iterations=1 ";
};

} // namespace

// A link at the output's name (to another user's file, or dangling to a name outside the
// folder) is replaced by the output; the file it pointed to is untouched, none is created.
TEST_F(SharedFolder, LinksAtTheOutputsNameAreReplacedNotFollowed)
{
    fs::create_symlink(outside / "victim.exr", dir / "out.exr");
    fs::create_symlink(outside / "created.exr", dir / "dangling.exr");
    spit(outside / "victim.texsyn", "the victim's recipe");
    fs::create_symlink(outside / "victim.texsyn", dir / "recipe.texsyn");
    const CliRun r = texsyn(run + "-o out.exr -o dangling.exr --recipe recipe.texsyn");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(victim(), "the victim's own file");
    EXPECT_EQ(slurp(outside / "victim.texsyn"), "the victim's recipe");
    EXPECT_FALSE(fs::exists(outside / "created.exr"));
    for (const char* name : { "out.exr", "dangling.exr", "recipe.texsyn" }) {
        EXPECT_FALSE(fs::is_symlink(dir / name)) << name;
        EXPECT_TRUE(fs::is_regular_file(dir / name)) << name;
    }
}

// A device, a FIFO, a socket or a directory at an output's name is refused before the run,
// with one line naming it, and is left as it was.
TEST_F(SharedFolder, OutputsThatAreNotRegularFilesAreRefused)
{
    ASSERT_EQ(::mkfifo((dir / "fifo.exr").c_str(), 0644), 0);
    expect_failure(run + "-o fifo.exr",
        "texsyn ERROR: -o fifo.exr : exists and is not a regular file (a device, FIFO or "
        "socket); texsyn does not replace it",
        { "stucco.png", "fifo.exr" });
    EXPECT_TRUE(fs::is_fifo(dir / "fifo.exr"));
    expect_failure(run + "-o out.png --recipe fifo.exr",
        "texsyn ERROR: --recipe fifo.exr : exists and is not a regular file (a device, FIFO or "
        "socket); texsyn does not replace it",
        { "stucco.png", "fifo.exr" });
    expect_failure("stucco.png --patch:size=32x32:map=fifo.exr -o out.png",
        "texsyn ERROR: map= fifo.exr : exists and is not a regular file (a device, FIFO "
        "or socket); texsyn does not replace it",
        { "stucco.png", "fifo.exr" });

    const int sock = ::socket(AF_UNIX, SOCK_STREAM, 0);
    ASSERT_GE(sock, 0);
    sockaddr_un addr {};
    addr.sun_family = AF_UNIX;
    const std::string sock_path = (dir / "sock.exr").string();
    ASSERT_LT(sock_path.size(), sizeof(addr.sun_path));
    std::snprintf(addr.sun_path, sizeof(addr.sun_path), "%s", sock_path.c_str());
    ASSERT_EQ(::bind(sock, reinterpret_cast<const sockaddr*>(&addr), sizeof(addr)), 0);
    expect_failure(run + "-o sock.exr",
        "texsyn ERROR: -o sock.exr : exists and is not a regular file (a device, FIFO or "
        "socket); texsyn does not replace it",
        { "stucco.png", "fifo.exr", "sock.exr" });
    EXPECT_TRUE(fs::is_socket(dir / "sock.exr"));
    ::close(sock);

    // A character device (root only can make one): /dev/null linked in is a link, which an
    // output replaces; the device itself named directly is refused.
    expect_failure(run + "-o /dev/null",
        "texsyn ERROR: -o /dev/null : exists and is not a regular file (a device, FIFO or "
        "socket); texsyn does not replace it",
        { "stucco.png", "fifo.exr", "sock.exr" });
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

// The analysis writer refuses a FIFO too (Python's Analysis.save, given /dev/full, used to
// replace the machine's /dev/full with a regular file: tests/python/test_errors.py).
TEST_F(SharedFolder, AnalysesAreNotWrittenOverFifos)
{
    ASSERT_EQ(::mkfifo((dir / "a.tsa").c_str(), 0644), 0);
    expect_failure("stucco.png --analyze -o a.tsa",
        "texsyn ERROR: -o a.tsa : exists and is not a regular file (a device, FIFO or socket); "
        "texsyn does not replace it",
        { "stucco.png", "a.tsa" });
    EXPECT_TRUE(fs::is_fifo(dir / "a.tsa"));
}

// The result cache's lock is not taken through a link planted at its name (a dangling one
// used to create its target outside the cache): the run synthesizes without it, with one
// warning, and creates nothing outside the folder.
TEST_F(SharedFolder, TheCacheLockIsNeverTakenThroughALink)
{
    ASSERT_EQ(texsyn(run + "--recipe r.texsyn -o first.exr").status, 0);
    // A first run through the cache names the entry and its lock (KEY.exr, KEY.lock).
    const std::string open_recipe = "TEXSYN_CACHE=cache oiiotool r.texsyn -o ";
    ASSERT_EQ(shell(open_recipe + "second.exr").status, 0);
    std::string key;
    for (auto& e : fs::directory_iterator(dir / "cache"))
        if (e.path().extension() == ".lock")
            key = e.path().stem().string();
    ASSERT_EQ(key.size(), 32u);
    fs::remove(dir / "cache" / (key + ".exr"));
    fs::remove(dir / "cache" / (key + ".lock"));
    fs::create_symlink(outside / "created.lock", dir / "cache" / (key + ".lock"));
    const CliRun r = shell(open_recipe + "third.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find(key + ".lock: cannot lock"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(outside / "created.lock"));
    EXPECT_TRUE(fs::is_symlink(dir / "cache" / (key + ".lock")));
    EXPECT_TRUE(fs::is_regular_file(dir / "cache" / (key + ".exr")));
}
