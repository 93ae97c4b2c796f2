// SPDX-License-Identifier: Apache-2.0
// The method registry: every row is complete and consistent, option ranges are enforced
// through one path with one message shape, and run_method checks what every front end
// hands it.
#include <texsyn/choosy.h>
#include <texsyn/material.h>
#include <texsyn/memory.h>
#include <texsyn/methods.h>
#include <texsyn/pyramid_synthesis.h>
#include <texsyn/surface.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <set>
#include <thread>

#include <OpenImageIO/imagebufalgo.h>

#include <gtest/gtest.h>

#include "test_metrics.h"
#include "test_samples.h"

using namespace texsyn;

namespace {

// The text of a number just past an option's upper bound, as a user would type it.
std::string past_the_end(const OptionField& f)
{
    if (f.type == OptionType::Integer)
        return std::to_string(int64_t(f.hi) + 1);
    return format_number_list({ float(f.hi) + 1.0f });
}

bool ends_with(const std::string& s, const std::string& end)
{
    return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

// lo..hi as the messages write it.
std::string range_of(const OptionField& f)
{
    if (f.type == OptionType::Integer)
        return std::to_string(int64_t(f.lo)) + ".." + std::to_string(int64_t(f.hi));
    return format_number_list({ float(f.lo) }) + ".." + format_number_list({ float(f.hi) });
}

OIIO::ImageBuf grey_image(int w, int h)
{
    OIIO::ImageBuf image(OIIO::ImageSpec(w, h, 3, OIIO::TypeFloat));
    OIIO::ImageBufAlgo::noise(image, "uniform", 0.2f, 0.8f, false, 3);
    return image;
}

} // namespace

TEST(Methods, EveryRowIsComplete)
{
    std::set<std::string> names;
    for (const Method* m : methods()) {
        SCOPED_TRACE(m->name);
        EXPECT_TRUE(names.insert(m->name).second) << "two rows named " << m->name;
        EXPECT_EQ(find_method(m->name), m);
        EXPECT_FALSE(m->summary.empty());
        EXPECT_FALSE(m->help.empty());
        EXPECT_EQ(m->example.find("texsyn "), 0u) << m->example;
        EXPECT_NE(m->example.find("--" + m->name), std::string::npos) << m->example;
        EXPECT_TRUE(std::filesystem::exists(std::string(TEXSYN_SOURCE_DIR) + "/docs/" + m->doc))
            << m->doc;
        ASSERT_TRUE(m->defaults);
        ASSERT_TRUE(m->run);
        const MethodOptions defaults = m->defaults();
        std::string error;
        // The defaults are a working synthesis; a mix's mode must be chosen, the mesh a
        // texture grows on, and the mask of a fill.
        EXPECT_EQ(defaults.validate(error),
            m->name != "mix" && m->name != "choosy-surface" && m->name != "fill")
            << error;
        EXPECT_EQ(m->inputs == MethodInputs::Samples, bool(m->count));
        if (m->count) {
            EXPECT_GE(m->count(defaults), 2);
        }
        std::set<std::string> options;
        for (const OptionField& f : defaults.table().fields()) {
            EXPECT_TRUE(options.insert(f.name).second) << "option " << f.name << " twice";
            EXPECT_FALSE(f.help.empty()) << f.name;
            EXPECT_TRUE(f.parse && f.format && f.check) << f.name;
            // What an option writes, it reads back to the same text.
            MethodOptions copy = defaults;
            const std::string value = defaults.value(f.name);
            if (f.type != OptionType::InputFile && f.type != OptionType::OutputFile) {
                EXPECT_TRUE(copy.set(f.name, value, error))
                    << f.name << "=" << value << ": " << error;
                EXPECT_EQ(copy.value(f.name), value) << f.name;
            }
        }
    }
    EXPECT_EQ(find_method("quilting"), nullptr);
    // method_names() lists the rows that make recipes (images, volumes, UV bakes), in order.
    std::string recipes, all;
    for (const Method* m : methods()) {
        all += (all.empty() ? "" : "|") + m->name;
        if (m->output == MethodOutput::Image || m->output == MethodOutput::Volume
            || m->output == MethodOutput::Mesh)
            recipes += (recipes.empty() ? "" : "|") + m->name;
    }
    EXPECT_EQ(method_names(), recipes);
    EXPECT_EQ(method_names(true), all);
    EXPECT_EQ(recipes.find("analyze"), std::string::npos);
    EXPECT_EQ(recipes.find("check"), std::string::npos);
}

// Ranges are declared once, in the table, and enforced the same way for every option of
// every method: "name=value : out of range lo..hi", the value as typed.
TEST(Methods, EveryRangeIsCheckedWithOneMessageShape)
{
    int checked = 0;
    for (const Method* m : methods()) {
        const MethodOptions defaults = m->defaults();
        for (const OptionField& f : defaults.table().fields()) {
            if (f.type != OptionType::Integer && f.type != OptionType::Real)
                continue;
            MethodOptions o = defaults;
            std::string error;
            const std::string value = past_the_end(f);
            EXPECT_FALSE(o.set(f.name, value, error)) << m->name << " " << f.name;
            EXPECT_EQ(error, f.name + "=" + value + " : out of range " + range_of(f)) << m->name;
            EXPECT_EQ(o.value(f.name), defaults.value(f.name)) << "unchanged on failure";
            ++checked;
        }
    }
    EXPECT_GT(checked, 30);
}

// MethodOptions copies deeply: a recipe's options and the tool's are independent.
TEST(Methods, OptionsAreValues)
{
    MethodOptions a = find_method("choosy")->defaults();
    MethodOptions b = a;
    std::string error;
    ASSERT_TRUE(b.apply("levels=2:iterations=1,8", error)) << error;
    EXPECT_EQ(a.value("levels"), "4");
    EXPECT_EQ(b.value("levels"), "2");
    EXPECT_FALSE(b.apply("levels=3:levels=2", error));
    EXPECT_EQ(error, "levels=2 : given twice");
    EXPECT_EQ(b.format().find("size=0x0:levels=3:iterations=1,8:"), 0u) << b.format();
    EXPECT_EQ(b.format().find("map="), std::string::npos); // file options are not options text
    EXPECT_TRUE(MethodOptions().format().empty());

    // The method's struct is reachable through a row that adds file options (map=).
    ChoosyOptions* choosy = b.get<ChoosyOptions>();
    ASSERT_NE(choosy, nullptr);
    EXPECT_EQ(std::to_string(choosy->levels), b.value("levels"));
    choosy->levels = 5;
    EXPECT_EQ(b.value("levels"), "5");
    EXPECT_EQ(b.get<PyramidOptions>(), nullptr);
}

TEST(Methods, InputsAreCountedFromTheRowAndTheOptions)
{
    const MethodOptions none;
    EXPECT_EQ(find_method("cascade")->input_count(none, 0), 0);
    EXPECT_EQ(find_method("cascade")->input_count(none, 3), 1);
    EXPECT_EQ(find_method("pyramid")->input_count(none, 3), 1);
    EXPECT_EQ(find_method("transfer")->input_count(none, 3), 2);
    MethodOptions mix = find_method("mix")->defaults();
    std::string error;
    ASSERT_TRUE(mix.set("weights", "1,1,1", error)) << error;
    EXPECT_EQ(find_method("mix")->input_count(mix, 5), 3);
    EXPECT_TRUE(find_method("pyramid")->accepts_analysis(0));
    EXPECT_FALSE(find_method("transfer")->accepts_analysis(0));
    EXPECT_TRUE(find_method("transfer")->accepts_analysis(1));
    EXPECT_FALSE(find_method("choosy")->accepts_analysis(0));
}

// A run's memory budget (RunSettings::max_memory) is its own: it refuses work needing
// more than the budget, and admits work within it even where the process-wide limit, less
// what the process (a host) holds, leaves nothing.
TEST(Methods, ARunsMemoryBudgetIsItsOwnWhateverTheProcessHolds)
{
    const OIIO::ImageBuf image = grey_image(64, 64);
    const Method& pyramid = *find_method("pyramid");
    std::string error;
    MethodOptions large = pyramid.defaults(), small = pyramid.defaults();
    ASSERT_TRUE(large.apply("size=4096x4096", error)) << error;
    ASSERT_TRUE(small.apply("size=64x64", error)) << error;
    const std::vector<MethodInput> inputs { { &image, nullptr, "a.png" } };
    RunSettings budget;
    budget.max_memory = size_t(64) << 20;
    MethodResult result;
    EXPECT_FALSE(run_method(pyramid, large, inputs, {}, budget, result, error));
    EXPECT_NE(error.find("this run's budget is 64.0 MB"), std::string::npos) << error;

    // The process-wide limit below what the process holds refuses everything, but not a
    // run with a budget of its own.
    set_memory_limit(size_t(1) << 20);
    EXPECT_FALSE(run_method(pyramid, small, inputs, {}, {}, result, error));
    EXPECT_NE(error.find("of which the process holds"), std::string::npos) << error;
    EXPECT_TRUE(run_method(pyramid, small, inputs, {}, budget, result, error)) << error;
    // The budget ended with its run.
    EXPECT_FALSE(check_memory(size_t(2) << 20, "after the run", error));
    set_memory_limit(0);
}

// run_method checks options, inputs and files for every front end before the row runs.
TEST(Methods, RunMethodChecksWhatItIsGiven)
{
    const OIIO::ImageBuf image = grey_image(64, 64);
    const TextureStatistics analysis;
    const Method& choosy = *find_method("choosy");
    MethodOptions options = choosy.defaults();
    std::string error;
    ASSERT_TRUE(options.apply("size=16x16:levels=2", error)) << error;
    MethodResult result;
    EXPECT_FALSE(run_method(choosy, options, {}, {}, {}, result, error));
    EXPECT_EQ(error, "choosy takes 1 input, got 0");
    EXPECT_FALSE(
        run_method(choosy, options, { { nullptr, &analysis, "a.tsa" } }, {}, {}, result, error));
    EXPECT_EQ(
        error, "a.tsa is an analysis, not an image (choosy needs the image it was made from)");
    MethodOptions bad = options;
    ASSERT_TRUE(bad.set("levels", "3", error));
    ASSERT_TRUE(bad.set("iterations", "1,1,1", error));
    ASSERT_TRUE(bad.set("levels", "2", error));
    EXPECT_FALSE(run_method(choosy, bad, { { &image, nullptr, "a.png" } }, {}, {}, result, error));
    EXPECT_EQ(error, "iterations=1,1,1 : 3 values for levels=2 (give 1..2)");
    ASSERT_TRUE(
        run_method(choosy, options, { { &image, nullptr, "maps/a.png" } }, {}, {}, result, error))
        << error;
    EXPECT_EQ(result.image.spec().width, 16);
    EXPECT_EQ(result.image.spec().get_string_attribute("synth:sample"), "a.png");

    const Method& cascade = *find_method("cascade");
    MethodOptions controlled = cascade.defaults();
    ASSERT_TRUE(controlled.apply("size=16x16:dilation=ctrl.exr", error)) << error;
    EXPECT_FALSE(run_method(cascade, controlled, {}, {}, {}, result, error));
    EXPECT_EQ(error, "dilation=ctrl.exr : the file was not read");
    OptionImages files;
    files["dilation"] = grey_image(8, 8);
    EXPECT_FALSE(run_method(cascade, controlled, {}, files, {}, result, error));
    EXPECT_EQ(error, "dilation=ctrl.exr : the control image has 3 channels; expected 1");
}

// A material set goes through run_method like any input: every row that copies pixels moves
// each map of the set by the one source map of its run, so a map made from the albedo's
// red channel is still exactly that channel of the synthesized albedo. (Rows that keep
// their image's size and need an option file, fill with its mask=, are run by their own
// tests.)
TEST(Methods, EveryCopyingRowMovesEveryMapOfAMaterialSetTogether)
{
    Material set;
    set.maps.push_back(
        { "albedo", MapKind::Colour, 1.0f, test::linear_crop("bricks.png", 128, 128) });
    set.maps.push_back({ "height", MapKind::Data, 0.0f,
        OIIO::ImageBufAlgo::channels(set.maps[0].image, 1, { 0 }) });
    int ran = 0;
    for (const Method* m : methods()) {
        if (!m->copies_pixels)
            continue;
        MethodOptions options = m->defaults();
        std::string error;
        if (!options.set("size", "144x128", error) || !options.validate(error))
            continue;
        RunSettings settings;
        settings.seed = 3;
        MethodResult result;
        ASSERT_TRUE(run_method(
            *m, options, { { nullptr, nullptr, "bricks.png", &set } }, {}, settings, result, error))
            << m->name << ": " << error;
        ASSERT_TRUE(result.material) << m->name;
        ASSERT_EQ(result.material->maps.size(), 2u) << m->name;
        const OIIO::ImageBuf& albedo = result.material->maps[0].image;
        const OIIO::ImageBuf& height = result.material->maps[1].image;
        EXPECT_EQ(result.material->maps[1].name, "height");
        ASSERT_EQ(albedo.spec().width, 144) << m->name;
        ASSERT_EQ(height.spec().height, 128) << m->name;
        EXPECT_EQ(result.image.spec().width, 144) << m->name << ": the image is the albedo";
        int differ = 0;
        for (OIIO::ImageBuf::ConstIterator<float> a(albedo), h(height); !a.done(); ++a, ++h)
            differ += a[0] != h[0];
        EXPECT_EQ(differ, 0) << m->name << ": the height moved apart from the albedo";
        ++ran;
    }
    EXPECT_GE(ran, 3);
}

// Only a row that copies pixels takes a material set, and then as its only input; an input
// is exactly one thing.
TEST(Methods, AMaterialSetGoesOnlyToACopyingRowAndAlone)
{
    Material set;
    set.maps.push_back({ "albedo", MapKind::Colour, 1.0f, grey_image(32, 32) });
    const OIIO::ImageBuf image = grey_image(32, 32);
    const Method& pyramid = *find_method("pyramid");
    MethodOptions options = pyramid.defaults();
    std::string error;
    ASSERT_TRUE(options.set("size", "32x32", error)) << error;
    MethodResult result;
    EXPECT_FALSE(
        run_method(pyramid, options, { { nullptr, nullptr, "set", &set } }, {}, {}, result, error));
    EXPECT_EQ(error,
        "set is a material set; " + command_list(&Method::copies_pixels, "", "")
            + " synthesize one, one set at a time");
    const Method& patch = *find_method("patch");
    EXPECT_FALSE(run_method(
        patch, patch.defaults(), { { &image, nullptr, "both", &set } }, {}, {}, result, error));
    EXPECT_EQ(error, "input 0 (both) must be one of an image, an analysis or a material set");
}

// A row copies pixels exactly when it writes their source map (an output-file option map=):
// the flag is what the front ends ask, the option what users give.
TEST(Methods, ARowCopiesPixelsExactlyWhenItWritesASourceMap)
{
    for (const Method* m : methods()) {
        const OptionField* map = m->defaults().table().find("map");
        EXPECT_EQ(m->copies_pixels, map && map->file == FileUse::Write) << m->name;
    }
}

// Messages list commands from the rows: those that copy pixels write source maps (cascade's
// map= is a parameter, not a file it writes), and the list reads as a sentence.
TEST(Methods, CommandListsComeFromTheRows)
{
    EXPECT_EQ(command_list(&Method::copies_pixels, ":map="),
        "--neighborhood:map=, --choosy:map=, --patch:map= and --fill:map=");
    EXPECT_FALSE(find_method("cascade")->copies_pixels);
    EXPECT_EQ(command_list([](const Method& m) { return m.name == "check"; }), "--check");
    EXPECT_EQ(command_list([](const Method&) { return false; }), "");
}

// Each row's output kind: a volume is a 3-D image, an analysis its statistics, a report
// text; a transfer names its image apart.
TEST(Methods, RowsGiveWhatTheySay)
{
    const OIIO::ImageBuf image = grey_image(32, 32);
    std::string error;
    MethodResult result;
    MethodOptions solid = find_method("solid")->defaults();
    ASSERT_TRUE(solid.apply("size=16x16x8:iterations=1", error)) << error;
    ASSERT_TRUE(run_method(
        *find_method("solid"), solid, { { &image, nullptr, "s.png" } }, {}, {}, result, error))
        << error;
    EXPECT_EQ(result.image.spec().depth, 8);

    result = MethodResult();
    ASSERT_TRUE(run_method(*find_method("analyze"), find_method("analyze")->defaults(),
        { { &image, nullptr, "dir/s.png" } }, {}, {}, result, error))
        << error;
    ASSERT_TRUE(result.analysis);
    EXPECT_EQ(result.analysis->source, "s.png");

    result = MethodResult();
    ASSERT_TRUE(run_method(*find_method("check"), find_method("check")->defaults(),
        { { &image, nullptr, "s.png" } }, {}, {}, result, error))
        << error;
    EXPECT_EQ(result.report.find("s.png (32x32)\n"), 0u) << result.report;

    result = MethodResult();
    MethodOptions transfer = find_method("transfer")->defaults();
    ASSERT_TRUE(transfer.set("iterations", "1", error));
    ASSERT_TRUE(run_method(*find_method("transfer"), transfer,
        { { &image, nullptr, "photo.png" }, { &image, nullptr, "rust.png" } }, {}, {}, result,
        error))
        << error;
    EXPECT_EQ(result.image.spec().get_string_attribute("synth:image"), "photo.png");
    EXPECT_EQ(result.image.spec().get_string_attribute("synth:sample"), "rust.png");
}

namespace {

// One run of a row for the generic tests below: its options and how many copies of the
// test image it takes.
struct Case {
    const char* method;
    std::string options;
    int inputs;
    int side = 96; ///< of the test image (and of fill's mask)
};

// Every row that synthesizes, with options that run in well under a second.
std::vector<Case> synthesis_cases()
{
    return {
        { "pyramid", "size=64x64:iterations=3", 1 },
        { "solid", "size=16x16x16:iterations=2", 1 },
        { "mix", "size=64x64:iterations=2:palette=0:pattern=1", 2 },
        { "transfer", "iterations=2", 2 },
        { "neighborhood", "size=48x48:levels=2", 1 },
        { "choosy", "size=48x48:levels=2", 1 },
        { "choosy-surface",
            "mesh=" + std::string(TEXSYN_TEST_DATA) + "/../meshes/sphere.obj:levels=2:remesh=0",
            1 },
        { "patch", "size=96x96", 1 },
        { "fill", "mask=hole.exr:patch=7,5", 1 },
        { "tileable", "patch=7,5", 1 },
        { "cascade", "size=64x64", 0 },
    };
}

// The rows the generic run tests leave out, and why: they measure or describe a sample
// rather than synthesize (no progress to stop, nothing to compare), or only hand their maps
// to the copying method after them.
const std::set<std::string> kNotSyntheses = { "analyze", "check", "material" };

// What running a case needs: its inputs and option images (fill's mask: a square hole of
// a sixth of the side in the middle).
struct CaseRun {
    OIIO::ImageBuf image;
    OptionImages files;
    std::vector<MethodInput> inputs;
    MethodOptions options;

