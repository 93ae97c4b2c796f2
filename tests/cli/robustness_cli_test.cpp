// SPDX-License-Identifier: Apache-2.0
// The tool under faults (docs/robustness.md): a full disk, signals, a killed process's
// debris, memory limits and decompression bombs, libraries that end the process, and
// oversized arguments. Each ends in one error line, a non-zero exit and no file left
// behind, never in a success with a broken file.
#include "cli_fixture.h"
#include "png_bomb.h"

#include <chrono>
#include <csignal>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <OpenImageIO/imagebufalgo.h>

namespace {

class Robustness : public Cli {
protected:
    // Runs `args` with the file-size limit `kb` (ulimit -f): every write past it fails as
    // on a full disk (EFBIG). stderr.txt stays far below the limit.
    CliRun texsyn_with_file_limit(const std::string& args, int kb)
    {
        return texsyn(args, "ulimit -f " + std::to_string(kb) + " &&");
    }

    // Names in the directory other than `inputs` (temporaries included: they start with '.').
    void expect_only(std::initializer_list<std::string> inputs, const std::string& context)
    {
        const auto left = outputs(inputs);
        EXPECT_TRUE(left.empty()) << context << ": left " << left.front();
    }

    // Starts the tool on `args` (stderr to err.txt) and returns its pid. The signals it
    // handles start with their default action (this test may run in a background job,
    // which ignores SIGINT), or ignored if `ignored` says so.
    pid_t spawn(const std::vector<std::string>& args, int ignored = 0)
    {
        const pid_t pid = ::fork();
        if (pid == 0) {
            for (int sig : { SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE })
                std::signal(sig, sig == ignored ? SIG_IGN : SIG_DFL);
            if (::chdir(dir.c_str()) != 0)
                ::_exit(127);
            const int err = ::open("err.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
            ::dup2(err, STDERR_FILENO);
            std::vector<char*> argv { const_cast<char*>(TEXSYN_EXE) };
            for (const std::string& a : args)
                argv.push_back(const_cast<char*>(a.c_str()));
            argv.push_back(nullptr);
            ::execv(TEXSYN_EXE, argv.data());
            ::_exit(127);
        }
        return pid;
    }

    // The name of a temporary file of the tool in the directory, waiting up to a minute
    // for one to appear; "" if none does.
    std::string wait_for_temporary()
    {
        for (int i = 0; i < 6000; ++i) {
            for (auto& e : fs::directory_iterator(dir)) {
                const std::string n = e.path().filename().string();
                if (n.find(".texsyn-tmp") != std::string::npos)
                    return n;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        return "";
    }

    // A tool run that writes a.exr early and then synthesizes for several seconds more:
    // its temporary a.exr exists for that long.
    static std::vector<std::string> slow_run()
    {
        return { "stucco.png", "--pyramid:size=64x64:iterations=1", "-o", "a.exr",
            "--pyramid:size=2048x2048:iterations=40", "-o", "b.exr" };
    }
};

} // namespace

// A full disk while writing: every output kind fails with one line naming the output, and
// neither the output nor its temporary file is left (the PNG, TGA, VDB and cascade cases
// used to end in success with a truncated, empty or sparse file; the JPEG one left its
// temporary).
TEST_F(Robustness, AFullDiskFailsEveryWriterCleanly)
{
    ASSERT_EQ(
        texsyn("stucco.png --neighborhood:size=64x64:levels=2:map=coords.exr -o n.png").status, 0);
    const std::string pyramid = "stucco.png --pyramid:size=256x256:iterations=1 ";
    const std::vector<std::pair<std::string, std::string>> cases = {
        { pyramid + "-o out.png", "-o out.png : cannot write (" },
        { pyramid + "-d uint16 -o out16.png", "-o out16.png : cannot write (" },
        { pyramid + "-o out.tga", "-o out.tga : cannot write (" },
        { pyramid + "-o out.tif", "-o out.tif : cannot write (" },
        { pyramid + "-d float -o out.exr", "-o out.exr : cannot write (" },
        { pyramid + "--subbands -d float -o bands.exr", "-o bands.exr : cannot write (" },
        { pyramid + "-o out.jpg", "-o out.jpg : " },
        { pyramid + "-o out.sgi", "-o out.sgi : cannot write (" }, // written by OIIO, read back
        { "--cascade:size=256x256 -o cascade.png", "-o cascade.png : cannot write (" },
        { "stucco.png --analyze -o a.tsa", "-o a.tsa : cannot write the analysis file (" },
        { "stucco.png --solid:size=32x32x32:iterations=1 -o v.vdb", "-o v.vdb : cannot write (" },
        { "stucco.png --solid:size=32x32x32:iterations=1 -o v.exr", "-o v.exr : cannot write (" },
        { "--apply-map coords.exr stucco.png -d uint16 -o applied.png",
            "-o applied.png : cannot write (" },
        { "stucco.png --neighborhood:size=128x128:levels=2:map=m.exr -o n2.exr",
            "--neighborhood : map=" },
    };
    for (const auto& [args, message] : cases) {
        const CliRun r = texsyn_with_file_limit(args, 8);
        EXPECT_EQ(r.status, 1) << args << ": " << r.err;
        EXPECT_EQ(r.first_err_line().rfind("texsyn ERROR: " + message, 0), 0u)
            << args << ": " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
        expect_only({ "stucco.png", "coords.exr", "n.png" }, args);
    }
}

// Without the limit the same outputs are written and read back: the checks that catch a
// full disk do not refuse good files of any writer.
TEST_F(Robustness, TheWriteChecksAcceptEveryGoodFile)
{
    const std::string pyramid = "stucco.png --pyramid:size=64x64:iterations=1 ";
    for (const std::string out : { "out.png", "out.tga", "out.tif", "out.jpg", "out.exr", "out.bmp",
             "out.tx", "out.hdr", "out.sgi" }) {
        const CliRun r = texsyn(pyramid + "-o " + out);
        EXPECT_EQ(r.status, 0) << out << ": " << r.err;
        EXPECT_TRUE(fs::exists(dir / out)) << out;
    }
    EXPECT_EQ(texsyn("stucco.png --solid:size=16x16x16:iterations=1 -o v.vdb").status, 0);
    EXPECT_EQ(texsyn("stucco.png --analyze -o a.tsa").status, 0);
    expect_only({ "stucco.png", "out.png", "out.tga", "out.tif", "out.jpg", "out.exr", "out.bmp",
                    "out.tx", "out.hdr", "out.sgi", "v.vdb", "a.tsa" },
        "good writes");
}

// SIGINT, SIGTERM and SIGHUP while a temporary output exists: the tool stops at once with
// 128 + the signal's number and removes every temporary.
TEST_F(Robustness, SignalsStopTheRunAndRemoveTemporaries)
{
    for (int sig : { SIGINT, SIGTERM, SIGHUP }) {
        const pid_t pid = spawn(slow_run());
        ASSERT_GT(pid, 0);
        const std::string tmp = wait_for_temporary();
        ASSERT_FALSE(tmp.empty()) << "signal " << sig << ": no temporary appeared";
        const auto sent = std::chrono::steady_clock::now();
        ::kill(pid, sig);
        int status = 0;
        ASSERT_EQ(::waitpid(pid, &status, 0), pid);
        const double seconds
            = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
        EXPECT_LT(seconds, 2.0) << "signal " << sig; // at once; slack for a loaded machine
        ASSERT_TRUE(WIFEXITED(status)) << "signal " << sig;
        EXPECT_EQ(WEXITSTATUS(status), 128 + sig);
        fs::remove(dir / "err.txt");
        expect_only({ "stucco.png" }, "signal " + std::to_string(sig));
    }
}

// A signal its parent ignores (SIGINT in a shell's background job, SIGHUP under nohup)
// stays ignored; the others still stop the run cleanly.
TEST_F(Robustness, InheritedIgnoredSignalsStayIgnored)
{
    const pid_t pid = spawn(slow_run(), SIGINT);
    ASSERT_GT(pid, 0);
    ASSERT_FALSE(wait_for_temporary().empty());
    ::kill(pid, SIGINT);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    int status = 0;
    EXPECT_EQ(::waitpid(pid, &status, WNOHANG), 0) << "SIGINT ended the run";
    ::kill(pid, SIGTERM);
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
    fs::remove(dir / "err.txt");
    expect_only({ "stucco.png" }, "SIGTERM after an ignored SIGINT");
}

// SIGKILL cannot be handled: its temporary stays, recognisable by name, host and pid, and
// the next run into the folder removes it. A live process's temporary is left alone.
TEST_F(Robustness, TheNextRunRemovesTheTemporariesOfKilledProcesses)
{
    const pid_t pid = spawn(slow_run());
    ASSERT_GT(pid, 0);
    const std::string tmp = wait_for_temporary();
    ASSERT_FALSE(tmp.empty());
    ::kill(pid, SIGKILL);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    fs::remove(dir / "err.txt");
    ASSERT_TRUE(fs::exists(dir / tmp));
    // The same name with this (live) test's pid: another process's work in progress.
    const std::string pid_text = std::to_string(pid);
    std::string live = tmp;
    live.replace(live.find(".texsyn-tmp") + 11, pid_text.size(), std::to_string(::getpid()));
    fs::copy_file(dir / tmp, dir / live);

    const CliRun r = texsyn("stucco.png --pyramid:size=64x64:iterations=1 -o c.exr");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_FALSE(fs::exists(dir / tmp)) << tmp;
    EXPECT_TRUE(fs::exists(dir / live)) << live;
    fs::remove(dir / live);
    expect_only({ "stucco.png", "c.exr" }, "after the next run");
}

// A decompression bomb (a PNG header claiming 100000x100000 pixels with a few bytes of
// data) is refused from its header, before any pixel is allocated; --max-memory lowers
// the limit, so a 20000x20000 claim is refused under 1G.
TEST_F(Robustness, ImageHeadersBeyondTheMemoryLimitAreRefused)
{
    {
        std::ofstream(dir / "bomb.png", std::ios::binary)
            << texsyn::test::png_bomb(sample_path("stucco_yellow.png"), 100000);
        std::ofstream(dir / "bomb20k.png", std::ios::binary)
            << texsyn::test::png_bomb(sample_path("stucco_yellow.png"), 20000);
    }
    const auto inputs
        = { std::string("stucco.png"), std::string("bomb.png"), std::string("bomb20k.png") };
    expect_failure_starting("bomb.png --pyramid -o out.exr",
        "texsyn ERROR: bomb.png: its 100000x100000 pixels would need about 447.0 GB of memory",
        inputs);
    const auto start = std::chrono::steady_clock::now();
    expect_failure_starting("--max-memory 1G bomb20k.png --pyramid -o out.exr",
        "texsyn ERROR: bomb20k.png: its 20000x20000 pixels would need about 17.9 GB of memory "
        "(only ",
        inputs);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
    expect_failure_starting("--apply-map bomb.png stucco.png -o out.exr",
        "texsyn ERROR: bomb.png: its 100000x100000 pixels would need about", inputs);
}

// --max-memory bounds the synthesis too, and the refusal is the only line printed (no
// library debug output).
TEST_F(Robustness, MaxMemoryRefusesBeforeAllocating)
{
    expect_failure_starting("--max-memory 300M stucco.png --pyramid:size=4096x4096 -o out.exr",
        "texsyn ERROR: --pyramid : size=4096x4096 would need about ");
    const CliRun r = texsyn("--max-memory 300M --cascade:size=4096x4096 -o out.png");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(
        r.first_err_line().rfind("texsyn ERROR: --cascade : size=4096x4096 would need about ", 0),
        0u)
        << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.first_err_line().find("see --max-memory"), std::string::npos) << r.err;
    for (const std::string bad : { "lots", "0", "-5G", "12Q", "150%" })
        expect_failure_starting("--max-memory " + bad + " stucco.png --pyramid -o out.exr",
            "texsyn ERROR: --max-memory " + bad
                + " : expected a memory size such as 8G, 512M, 1500000000 or 50%");
    EXPECT_EQ(
        texsyn("--max-memory 2G stucco.png --pyramid:size=64x64:iterations=1 -o ok.exr").status, 0);
}

// Under an address-space limit (ulimit -v) an 8K sample's float pixels do not fit: the read
// is refused with the estimate, where it used to crash in the allocation.
TEST_F(Robustness, AnAddressSpaceLimitIsRespectedWhenReading)
{
    OIIO::ImageBuf big(OIIO::ImageSpec(8192, 8192, 3, OIIO::TypeUInt8));
    const float grey[3] = { 0.5f, 0.4f, 0.3f };
    OIIO::ImageBufAlgo::fill(big, grey);
    ASSERT_TRUE(big.write((dir / "big.png").string()));
    const CliRun r = texsyn("big.png --pyramid -o out.exr", "ulimit -v 700000 &&");
    EXPECT_EQ(r.status, 1) << r.err;
    EXPECT_EQ(
        r.first_err_line().rfind(
            "texsyn ERROR: big.png: its 8192x8192 pixels would need about 3.0 GB of memory", 0),
        0u)
        << r.err;
    expect_only({ "stucco.png", "big.png" }, "ulimit -v");
}

// Errors echo arguments; a 100 kB value is cut to a readable length.
TEST_F(Robustness, HugeArgumentsAreCutInErrorLines)
{
    const std::string huge(100000, '7');
    const CliRun r = texsyn("stucco.png --pyramid:iterations=" + huge + " -o out.exr");
    EXPECT_EQ(r.status, 1);
    EXPECT_LT(r.err.size(), 400u) << r.err.substr(0, 400);
    EXPECT_NE(r.err.find("...(100011 characters)"), std::string::npos) << r.err.substr(0, 400);
}

// Linux file names are bytes; JSON text is UTF-8. A recipe or analysis file that would
// have to name such a file is refused (it used to end the process with an exception).
TEST_F(Robustness, NamesThatAreNotUtf8AreRefusedByTheJsonWriters)
{
    const std::string name = "bad\x90name.png";
    fs::copy_file(dir / "stucco.png", dir / name);
    const CliRun r
        = texsyn("'" + name + "' --pyramid:size=64x64:iterations=1 -o out.exr --recipe r.texsyn");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.first_err_line(),
        "texsyn ERROR: --recipe r.texsyn : a file or colour-space name is not valid UTF-8, which "
        "a JSON recipe cannot hold");
    const CliRun a = texsyn("'" + name + "' --analyze -o a.tsa");
    EXPECT_EQ(a.status, 1);
    EXPECT_EQ(a.first_err_line(),
        "texsyn ERROR: -o a.tsa : cannot write the analysis file (the sample's file name or a "
        "channel name is not valid UTF-8)");
    expect_only({ "stucco.png", name }, "names that are not UTF-8");
}

namespace {

// A little-endian baseline TIFF: uncompressed 8-bit RGB, one strip of `strip_bytes` at
// offset 8 + IFD, followed by `data` (found by an adversarial campaign: headers and strips
// that do not hold the pixels they claim).
std::string rgb_tiff(uint32_t width, uint32_t height, uint32_t strip_bytes, const std::string& data)
{
    const uint16_t entries = 9;
    const uint32_t data_offset = 8 + 2 + 12 * entries + 4;
    const uint32_t tags[entries][4] = { { 256, 4, 1, width }, { 257, 4, 1, height },
        { 258, 3, 1, 8 }, { 259, 3, 1, 1 }, { 262, 3, 1, 2 }, { 273, 4, 1, data_offset },
        { 277, 3, 1, 3 }, { 278, 4, 1, height }, { 279, 4, 1, strip_bytes } };
    std::string out = std::string("II*\0", 4);
    auto put = [&](uint32_t v, int bytes) {
        for (int i = 0; i < bytes; ++i)
            out += char((v >> (8 * i)) & 0xff);
    };
    put(8, 4);
    put(entries, 2);
    for (const auto& t : tags) {
        put(t[0], 2);
        put(t[1], 2);
        put(t[2], 4);
        put(t[3], t[1] == 3 ? 2 : 4);
        if (t[1] == 3)
            put(0, 2);
    }
    put(0, 4);
    return out + data;
}

} // namespace

// Truncated and lying files are refused, not read as black or grey pixels: a JPEG cut in
// half (libjpeg reports success and only records "Premature end of JPEG file"), a TIFF
// whose strip is cut off, and a 138-byte TIFF claiming two million rows (OIIO added an
// error per missing row until its 16 MB limit on errors aborted the process).
TEST_F(Robustness, TruncatedAndLyingFilesAreRefused)
{
    ASSERT_EQ(texsyn("stucco.png -o whole.jpg").status, 0);
    const std::string jpeg = slurp(dir / "whole.jpg");
    spit(dir / "half.jpg", jpeg.substr(0, jpeg.size() / 2));
    spit(dir / "cut.tif", rgb_tiff(64, 64, 64 * 64 * 3, std::string(1000, '\x80')));
    spit(dir / "tall.tif", rgb_tiff(1, 2000000, 16, std::string(16, '\x80')));
    for (const std::string name : { "half.jpg", "cut.tif", "tall.tif" }) {
        const auto start = std::chrono::steady_clock::now();
        const CliRun r = texsyn(name + " --check");
        EXPECT_EQ(r.status, 1) << name;
        EXPECT_EQ(r.first_err_line().find("texsyn ERROR: " + name + ": cannot read image ("), 0u)
            << r.err;
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
        EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20)) << name;
    }
    EXPECT_NE(texsyn("half.jpg --check").err.find("Premature end of JPEG file"), std::string::npos);
    // TIFF strips are checked against the file's size: OIIO reads JPEG-compressed TIFF
    // through libtiff's RGBA interface, which filled a missing strip from the ones before.
    EXPECT_EQ(texsyn("cut.tif --check").first_err_line(),
        "texsyn ERROR: cut.tif: cannot read image (it is cut short: strip or tile 0 of 1 ends at "
        "byte 12410 of a file of 1122)");
}

