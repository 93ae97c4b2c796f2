// SPDX-License-Identifier: Apache-2.0
// The on-disk result cache ($TEXSYN_CACHE, docs/cache.md), through stock oiiotool and
// iinfo with the plugin, and through recipe_images() in one process: hits give the
// uncached pixels bit for bit, any change of an input misses, a damaged entry is replaced,
// concurrent processes and threads synthesize once, and an unusable folder never fails a
// render. Syntheses are counted by the TEXSYN_CACHE_VERBOSE lines ("miss KEY,
// synthesizing").
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include <texsyn/recipe.h>

namespace fs = std::filesystem;

namespace {

struct ToolRun {
    int status = -1;
    std::string out; // stdout and stderr together
};

size_t count(const std::string& text, const std::string& what)
{
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

std::string slurp(const fs::path& p)
{
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

class ResultCache : public ::testing::Test {
protected:
    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = fs::temp_directory_path() / (std::string("texsyn_cache_") + info->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
        fs::copy_file(std::string(TEXSYN_TEST_DATA) + "/stucco_yellow.png", dir / "s.png");
        write("r.texsyn", R"({ "sample": "s.png", "size": "48x40", "iterations": 1, "seed": 3 })");
    }
    void TearDown() override
    {
        ::unsetenv("TEXSYN_CACHE");
        fs::remove_all(dir);
    }

    // Runs `cmd` in the test folder with the plugin visible, $OCIO unset, the cache
    // folder `cache` (relative to the test folder; "" = no cache) and its verbose lines.
    ToolRun sh(const std::string& cmd, const std::string& cache = "cache")
    {
        const std::string full = "cd '" + dir.string() + "' && unset OCIO TEXSYN_CACHE && export "
            + "OIIO_LIBRARY_PATH='" + TEXSYN_PLUGIN_DIR + "' TEXSYN_CACHE_VERBOSE=1 "
            + (cache.empty() ? "" : "TEXSYN_CACHE='" + cache + "'") + " && (" + cmd
            + ") > out.txt 2>&1";
        const int rc = std::system(full.c_str());
        ToolRun r;
        r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : 128 + WTERMSIG(rc);
        r.out = slurp(dir / "out.txt");
        return r;
    }

    void write(const std::string& name, const std::string& text)
    {
        std::ofstream(dir / name) << text;
    }

    // The entries in the cache folder (KEY.exr), sorted.
    std::vector<std::string> entries(const std::string& cache = "cache")
    {
        std::vector<std::string> names;
        std::error_code ec;
        for (const auto& e : fs::directory_iterator(dir / cache, ec))
            if (e.path().extension() == ".exr")
                names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

    // The uncached result of NAME (every subimage, float), and `iinfo -v -a NAME`, as the
    // files PLAIN.exr and PLAIN.txt; made on the first call for NAME.
    std::string plain(const std::string& name)
    {
        auto known = std::find(plains.begin(), plains.end(), name);
        if (known == plains.end())
            known = plains.insert(known, name);
        const std::string file = "plain" + std::to_string(known - plains.begin());
        if (!fs::exists(dir / (file + ".exr"))) {
            const ToolRun r = sh("oiiotool -a '" + name + "' -d float -o " + file
                    + ".exr && iinfo -v -a '" + name + "' > " + file + ".txt",
                "");
            EXPECT_EQ(r.status, 0) << r.out;
        }
        return file;
    }

    // How many times `oiiotool -a NAME -d float -o cached.exr` synthesizes through the
    // cache `cache` (0: it reads the cache).
    size_t syntheses(const std::string& name, const std::string& cache = "cache")
    {
        const ToolRun r = sh("oiiotool -a '" + name + "' -d float -o cached.exr", cache);
        EXPECT_EQ(r.status, 0) << r.out;
        return count(r.out, ", synthesizing");
    }

    // `oiiotool -a NAME -d float -o cached.exr` through the cache `cache` synthesizes
    // `times` times (0: reads the cache) and gives the pixels (every subimage, bit for bit)
    // and the metadata that NAME gives with no cache. Returns what the tools printed.
    std::string expect_uncached_result(
        const std::string& name, size_t times, const std::string& cache = "cache")
    {
        const std::string reference = plain(name);
        const ToolRun r = sh("oiiotool -a '" + name + "' -d float -o cached.exr && iinfo -v -a '"
                + name + "' > cached.txt && idiff -a -fail 0 " + reference + ".exr cached.exr",
            cache);
        EXPECT_EQ(r.status, 0) << r.out;
        EXPECT_EQ(count(r.out, ", synthesizing"), times) << r.out;
        EXPECT_EQ(slurp(dir / "cached.txt"), slurp(dir / (reference + ".txt")));
        return r.out;
    }

    // A child process that holds an exclusive flock() on `lock` until it is killed (the
    // kernel then frees the lock); -1 if it could not take it.
    static pid_t hold_lock(const std::string& lock)
    {
        int ready[2];
        if (::pipe(ready) != 0)
            return -1;
        const pid_t holder = ::fork();
        if (holder == 0) { // only async-signal-safe calls here
            const int fd = ::open(lock.c_str(), O_RDWR);
            const char locked = fd >= 0 && ::flock(fd, LOCK_EX) == 0;
            if (::write(ready[1], &locked, 1) != 1 || !locked)
                ::_exit(1);
            for (;;)
                ::pause();
        }
        char locked = 0;
        const bool read = ::read(ready[0], &locked, 1) == 1;
        ::close(ready[0]);
        ::close(ready[1]);
        if (holder > 0 && (!read || !locked)) {
            ::waitpid(holder, nullptr, 0);
            return -1;
        }
        return holder;
    }

    fs::path dir;
    std::vector<std::string> plains; // the names plain() has made, in order
};

} // namespace

TEST_F(ResultCache, ASecondOpenReadsTheEntry)
{
    expect_uncached_result("r.texsyn", 1);
    ASSERT_EQ(entries().size(), 1u);
    const std::string key = entries()[0].substr(0, 32);
    EXPECT_TRUE(fs::exists(dir / "cache" / (key + ".lock")));
    expect_uncached_result("r.texsyn", 0);
    // The entry is an ordinary float OpenEXR that stock tools read.
    ToolRun r = sh("iinfo -v cache/" + key + ".exr");
    EXPECT_NE(r.out.find("48 x   40, 3 channel, float openexr"), std::string::npos) << r.out;
    // The same recipe by REST arguments, and its text in another folder with a copy of
    // the sample: the same key (files are known by their bytes).
    fs::create_directories(dir / "elsewhere");
    fs::copy_file(dir / "s.png", dir / "elsewhere" / "s.png");
    fs::copy_file(dir / "r.texsyn", dir / "elsewhere" / "r.texsyn");
    r = sh("oiiotool elsewhere/r.texsyn -o a.exr && cd elsewhere && oiiotool "
           "'s.png.texsyn?size=48x40&iterations=1&seed=3' -o b.exr",
        (dir / "cache").string());
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_EQ(count(r.out, "texsyn cache: hit " + key), 2u) << r.out;
    EXPECT_EQ(entries().size(), 1u);
}

TEST_F(ResultCache, AChangedInputMisses)
{
    EXPECT_EQ(syntheses("r.texsyn"), 1u);
    write("seed4.texsyn", R"({ "sample": "s.png", "size": "48x40", "iterations": 1, "seed": 4 })");
    EXPECT_EQ(syntheses("seed4.texsyn"), 1u);
    // The sample's bytes, changed in place.
    ASSERT_EQ(sh("oiiotool s.png --flip -o s.png", "").status, 0);
    EXPECT_EQ(syntheses("r.texsyn"), 1u);
    // The same text in another folder, whose sample differs.
    fs::create_directories(dir / "other");
    fs::copy_file(std::string(TEXSYN_TEST_DATA) + "/rust.png", dir / "other" / "s.png");
    fs::copy_file(dir / "r.texsyn", dir / "other" / "r.texsyn");
    EXPECT_EQ(syntheses("other/r.texsyn"), 1u);
    // A file an option reads (the cascade's palette=).
    fs::copy_file(std::string(TEXSYN_TEST_DATA) + "/rust.png", dir / "pal.png");
    write("c.texsyn", R"({ "method": "cascade", "preset": "stone", "size": "32x32",
                           "palette": "pal.png" })");
    EXPECT_EQ(syntheses("c.texsyn"), 1u);
    EXPECT_EQ(syntheses("c.texsyn"), 0u);
    ASSERT_EQ(sh("oiiotool pal.png --flop -o pal.png", "").status, 0);
    EXPECT_EQ(syntheses("c.texsyn"), 1u);
    // The colour config: a copy of the bundled one is the bundled one; an edit is not.
    fs::copy_file(std::string(TEXSYN_BUNDLED_OCIO_CONFIG), dir / "studio.ocio");
    write("k.texsyn", R"({ "sample": "s.png", "size": "48x40", "iterations": 1, "seed": 3,
                           "colorconfig": "studio.ocio" })");
    EXPECT_EQ(syntheses("k.texsyn"), 0u);
    std::ofstream(dir / "studio.ocio", std::ios::app) << "# edited\n";
    EXPECT_EQ(syntheses("k.texsyn"), 1u);
    EXPECT_EQ(entries().size(), 7u);
}

TEST_F(ResultCache, ARecipeReadAsASampleIsKnownByItsOwnInputs)
{
    write(
        "outer.texsyn", R"({ "sample": "r.texsyn", "size": "32x32", "iterations": 1, "seed": 1 })");
    EXPECT_EQ(syntheses("outer.texsyn"), 2u); // the outer and the inner recipe
    expect_uncached_result("outer.texsyn", 0);
    ASSERT_EQ(sh("oiiotool s.png --flip -o s.png", "").status, 0);
    EXPECT_EQ(syntheses("outer.texsyn"), 2u);
    EXPECT_EQ(entries().size(), 4u);
}

TEST_F(ResultCache, SolidAndSubbandRecipesAreCachedWhole)
{
    const std::string solid = "s.png.texsyn?method=solid&size=16x16x6&iterations=1";
    expect_uncached_result(solid, 1);
    expect_uncached_result(solid, 0);
    const std::string bands = "s.png.texsyn?size=32x32&iterations=1&subbands=1";
    expect_uncached_result(bands, 1);
    expect_uncached_result(bands, 0);
    EXPECT_EQ(entries().size(), 2u);
}

TEST_F(ResultCache, ADamagedEntryIsIgnoredAndReplaced)
{
    expect_uncached_result("r.texsyn", 1);
    ASSERT_EQ(entries().size(), 1u);
    const fs::path entry = dir / "cache" / entries()[0];
    const std::string good = slurp(entry);
    const std::vector<std::pair<std::string, std::string>> damages = {
        { "truncated", good.substr(0, good.size() / 2) },
        { "empty", "" },
        { "not an image", "hello" },
        { "a flipped byte",
            [&] {
                std::string bad = good;
                bad[bad.size() - 100] ^= 0x40; // in the pixel data, at the end of the file
                return bad;
            }() },
    };
    for (const auto& [what, bytes] : damages) {
        std::ofstream(entry, std::ios::binary | std::ios::trunc) << bytes;
        ToolRun r = sh("oiiotool r.texsyn -d float -o a.exr && idiff -fail 0 plain0.exr a.exr");
        EXPECT_EQ(r.status, 0) << what << ": " << r.out;
        EXPECT_EQ(count(r.out, ": ignoring a damaged entry ("), 1u) << what << ": " << r.out;
        EXPECT_EQ(count(r.out, ", synthesizing"), 1u) << what << ": " << r.out;
        EXPECT_NE(slurp(entry), bytes) << what; // replaced
        r = sh("oiiotool r.texsyn -d float -o b.exr && idiff -fail 0 plain0.exr b.exr");
        EXPECT_EQ(r.status, 0) << what << ": " << r.out;
        EXPECT_EQ(count(r.out, "texsyn cache: hit"), 1u) << what << ": " << r.out;
    }
}

// Four stock oiiotool processes started together on one recipe: one synthesizes, the
// others wait for its entry and read it. The entry's lock is held first by another process:
// while it lives none of the four can finish; when it is killed (SIGKILL, no clean-up) the
// kernel frees its lock and they go on.
TEST_F(ResultCache, ConcurrentProcessesSynthesizeOnce)
{
    expect_uncached_result("r.texsyn", 1);
    ASSERT_EQ(entries().size(), 1u);
    const std::string key = entries()[0].substr(0, 32);
    fs::remove(dir / "cache" / entries()[0]);
    const pid_t holder = hold_lock((dir / "cache" / (key + ".lock")).string());
    ASSERT_GT(holder, 0);
    ToolRun r;
    std::thread processes([&] {
        r = sh("for i in 1 2 3 4; do (oiiotool r.texsyn -d float -o out$i.exr > log$i.txt 2>&1) "
               "& done; wait; cat log1.txt log2.txt log3.txt log4.txt");
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    for (int i = 1; i <= 4; ++i)
        EXPECT_FALSE(fs::exists(dir / ("out" + std::to_string(i) + ".exr")));
    ::kill(holder, SIGKILL);
    ::waitpid(holder, nullptr, 0);
    processes.join();
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_EQ(count(r.out, "texsyn cache: miss " + key + ", synthesizing"), 1u) << r.out;
    EXPECT_EQ(count(r.out, "texsyn cache: stored " + key), 1u) << r.out;
    EXPECT_EQ(count(r.out, "texsyn cache: hit " + key), 3u) << r.out;
    for (int i = 1; i <= 4; ++i)
        EXPECT_EQ(sh("idiff -fail 0 plain0.exr out" + std::to_string(i) + ".exr").status, 0);
    EXPECT_EQ(entries().size(), 1u);
}

// Threads of one process that ask for one result at once synthesize it once.
TEST_F(ResultCache, ConcurrentThreadsSynthesizeOnce)
{
    texsyn::Recipe recipe;
    std::string error;
    ASSERT_TRUE(texsyn::recipe_from_filename((dir / "r.texsyn").string(), recipe, error)) << error;
    OIIO::ImageBuf plain;
    ASSERT_TRUE(texsyn::run_recipe(recipe, plain, nullptr, error)) << error;
    ::setenv("TEXSYN_CACHE", (dir / "cache").c_str(), 1);
    ::setenv("TEXSYN_CACHE_VERBOSE", "1", 1);
    ::testing::internal::CaptureStderr();
    std::vector<std::vector<OIIO::ImageBuf>> got(4);
    std::vector<std::thread> threads;
    for (size_t t = 0; t < got.size(); ++t)
        threads.emplace_back([&, t] {
            std::string err;
            EXPECT_TRUE(texsyn::recipe_images(recipe, got[t], err)) << err;
        });
    for (std::thread& t : threads)
        t.join();
    const std::string log = ::testing::internal::GetCapturedStderr();
    ::unsetenv("TEXSYN_CACHE_VERBOSE");
    EXPECT_EQ(count(log, ", synthesizing"), 1u) << log;
    EXPECT_EQ(count(log, "texsyn cache: hit"), 3u) << log;
    for (const auto& images : got) {
        ASSERT_EQ(images.size(), 1u);
        EXPECT_EQ(OIIO::ImageBufAlgo::computePixelHashSHA1(images[0]),
            OIIO::ImageBufAlgo::computePixelHashSHA1(plain));
    }
}

TEST_F(ResultCache, AnUnusableFolderStillRenders)
{
    for (const std::string cache : { "s.png", "s.png/cache" }) {
        const std::string out = expect_uncached_result("r.texsyn", 0, cache);
        EXPECT_EQ(
            count(out, "texsyn WARNING: TEXSYN_CACHE: " + cache + ": cannot create the folder"), 1u)
            << out;
    }
    if (::geteuid() == 0)
        return;                                            // root writes into any folder
    ASSERT_EQ(sh("oiiotool r.texsyn -o a.exr").status, 0); // one entry
    fs::permissions(dir / "cache", fs::perms::owner_write, fs::perm_options::remove);
    ToolRun r = sh("oiiotool r.texsyn -o b.exr && oiiotool 'r.texsyn?seed=9' -o c.exr");
    fs::permissions(dir / "cache", fs::perms::owner_write, fs::perm_options::add);
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("not writable: results are read from it, not stored"), std::string::npos)
        << r.out;
    EXPECT_EQ(count(r.out, "texsyn cache: hit"), 1u) << r.out;
    EXPECT_EQ(entries().size(), 1u);
}

// Issue #34: the checksum finds damage, not forgery. An entry of seed 8 renamed to seed 7's
// key with its key attribute rewritten is served without a site secret (anyone who can
// write the folder can do this: docs/cache.md); with $TEXSYN_CACHE_SECRET it is ignored,
// and so is an authenticated entry whose key was rewritten.
TEST_F(ResultCache, ForgedEntriesAreServedOnlyWithoutASecret)
{
    write("r8.texsyn", R"({ "sample": "s.png", "size": "48x40", "iterations": 1, "seed": 8 })");
    std::ofstream(dir / "secret") << "0123456789abcdef-a-site-secret";
    // forge(SECRET): seed 7's entry replaced by seed 8's, its key rewritten.
    auto forge = [&](const std::string& env) {
        fs::remove_all(dir / "cache");
        EXPECT_EQ(sh(env + " oiiotool r.texsyn -o a.exr").status, 0);
        const std::string key7 = entries()[0].substr(0, 32);
        fs::remove(dir / "cache" / entries()[0]);
        EXPECT_EQ(sh(env + " oiiotool r8.texsyn -o b.exr").status, 0);
        const std::string key8 = entries()[0].substr(0, 32);
        const ToolRun r = sh("oiiotool -a cache/" + key8 + ".exr --attrib synth:cache_key " + key7
                + " -d float -o cache/" + key7 + ".exr && rm cache/" + key8 + ".exr",
            "");
        EXPECT_EQ(r.status, 0) << r.out;
    };
    const std::string reference = plain("r.texsyn"); // seed 3
    const std::string forged = plain("r8.texsyn");
    forge("");
    ToolRun r = sh("oiiotool r.texsyn -d float -o c.exr && idiff -fail 0 " + forged + ".exr c.exr");
    EXPECT_EQ(r.status, 0) << "without a secret the forgery is served: " << r.out;
    EXPECT_EQ(count(r.out, "texsyn cache: hit"), 1u) << r.out;

    const std::string secret = "TEXSYN_CACHE_SECRET=secret";
    forge(secret); // authenticated entries, one key rewritten
    r = sh(secret + " oiiotool r.texsyn -d float -o d.exr && idiff -fail 0 " + reference
        + ".exr d.exr");
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_EQ(count(r.out,
                  ": ignoring an untrusted entry (it is not authenticated with "
                  "$TEXSYN_CACHE_SECRET (written without it, or forged)); it is made "
                  "again"),
        1u)
        << r.out;
    EXPECT_EQ(count(r.out, ", synthesizing"), 1u) << r.out;
    r = sh(secret + " oiiotool r.texsyn -d float -o e.exr && idiff -fail 0 " + reference
        + ".exr e.exr");
    EXPECT_EQ(count(r.out, "texsyn cache: hit"), 1u)
        << "replaced by an authenticated one: " << r.out;
    // An entry stored without the secret is not trusted by a process that has it.
    fs::remove_all(dir / "cache");
    ASSERT_EQ(sh("oiiotool r.texsyn -o f.exr").status, 0);
    r = sh(secret + " oiiotool r.texsyn -o g.exr");
    EXPECT_EQ(count(r.out, "ignoring an untrusted entry"), 1u) << r.out;
    // A secret that is too short turns the cache off, with one warning.
    std::ofstream(dir / "short") << "123";
    r = sh("TEXSYN_CACHE_SECRET=short oiiotool r.texsyn -d float -o h.exr && idiff -fail 0 "
        + reference + ".exr h.exr");
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_NE(
        r.out.find("TEXSYN_CACHE: short: a cache secret is 16 to 4096 bytes"), std::string::npos)
        << r.out;
}

// A process holding an entry's lock that is stopped (SIGSTOP) delays the others by the
// lock timeout, not for ever.
TEST_F(ResultCache, AStoppedLockHolderDelaysOthersByTheTimeoutOnly)
{
    expect_uncached_result("r.texsyn", 1);
    const std::string key = entries()[0].substr(0, 32);
    fs::remove(dir / "cache" / entries()[0]);
    const pid_t holder = hold_lock((dir / "cache" / (key + ".lock")).string());
    ASSERT_GT(holder, 0);
    ::kill(holder, SIGSTOP);
    const auto start = std::chrono::steady_clock::now();
    const ToolRun r = sh("TEXSYN_CACHE_LOCK_TIMEOUT=2 oiiotool r.texsyn -d float -o a.exr && "
                         "idiff -fail 0 plain0.exr a.exr");
    const double seconds
        = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ::kill(holder, SIGKILL);
    ::waitpid(holder, nullptr, 0);
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find(key
                  + ".lock: still held by another process after 2 s "
                    "($TEXSYN_CACHE_LOCK_TIMEOUT): synthesizing without waiting more"),
        std::string::npos)
        << r.out;
    EXPECT_GE(seconds, 2.0);
    EXPECT_LT(seconds, 30.0);
    EXPECT_EQ(count(r.out, "texsyn cache: stored " + key), 1u) << r.out;
}

// In a folder anyone may write, entries and locks of other users are not used (root can
// make a file of another user: the test needs it).
TEST_F(ResultCache, AWorldWritableFolderTrustsOnlyItsOwnerAndThisUser)
{
    if (::geteuid() != 0)
        GTEST_SKIP() << "making a file of another user needs root";
    expect_uncached_result("r.texsyn", 1);
    const fs::path entry = dir / "cache" / entries()[0];
    const std::string key = entries()[0].substr(0, 32);
    ASSERT_EQ(::chown(entry.c_str(), 4321, 4321), 0);
    ASSERT_EQ(::chmod((dir / "cache").c_str(), 01777), 0);
    ToolRun r = sh("oiiotool r.texsyn -d float -o a.exr && idiff -fail 0 plain0.exr a.exr");
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_EQ(count(r.out,
                  "ignoring an untrusted entry (it belongs to user 4321, and anyone may "
                  "write the folder"),
        1u)
        << r.out;
    EXPECT_EQ(count(r.out, ", synthesizing"), 1u) << r.out;
    // The folder owner's entry is used; a lock of another user is not.
    fs::remove(entry);
    ASSERT_EQ(::chown((dir / "cache" / (key + ".lock")).c_str(), 4321, 4321), 0);
    r = sh("oiiotool r.texsyn -o b.exr");
    EXPECT_NE(r.out.find(key
                  + ".lock: not used (it belongs to user 4321, and anyone may write "
                    "the folder)"),
        std::string::npos)
        << r.out;
    EXPECT_EQ(entries().size(), 1u);
    r = sh("oiiotool r.texsyn -o c.exr");
    EXPECT_EQ(count(r.out, "texsyn cache: hit"), 1u) << r.out;
    // Without o+w, the folder's writers are its owner and group: every entry is used.
    ASSERT_EQ(::chown((dir / "cache" / entries()[0]).c_str(), 4321, 4321), 0);
    ASSERT_EQ(::chmod((dir / "cache").c_str(), 02775), 0);
    r = sh("oiiotool r.texsyn -o d.exr");
    EXPECT_EQ(count(r.out, "texsyn cache: hit"), 1u) << r.out;
}
