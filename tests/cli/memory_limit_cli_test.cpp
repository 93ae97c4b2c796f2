// SPDX-License-Identifier: Apache-2.0
// --max-memory for every method (issue #34): a run under a limit either is refused before
// the work, naming what it would need, or stays within the limit. Each method is run at a
// size that fits and one that does not, and the peak resident memory of the process is
// measured (wait4's maximum resident set, which includes every descendant).
#include <cstdio>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_fixture.h"

namespace {

constexpr size_t kLimitMb = 400;

struct PeakRun {
    int status = -1;
    size_t peak_mb = 0;
    std::string err;
};

} // namespace

class MemoryLimit : public Cli {
protected:
    // `texsyn --max-memory 400M ARGS` in the test folder, with its peak memory.
    PeakRun run_measured(const std::string& args)
    {
        const std::string cmd = "cd " + quote(dir.string()) + " && exec " + quote(TEXSYN_EXE)
            + " --max-memory " + std::to_string(kLimitMb) + "M " + args + " 2> stderr.txt";
        PeakRun r;
        const pid_t pid = ::fork();
        if (pid == 0) {
            ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
            ::_exit(127);
        }
        int status = 0;
        struct rusage usage { };
        if (pid < 0 || ::wait4(pid, &status, 0, &usage) != pid)
            return r;
        r.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        r.peak_mb = size_t(usage.ru_maxrss) / 1024; // kilobytes on Linux
        r.err = slurp(dir / "stderr.txt");
        return r;
    }

    // `fits` runs within the limit; `too_large` is refused with an estimate, before the
    // work (well within the limit too).
    void expect_kept(const std::string& fits, const std::string& too_large)
    {
        const PeakRun ok = run_measured(fits);
        EXPECT_EQ(ok.status, 0) << fits << ": " << ok.err;
        EXPECT_LE(ok.peak_mb, kLimitMb) << fits;
        std::printf("peak %zu MB under %zu MB: %s\n", ok.peak_mb, kLimitMb, fits.c_str());
        const PeakRun refused = run_measured(too_large);
        EXPECT_EQ(refused.status, 1) << too_large << ": " << refused.err;
        EXPECT_NE(refused.err.find(" of memory (only "), std::string::npos)
            << too_large << ": " << refused.err;
        EXPECT_LE(refused.peak_mb, kLimitMb) << too_large;
    }
};

TEST_F(MemoryLimit, EveryMethodIsRefusedOrStaysWithinTheLimit)
{
    ASSERT_EQ(shell("oiiotool stucco.png --resize 1024x1024 -o plate1k.png && oiiotool "
                    "stucco.png --resize 512x512 -o plate512.png && oiiotool "
                    "stucco.png --resize 4096x4096 -o plate4k.png && oiiotool --pattern "
                    "constant:color=0 1024x1024 1 --box:color=1:fill=1 400,400,560,520 -d uint8 "
                    "-o mask1k.png && oiiotool --pattern constant:color=0 4096x4096 1 "
                    "--box:color=1:fill=1 1200,1200,2800,2400 -d uint8 -o mask4k.png")
                  .status,
        0);
    fs::copy_file(sample_path("rust.png"), dir / "rust.png");
    fs::copy_file(
        fs::path(TEXSYN_TEST_DATA).parent_path() / "meshes" / "torus_uv.obj", dir / "torus_uv.obj");
    // Each method at a size that fits and one that does not (the second's outputs: -o out.exr).
    const std::pair<std::string, std::string> runs[] = {
        { "stucco.png --pyramid:size=1024x1024", "stucco.png --pyramid:size=4096x4096" },
        { "stucco.png --patch:size=1024x1024", "stucco.png --patch:size=8192x8192" },
        { "stucco.png --neighborhood:size=256x256", "stucco.png --neighborhood:size=8192x8192" },
        { "stucco.png --choosy:size=256x256", "stucco.png --choosy:size=8192x8192" },
        { "--cascade:size=1024x1024", "--cascade:size=8192x8192" },
        { "stucco.png --solid:size=64x64x64", "stucco.png --solid:size=512x512x512" },
        { "stucco.png rust.png --mix:weights=1,1:size=1024x1024",
            "stucco.png rust.png --mix:weights=1,1:size=4096x4096" },
        { "plate1k.png --fill:mask=mask1k.png", "plate4k.png --fill:mask=mask4k.png" },
        { "plate512.png --tileable", "plate4k.png --tileable" },
        { "stucco.png --choosy-surface:mesh=torus_uv.obj:levels=3:bake=1024x1024 -o t.ply",
            "stucco.png --choosy-surface:mesh=torus_uv.obj:levels=3:bake=8192x8192 -o t.ply" },
    };
    for (const auto& [fits, too_large] : runs)
        expect_kept(fits + " -o out.exr", too_large + " -o out.exr");
}
