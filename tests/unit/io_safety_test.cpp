// SPDX-License-Identifier: Apache-2.0
// The file-safety layer (texsyn/io.h, texsyn/memory.h): temporary names, their registry,
// checks of written files, and the memory limit.
#include <texsyn/io.h>
#include <texsyn/memory.h>

#include <filesystem>
#include <fstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "image/io_pvt.h"

using namespace texsyn;
namespace fs = std::filesystem;

namespace {

class IoSafety : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir = fs::temp_directory_path()
            / (std::string("texsyn_io_")
                + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
    fs::path dir;
};

OIIO::ImageBuf noise_image(int w, int h)
{
    OIIO::ImageBuf buf(OIIO::ImageSpec(w, h, 3, OIIO::TypeFloat));
    OIIO::ImageBufAlgo::noise(buf, "uniform", 0.0f, 1.0f, false, 3);
    return buf;
}

} // namespace

TEST_F(IoSafety, TemporaryNamesKeepTheExtensionOwnerAndNameMax)
{
    const std::string name = (dir / (std::string(240, 'n') + ".exr")).string();
    const std::string tmp = temporary_path_for(name);
    const std::string base = fs::path(tmp).filename().string();
    EXPECT_LE(base.size(), 255u);
    EXPECT_EQ(base[0], '.');
    EXPECT_EQ(fs::path(tmp).extension(), ".exr");
    EXPECT_NE(base.find(".texsyn-tmp" + std::to_string(::getpid()) + "-"), std::string::npos);
    EXPECT_EQ(fs::path(tmp).parent_path(), dir);
    EXPECT_NE(temporary_path_for(name), tmp); // a counter makes each unique
    discard_temporary(tmp);
}

// A temporary is created by temporary_path_for itself, exclusively: a regular file of this
// process's user, never a name someone planted (each name has an unpredictable part).
TEST_F(IoSafety, TemporariesAreCreatedExclusivelyAndNotThroughLinks)
{
    const std::string name = (dir / "out.exr").string();
    const std::string a = temporary_path_for(name), b = temporary_path_for(name);
    EXPECT_NE(a, b);
    for (const std::string& t : { a, b }) {
        EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(t))) << t;
        EXPECT_EQ(fs::file_size(t), 0u) << t;
    }
    discard_temporary(a);
    discard_temporary(b);
}

// commit_file renames only the regular file it made: a temporary swapped for a link (to a
// file outside the folder) is removed, the link's target untouched, nothing committed.
// write_bytes never writes through a link.
TEST_F(IoSafety, SwappedTemporariesAndLinksAreNotWrittenThrough)
{
    const fs::path victim = dir / "victim.txt";
    std::ofstream(victim) << "victim";
    const std::string out = (dir / "out.exr").string();
    const std::string tmp = temporary_path_for(out);
    fs::remove(tmp);
    fs::create_symlink(victim, tmp);
    std::string error;
    EXPECT_FALSE(commit_file(tmp, out, error));
    EXPECT_EQ(error,
        out
            + ": cannot write (its temporary file was replaced while it was written: is "
              "someone else writing to this folder?)");
    EXPECT_FALSE(fs::exists(fs::symlink_status(tmp)));
    EXPECT_FALSE(fs::exists(out));

    fs::create_symlink(victim, dir / "link.txt");
    std::string reason;
    EXPECT_FALSE(write_bytes((dir / "link.txt").string(), "attack", reason));
    EXPECT_EQ(reason.rfind("cannot create (", 0), 0u) << reason;
    std::ifstream in(victim);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "victim");
}