    bool prepare(const Case& c, std::string& error)
    {
        image = grey_image(c.side, c.side);
        OIIO::ImageBuf mask(OIIO::ImageSpec(c.side, c.side, 1, OIIO::TypeFloat));
        const float one = 1.0f;
        const int h0 = c.side * 5 / 12, h1 = c.side * 7 / 12;
        OIIO::ImageBufAlgo::fill(mask, &one, OIIO::ROI(h0, h1, h0, h1));
        if (std::string(c.method) == "fill")
            files["mask"] = mask;
        inputs.assign(size_t(c.inputs), { &image, nullptr, "s.png" });
        options = find_method(c.method)->defaults();
        return options.apply(c.options, error);
    }
};

// A run's result as bits: its image's pixels, or its surface's face colours.
std::string result_bits(const MethodResult& result)
{
    if (result.surface) {
        std::string bits;
        for (const std::vector<float>& channel : result.surface->colours)
            bits.append(
                reinterpret_cast<const char*>(channel.data()), channel.size() * sizeof(float));
        return bits;
    }
    std::vector<float> pixels(
        size_t(result.image.spec().image_pixels()) * size_t(result.image.nchannels()));
    result.image.get_pixels(OIIO::ROI::All(), OIIO::TypeFloat, pixels.data());
    return std::string(reinterpret_cast<const char*>(pixels.data()), pixels.size() * sizeof(float));
}

} // namespace

// The generic run tests below cover every row of the registry: a new row fails here until
// it has a case (or a reason to be left out).
TEST(Methods, EveryRowHasARunCase)
{
    std::set<std::string> covered(kNotSyntheses);
    for (const Case& c : synthesis_cases()) {
        ASSERT_NE(find_method(c.method), nullptr) << c.method;
        covered.insert(c.method);
    }
    for (const Method* m : methods())
        EXPECT_TRUE(covered.count(m->name)) << m->name << " has no case in synthesis_cases()";
}

// A stop flag (stop.h) ends every synthesis at its next step: set from the first progress
// report, the run fails with "…: stopped" (the method's function names itself) and reports
// nothing more. Set before the run, it never reports progress at all.
TEST(Methods, AStopFlagEndsEveryRunAtItsNextStep)
{
    for (const Case& c : synthesis_cases()) {
        SCOPED_TRACE(c.method);
        const Method& method = *find_method(c.method);
        CaseRun run;
        std::string error;
        ASSERT_TRUE(run.prepare(c, error)) << error;

        StopFlag stop { false };
        int reports = 0;
        RunSettings settings;
        settings.stop = &stop;
        settings.progress = [&](float) {
            ++reports;
            stop = true;
        };
        MethodResult result;
        EXPECT_FALSE(
            run_method(method, run.options, run.inputs, run.files, settings, result, error));
        EXPECT_TRUE(ends_with(error, ": stopped")) << error;
        EXPECT_EQ(reports, 1);

        reports = 0;
        EXPECT_FALSE(
            run_method(method, run.options, run.inputs, run.files, settings, result, error));
        EXPECT_TRUE(ends_with(error, ": stopped")) << error;
        EXPECT_EQ(reports, 0);

        // Unset, the same run completes.
        stop = false;
        settings.progress = {};
        EXPECT_TRUE(run_method(method, run.options, run.inputs, run.files, settings, result, error))
            << error;
    }
}

// Every synthesis row at a size that runs for several seconds (the test image `side`
// pixels square where the output is the input's size).
std::vector<Case> long_cases()
{
    return {
        { "pyramid", "size=2048x2048", 1 },
        { "solid", "size=128x128x128", 1 },
        { "mix", "size=1024x1024:palette=0:pattern=1", 2 },
        { "transfer", "iterations=8", 2, 1024 },
        { "neighborhood", "size=2048x2048", 1 },
        { "choosy", "size=512x512", 1 },
        { "choosy-surface",
            "mesh=" + std::string(TEXSYN_TEST_DATA) + "/../meshes/sphere.obj:levels=4", 1 },
        { "patch", "size=2048x2048", 1 },
        { "fill", "mask=hole.exr", 1, 2048 },
        { "tileable", "", 1, 4096 },
        { "cascade", "size=8192x8192", 0 },
    };
}

// stop.h's promise: a run ends within about a second of its stop flag being set, at any
// size and at any point. Each row runs on a thread of its own and is stopped twice: 50 ms
// after it starts (in its preparation: reading, analysis, setting up) and 300 ms after its
// first progress report (in its main loop). It must end with "stopped" within 1.5 s.
// (A timing bound: ctest runs it alone (tests/CMakeLists.txt), and it is left out of the
// sanitizer builds, which run several times slower.)
TEST(Methods, StopLatencyIsAboutASecondForEveryRow)
{
    using Clock = std::chrono::steady_clock;
    using std::chrono::milliseconds;
    std::set<std::string> covered(kNotSyntheses);
    for (const Case& c : long_cases()) {
        covered.insert(c.method);
        CaseRun run;
        std::string error;
        ASSERT_TRUE(run.prepare(c, error)) << error;
        for (const bool after_progress : { false, true }) {
            SCOPED_TRACE(std::string(c.method) + (after_progress ? ", in its loop" : ", early"));
            StopFlag stop { false };
            std::atomic<bool> reported { false };
            RunSettings settings;
            settings.stop = &stop;
            settings.progress = [&](float) { reported = true; };
            MethodResult result;
            bool ok = true;
            Clock::time_point ended;
            std::thread runner([&] {
                ok = run_method(*find_method(c.method), run.options, run.inputs, run.files,
                    settings, result, error);
                ended = Clock::now();
            });
            const Clock::time_point limit = Clock::now() + std::chrono::seconds(60);
            while (after_progress && !reported && Clock::now() < limit)
                std::this_thread::sleep_for(milliseconds(5));
            std::this_thread::sleep_for(milliseconds(after_progress ? 300 : 50));
            const Clock::time_point stopped = Clock::now();
            stop = true;
            runner.join();
            EXPECT_FALSE(ok) << "the run ended before it was stopped: make the case longer";
            EXPECT_TRUE(ends_with(error, ": stopped")) << error;
            const double latency = std::chrono::duration<double>(ended - stopped).count();
            test::doc_number(
                std::string("stop.") + c.method + (after_progress ? ".loop_ms" : ".early_ms"),
                1000.0 * latency, 0);
            EXPECT_LT(latency, 1.5);
        }
    }
    for (const Method* m : methods())
        EXPECT_TRUE(covered.count(m->name)) << m->name << " has no case in long_cases()";
}

// Runs of different methods in one process, at once on their own threads, give the bits
// each gives run alone: no method keeps state another run can see.
TEST(Methods, ConcurrentRunsGiveTheBitsOfRunsAlone)
{
    const std::vector<Case> cases = synthesis_cases();
    std::vector<CaseRun> runs(cases.size());
    std::vector<std::string> alone(cases.size()), together(cases.size()), errors(cases.size());
    for (size_t i = 0; i < cases.size(); ++i) {
        ASSERT_TRUE(runs[i].prepare(cases[i], errors[i])) << errors[i];
        MethodResult result;
        ASSERT_TRUE(run_method(*find_method(cases[i].method), runs[i].options, runs[i].inputs,
            runs[i].files, {}, result, errors[i]))
            << cases[i].method << ": " << errors[i];
        alone[i] = result_bits(result);
        ASSERT_FALSE(alone[i].empty()) << cases[i].method;
    }
    std::vector<std::thread> threads;
    for (size_t i = 0; i < cases.size(); ++i)
        threads.emplace_back([&, i] {
            MethodResult result;
            RunSettings settings;
            settings.nthreads = 1;
            if (run_method(*find_method(cases[i].method), runs[i].options, runs[i].inputs,
                    runs[i].files, settings, result, errors[i]))
                together[i] = result_bits(result);
        });
    for (std::thread& t : threads)
        t.join();
    for (size_t i = 0; i < cases.size(); ++i)
        EXPECT_TRUE(together[i] == alone[i]) << cases[i].method << " " << errors[i];
}