// A JPEG-compressed TIFF whose second strip is damaged inside the file: OIIO reads such
// files through libtiff's RGBA interface, which repeated the first strip's rows and
// reported success. Every strip is now decoded once with libtiff.
TEST_F(Robustness, DamagedStripsOfJpegTiffsAreRefused)
{
    OIIO::ImageSpec spec(64, 128, 3, OIIO::TypeUInt8); // OIIO writes 64 rows per strip
    spec.attribute("compression", "jpeg");
    OIIO::ImageBuf image(spec);
    OIIO::ImageBufAlgo::checker(image, 8, 8, 1, { 0.9f, 0.5f, 0.1f }, { 0.1f, 0.2f, 0.7f });
    ASSERT_TRUE(image.write((dir / "good.tif").string())) << image.geterror();
    ASSERT_EQ(texsyn("good.tif --check").status, 0);
    // Each strip is a JPEG stream with a scan (SOI FF D8 ... SOS FF DA); the shared tables
    // are a stream without one. Damage the second strip.
    std::string bytes = slurp(dir / "good.tif");
    std::vector<size_t> strips;
    for (size_t at = bytes.find("\xff\xd8\xff"); at != std::string::npos;
         at = bytes.find("\xff\xd8\xff", at + 3))
        if (bytes.find("\xff\xda", at) < bytes.find("\xff\xd9", at))
            strips.push_back(at);
    ASSERT_EQ(strips.size(), 2u);
    bytes.replace(strips[1], 16, std::string(16, '\0'));
    spit(dir / "damaged.tif", bytes);
    expect_failure_starting("damaged.tif --check",
        "texsyn ERROR: damaged.tif: cannot read image (strip or tile 1 of 2 does not decode",
        { "stucco.png", "good.tif", "damaged.tif" });
}