// An output replaces nothing, a regular file or a link; never a FIFO, socket, device or
// directory, and commit_file keeps to that too.
TEST_F(IoSafety, OnlyRegularFilesAndLinksAreReplaced)
{
    std::string error;
    EXPECT_TRUE(check_output_destination((dir / "none.exr").string(), error));
    std::ofstream(dir / "file.exr") << "x";
    EXPECT_TRUE(check_output_destination((dir / "file.exr").string(), error));
    fs::create_symlink("/dev/null", dir / "link.exr");
    EXPECT_TRUE(check_output_destination((dir / "link.exr").string(), error));
    ASSERT_EQ(::mkfifo((dir / "fifo.exr").c_str(), 0644), 0);
    EXPECT_FALSE(check_output_destination((dir / "fifo.exr").string(), error));
    EXPECT_EQ(error,
        (dir / "fifo.exr").string()
            + ": exists and is not a regular file (a device, FIFO or socket); texsyn does not "
              "replace it");
    EXPECT_FALSE(check_output_destination("/dev/null", error));
    fs::create_directories(dir / "folder.exr");
    EXPECT_FALSE(check_output_destination((dir / "folder.exr").string(), error));
    EXPECT_NE(error.find("(a directory)"), std::string::npos) << error;

    const std::string tmp = temporary_path_for((dir / "fifo.exr").string());
    EXPECT_FALSE(commit_file(tmp, (dir / "fifo.exr").string(), error));
    EXPECT_TRUE(fs::is_fifo(dir / "fifo.exr"));
    EXPECT_FALSE(fs::exists(tmp));
    const std::string ok = temporary_path_for((dir / "link.exr").string());
    ASSERT_TRUE(commit_file(ok, (dir / "link.exr").string(), error)) << error;
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir / "link.exr")));
    EXPECT_TRUE(fs::is_character_file("/dev/null"));
}

TEST_F(IoSafety, LiveTemporariesAreRemovedOnDemandAndCommittedOnesAreNot)
{
    const std::string a = temporary_path_for((dir / "a.exr").string());
    const std::string b = temporary_path_for((dir / "b.exr").string());
    std::ofstream(a) << "a";
    std::ofstream(b) << "b";
    std::string error;
    ASSERT_TRUE(commit_file(b, (dir / "b.exr").string(), error)) << error;
    remove_live_temporaries(); // what a signal handler calls
    EXPECT_FALSE(fs::exists(a));
    EXPECT_TRUE(fs::exists(dir / "b.exr"));
}

TEST_F(IoSafety, WrittenFilesWithHolesOrNothingInThemAreCaught)
{
    const std::string empty = (dir / "empty.bin").string(), sparse = (dir / "sparse.bin").string(),
                      full = (dir / "full.bin").string();
    std::ofstream(empty).close();
    {
        const int fd = ::open(sparse.c_str(), O_WRONLY | O_CREAT, 0644);
        ASSERT_GE(fd, 0);
        ASSERT_EQ(::pwrite(fd, "end", 3, 1 << 20), 3); // a megabyte never written
        ::close(fd);
    }
    std::string reason;
    ASSERT_TRUE(write_bytes(full, std::string(100000, 'x'), reason)) << reason;
    EXPECT_TRUE(sync_written_file(full, reason)) << reason;
    EXPECT_FALSE(sync_written_file(empty, reason));
    EXPECT_EQ(reason, "nothing was written (disk full?)");
    EXPECT_FALSE(sync_written_file(sparse, reason));
    EXPECT_EQ(reason, "the file has unwritten gaps (disk full?)");
    EXPECT_FALSE(write_bytes((dir / "no" / "such" / "dir").string(), "x", reason));
    EXPECT_EQ(reason.rfind("cannot create (", 0), 0u) << reason;
}

TEST_F(IoSafety, TruncatedImagesDoNotVerifyAndWholeOnesDo)
{
    // Not JPEG: libjpeg decodes a truncated file as grey without an error, but it reports
    // its own write errors (AFullDiskFailsEveryWriterCleanly covers that case).
    const OIIO::ImageBuf image = noise_image(64, 48);
    for (const std::string ext : { ".png", ".exr", ".tif", ".tga", ".bmp" }) {
        const std::string path = (dir / ("a" + ext)).string();
        ASSERT_TRUE(image.write(path, ext == ".exr" ? OIIO::TypeHalf : OIIO::TypeUInt8));
        std::string reason;
        EXPECT_TRUE(verify_image_file(path, image.spec(), reason)) << ext << ": " << reason;
        fs::resize_file(path, fs::file_size(path) * 2 / 3);
        EXPECT_FALSE(verify_image_file(path, image.spec(), reason)) << ext;
        EXPECT_EQ(reason.rfind("the written file is incomplete (disk full?)", 0), 0u) << reason;
    }
}