// No two outputs may name one file, however spelled: the last used to replace the others
// silently.
TEST_F(Robustness, TwoOutputsNamingOneFileAreRefused)
{
    const std::string run = "stucco.png --pyramid:size=32x32:iterations=1 ";
    expect_failure(
        run + "-o a.png -o ./a.png", "texsyn ERROR: -o ./a.png : is also written by -o a.png");
    expect_failure(
        run + "-o a.png -o a.png", "texsyn ERROR: -o a.png : is also written by -o a.png");
    expect_failure(run + "-o a.exr -o " + (dir / "a.exr").string(),
        "texsyn ERROR: -o " + (dir / "a.exr").string() + " : is also written by -o a.exr");
    expect_failure(run + "-o z.png --recipe r.texsyn --recipe ./r.texsyn",
        "texsyn ERROR: --recipe ./r.texsyn : is also written by --recipe r.texsyn");
    expect_failure("stucco.png --analyze -o a.tsa -o ./a.tsa",
        "texsyn ERROR: -o ./a.tsa : is also written by -o a.tsa");
    ASSERT_EQ(texsyn(run + "-o a.png").status, 0);
    fs::create_symlink("a.png", dir / "l.png");
    expect_failure(run + "-o a.png -o l.png",
        "texsyn ERROR: -o l.png : is also written by -o a.png", { "stucco.png", "a.png", "l.png" });
}