// Images are encoded in memory and their bytes written with checked write() calls: the
// files are those OIIO writes itself, and every format here is encoded in memory (a file
// written by the library is read back whole instead: 4096² took 8.4 s rather than 5.7 s).
// (SGI, which OIIO cannot write to memory, is written by OIIO and read back:
// AFullDiskFailsEveryWriterCleanly.)
TEST_F(IoSafety, CheckedWritesGiveTheFilesOiioWrites)
{
    OIIO::ImageBuf image = noise_image(64, 48);
    image.specmod().attribute("DateTime", "2026:01:01 00:00:00"); // else the time of writing
    auto bytes_of = [](const fs::path& path) {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    for (const std::string ext : { ".exr", ".png", ".tif", ".tga", ".bmp", ".jpg", ".hdr" }) {
        const fs::path ours = dir / ("ours" + ext), oiio = dir / ("oiio" + ext);
        const OIIO::TypeDesc type = ext == ".exr" ? OIIO::TypeHalf
            : ext == ".hdr"                       ? OIIO::TypeFloat
                                                  : OIIO::TypeUInt8;
        std::string error;
        ASSERT_TRUE(write_image_verified(image, ours.string(), type, error))
            << ext << ": " << error;
        ASSERT_TRUE(image.write(oiio.string(), type)) << ext;
        EXPECT_GT(fs::file_size(ours), 0u) << ext;
        EXPECT_TRUE(bytes_of(ours) == bytes_of(oiio)) << ext;
        std::vector<unsigned char> encoded;
        EXPECT_TRUE(encode_in_memory(image, ours.string(), type, encoded, error))
            << ext << ": " << error;
        EXPECT_TRUE(std::string(encoded.begin(), encoded.end()) == bytes_of(oiio)) << ext;
    }
}

TEST_F(IoSafety, AtomicWritesAreVerifiedAndLeaveNoTemporary)
{
    const OIIO::ImageBuf image = noise_image(32, 32);
    std::string error;
    ASSERT_TRUE(write_image_atomic(image, (dir / "ok.png").string(), OIIO::TypeUInt8, error))
        << error;
    // A file that cannot even be created leaves nothing either.
    fs::create_directories(dir / "locked");
    fs::permissions(dir / "locked", fs::perms::owner_read | fs::perms::owner_exec);
    if (::geteuid() != 0) { // root writes anyway
        EXPECT_FALSE(
            write_image_atomic(image, (dir / "locked" / "x.png").string(), OIIO::TypeUInt8, error));
        EXPECT_TRUE(fs::is_empty(dir / "locked"));
    }
    fs::permissions(dir / "locked", fs::perms::owner_all);
    for (auto& e : fs::directory_iterator(dir))
        EXPECT_EQ(e.path().filename().string().find(".texsyn-tmp"), std::string::npos);
}

TEST(MemoryLimit, SizesParseInBinaryUnitsAndShares)
{
    size_t bytes = 0;
    std::string error;
    ASSERT_TRUE(parse_memory_size("512M", bytes, error));
    EXPECT_EQ(bytes, size_t(512) << 20);
    ASSERT_TRUE(parse_memory_size("8G", bytes, error));
    EXPECT_EQ(bytes, size_t(8) << 30);
    ASSERT_TRUE(parse_memory_size("1.5GB", bytes, error));
    EXPECT_EQ(bytes, size_t(3) << 29);
    ASSERT_TRUE(parse_memory_size("1500000000", bytes, error));
    EXPECT_EQ(bytes, size_t(1500000000));
    ASSERT_TRUE(parse_memory_size("50%", bytes, error));
    EXPECT_GT(bytes, size_t(0));
    for (const char* bad : { "", "G", "lots", "0", "-1G", "12Q", "150%", "1e30", "nan" }) {
        EXPECT_FALSE(parse_memory_size(bad, bytes, error)) << bad;
        EXPECT_EQ(error, "expected a memory size such as 8G, 512M, 1500000000 or 50%");
    }
}

TEST(MemoryLimit, RefusalsNameTheEstimateAndTheLimit)
{
    std::string error;
    EXPECT_TRUE(check_memory(size_t(1) << 20, "a small job", error)) << error;
    set_memory_limit(size_t(256) << 20);
    EXPECT_EQ(memory_limit(), size_t(256) << 20);
    EXPECT_FALSE(check_memory(size_t(1) << 30, "size=16384x16384", error));
    EXPECT_EQ(error.rfind("size=16384x16384 would need about 1.0 GB of memory (only ", 0), 0u)
        << error;
    EXPECT_NE(error.find("available of a limit of 256.0 MB, of which the process holds "),
        std::string::npos)
        << error;
    set_memory_limit(0);
    EXPECT_GT(memory_limit(), size_t(256) << 20);
}