// A colour config whose FileTransform names a FIFO or a device is refused when it is
// loaded: OCIO would block for ever reading it, in texsyn and in every host of the plugin.
TEST_F(Robustness, LutFilesThatAreNotRegularFilesAreRefused)
{
    ASSERT_EQ(::mkfifo((dir / "lut.spi1d").c_str(), 0644), 0);
    std::string config = slurp(TEXSYN_BUNDLED_OCIO_CONFIG);
    const size_t search = config.find("search_path:");
    ASSERT_NE(search, std::string::npos);
    config.replace(search, config.find('\n', search) - search, "search_path: \".\"");
    spit(dir / "fifo.ocio",
        config
            + "\n  - !<ColorSpace>\n    name: evil\n    isdata: false\n"
              "    to_scene_reference: !<FileTransform> {src: lut.spi1d, interpolation: linear}\n");
    spit(dir / "zero.ocio",
        config
            + "\n  - !<ColorSpace>\n    name: evil\n    isdata: false\n"
              "    to_scene_reference: !<FileTransform> {src: /dev/zero, interpolation: linear}\n");
    expect_failure("--colorconfig fifo.ocio --iscolorspace evil stucco.png --pyramid -o o.png",
        "texsyn ERROR: colour config 'fifo.ocio': its FileTransform 'lut.spi1d': "
            + (dir / "lut.spi1d").string()
            + ": is not a regular file (a FIFO, device or socket), not a LUT file",
        { "stucco.png", "fifo.ocio", "zero.ocio", "lut.spi1d" });
    // OCIO reads a LUT whole: a sparse file of gigabytes took minutes and memory past any
    // limit.
    spit(dir / "huge.spi1d", "");
    fs::resize_file(dir / "huge.spi1d", uintmax_t(1) << 30);
    spit(dir / "huge.ocio",
        config
            + "\n  - !<ColorSpace>\n    name: evil\n    isdata: false\n"
              "    to_scene_reference: !<FileTransform> {src: huge.spi1d, interpolation: "
              "linear}\n");
    expect_failure("--colorconfig huge.ocio stucco.png --pyramid -o o.png",
        "texsyn ERROR: colour config 'huge.ocio': its FileTransform 'huge.spi1d': "
            + (dir / "huge.spi1d").string()
            + " is 1.0 GB, more than any LUT texsyn reads (128.0 MB)",
        { "stucco.png", "fifo.ocio", "zero.ocio", "lut.spi1d", "huge.ocio", "huge.spi1d" });
    expect_failure_starting("--colorconfig zero.ocio stucco.png --pyramid -o o.png",
        "texsyn ERROR: colour config 'zero.ocio': its FileTransform '/dev/zero': /dev/zero: is not "
        "a regular file",
        { "stucco.png", "fifo.ocio", "zero.ocio", "lut.spi1d", "huge.ocio", "huge.spi1d" });
}

// The memory estimate covers what reading a sample and analysing it hold, not only the
// output: a large sample under a small limit is refused before the memory is used (an 8K
// sample used to reach 14 GB under --max-memory 1G).
TEST_F(Robustness, TheSampleAndItsAnalysisAreEstimated)
{
    const OIIO::ImageBuf big
        = OIIO::ImageBufAlgo::resize(OIIO::ImageBuf((dir / "stucco.png").string()), "", 0,
            OIIO::ROI(0, 1024, 0, 1024, 0, 1, 0, 3));
    ASSERT_TRUE(big.write((dir / "big.png").string())) << big.geterror();
    expect_failure_starting("--max-memory 140M big.png --pyramid:size=64x64 -o o.png",
        "texsyn ERROR: big.png: its 1024x1024 pixels would need about 48.0 MB of memory (only ",
        { "stucco.png", "big.png" });
    expect_failure_starting("--max-memory 250M big.png --pyramid:size=64x64 -o o.png",
        "texsyn ERROR: --pyramid : the analysis of the 1024x1024 sample would need about ",
        { "stucco.png", "big.png" });
    const CliRun r = texsyn("--max-memory 250M big.png --pyramid:size=64x64 -o o.png");
    EXPECT_NE(r.err.find(", of which the process holds "), std::string::npos) << r.err;
}

// Issue #34: the methods the determinism campaign had not covered give the same bits for a
// seed at 1, 2 and 4 threads, every file they write included (the fill's source map, each
// map of a material set, a bake).
TEST_F(Robustness, FillTileableMaterialAndSurfaceAreBitIdenticalAtOneTwoAndFourThreads)
{
    for (const char* name : { "bricks.png", "bricks_height.png", "flowers.png" })
        fs::copy_file(sample_path(name), dir / name);
    fs::copy_file(
        fs::path(TEXSYN_TEST_DATA).parent_path() / "meshes" / "torus_uv.obj", dir / "torus_uv.obj");
    ASSERT_EQ(shell("oiiotool --pattern constant:color=0 256x256 1 --box:color=1:fill=1 "
                    "90,100,170,150 -d uint8 -o hole.png")
                  .status,
        0);
    struct Run {
        std::string args;
        std::vector<std::string> files; // what it writes; {T} is the thread count
    };
    const Run runs[] = {
        { "bricks.png --fill:mask=hole.png:map=fillmap{T}.exr -d float -o fill{T}.exr",
            { "fill{T}.exr", "fillmap{T}.exr" } },
        { "stucco.png --tileable -d float -o tile{T}.exr", { "tile{T}.exr" } },
        { "bricks.png --material:height=bricks_height.png --patch:size=96x96:flatten=1 -d float "
          "-o mat{T}_{map}.exr",
            { "mat{T}_albedo.exr", "mat{T}_height.exr" } },
        { "flowers.png --choosy-surface:mesh=torus_uv.obj:levels=3:bake=64x64 -o surf{T}.ply -d "
          "float -o surf{T}.exr",
            { "surf{T}.ply", "surf{T}.exr" } },
    };
    auto with = [](std::string text, int threads) {
        for (size_t at = text.find("{T}"); at != std::string::npos; at = text.find("{T}", at))
            text.replace(at, 3, std::to_string(threads));
        return text;
    };
    for (const Run& run : runs)
        for (int threads : { 1, 2, 4 }) {
            const std::string args
                = "--seed 6 --threads " + std::to_string(threads) + " " + with(run.args, threads);
            const CliRun r = texsyn(args);
            ASSERT_EQ(r.status, 0) << args << ": " << r.err;
            if (threads == 1)
                continue;
            for (const std::string& file : run.files) {
                // Files carry the command line; pixels (and a PLY's bytes) must match.
                if (file.find(".ply") != std::string::npos) {
                    EXPECT_EQ(slurp(dir / with(file, 1)), slurp(dir / with(file, threads)))
                        << with(file, threads);
                    continue;
                }
                const OIIO::ImageBuf one((dir / with(file, 1)).string());
                const OIIO::ImageBuf other((dir / with(file, threads)).string());
                const auto c = OIIO::ImageBufAlgo::compare(one, other, 0.0f, 0.0f);
                EXPECT_FALSE(c.error) << with(file, threads);
                EXPECT_EQ(c.nfail, 0u) << with(file, threads) << " differs from 1 thread";
                EXPECT_EQ(one.spec().width, other.spec().width);
            }
        }
}
