// Fuzz target: the command line. The input is the argument list, one argument
// per line (the program name is added). It is parsed by the real `morphogen`
// app: every command registered as app/cli/main.cpp registers it, stopped
// after the parse, so no command runs: the callbacks write and delete
// files (outputs, probes, frame folders), open GL contexts and simulate, none of
// which a fuzzer may do thousands of times a second with arbitrary paths.
//
// For `render`, the flags that edit the session are then applied as render
// applies them, through the same pure functions (preset, --param, the knob flags
// of knob_flags.hpp, the gradient flags, the settle flags, validateSession and
// the run's plan), reaching the JSON readers the flags go through. Flags that
// render parses in its own file (--size, --schedule, --levels) are reached by
// CLI11's parse only.
//
// Found and failed on: a crash, hang or sanitizer report, and an exception
// other than CLI11's parse errors and InputError (bad input is exit 2).

#include <cstdint>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <typeinfo>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/bench_command.hpp"
#include "cli/colour_flags.hpp"
#include "cli/commands.hpp"
#include "cli/knob_flags.hpp"
#include "cli/settle_flags.hpp"
#include "core/base/errors.hpp"
#include "core/output/colormap.hpp"
#include "core/output/frames.hpp"
#include "core/session/session.hpp"
#include "core/sim/segments.hpp"
#include "fuzz_support.hpp"

namespace {

using morphogen::InputError;
using morphogen::Session;
namespace bench = morphogen::bench;
namespace cli = morphogen::cli;
namespace fuzz = morphogen::fuzz;

std::string describe(const std::exception& e) {
    return std::string(typeid(e).name()) + ": " + e.what();
}

std::vector<std::string> splitLines(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> args(1);
    for (std::size_t i = 0; i < size; ++i) {
        if (data[i] == '\n')
            args.emplace_back();
        else
            args.back() += char(data[i]);
    }
    if (!args.empty() && args.back().empty())
        args.pop_back(); // a final newline ends the last argument
    return args;
}

// The app main.cpp builds, stopped after the parse: CLI11 calls pre_callback on
// the top-level app once every flag is parsed, converted and checked, before
// any command's callback runs (the callbacks keep their state alive; they are
// left as registered, just never called).
class ParseOnlyApp : public CLI::App {
public:
    struct Parsed {};
    using CLI::App::App;
    void pre_callback() override { throw Parsed{}; }
};

// Parses the whole app; returns the command that would have run ("" for none).
std::string parseApp(const std::vector<const char*>& argv) {
    ParseOnlyApp app{"Morphogen", "morphogen"};
    app.require_subcommand(1);
    cli::addRenderCommand(app);
    cli::addPresetsCommand(app);
    bench::addBenchCommand(app);
    cli::addPropagatorCommand(app);
    cli::addGalleryCommand(app);
    cli::addMapCommand(app);
    cli::addSweepCommand(app);
    cli::addColourCommand(app);
    cli::addMeshCommands(app);
    cli::addDesignCommand(app);
    cli::addCompletionCommand(app);
    try {
        app.parse(int(argv.size()), argv.data());
    } catch (const ParseOnlyApp::Parsed&) {
        const std::vector<CLI::App*> commands = app.get_subcommands();
        return commands.empty() ? "" : commands.front()->get_name();
    } catch (const CLI::Error&) {
        return ""; // help, parse errors: main.cpp prints them, exit 0 or 2
    } catch (const InputError&) {
        return "";
    } catch (const std::exception& e) {
        fuzz::fail("parsing threw " + describe(e) + " instead of a parse error or an InputError");
    }
    fuzz::fail("the parse ran past pre_callback: a command's callback may have run");
}

// loadPreset parses every embedded preset; the same name gives the same
// session, so keep the answers (bounded: fuzzed names are many).
std::optional<Session> preset(const std::string& name) {
    static std::map<std::string, std::optional<Session>> cache;
    const auto it = cache.find(name);
    if (it != cache.end())
        return it->second;
    std::optional<Session> s;
    try {
        s = morphogen::loadPreset(name);
    } catch (const InputError&) {
    }
    if (cache.size() < 256)
        cache.emplace(name, s);
    return s;
}

// render's session edits, in render's order, on the arguments after "render".
void renderSession(const std::vector<const char*>& argv) {
    CLI::App app{"render's session flags", "render"};
    app.allow_extras(); // render's other flags, already parsed above
    std::string presetName = "gs_coral", sessionFile, colormap, chemical;
    std::vector<std::string> params;
    app.add_option("--preset", presetName);
    app.add_option("--session", sessionFile);
    app.add_option("--param", params);
    app.add_option("--colormap", colormap);
    app.add_option("--chemical", chemical);
    cli::KnobFlags knobs;
    cli::addKnobFlags(app, knobs);
    cli::GradientFlags gradient;
    cli::addGradientFlags(app, gradient);
    cli::SettleFlags settle;
    cli::addSettleFlags(app, settle);
    try {
        app.parse(int(argv.size()), argv.data());
    } catch (const CLI::Error&) {
        return;
    }
    try {
        // A session file named on a fuzzed command line is whatever is on the
        // disk; the session reader has its own target.
        if (!sessionFile.empty())
            return;
        std::optional<Session> s = preset(presetName);
        if (!s)
            return;
        for (const std::string& p : params)
            morphogen::applyParamOverride(*s, p);
        (void)cli::applyKnobFlags(knobs, *s);
        if (!colormap.empty())
            s->colormap.name = colormap;
        if (!chemical.empty())
            s->colormap.chemical = chemical;
        cli::applyGradientFlags(gradient, colormap, s->colormap);
        (void)morphogen::colormapChemical(s->colormap, s->outputModel());
        morphogen::validateSession(*s, "fuzz");
        const cli::SettleRun run(settle, *s, true, false);
        (void)morphogen::segmentsOf(*s);
        (void)morphogen::describePlan(*s);
        (void)morphogen::sessionTotalSteps(*s);
    } catch (const InputError&) {
    } catch (const std::exception& e) {
        fuzz::fail("render's session flags threw " + describe(e) + " instead of an InputError");
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::vector<std::string> args = splitLines(data, size);
    std::vector<const char*> argv{"morphogen"};
    for (const std::string& a : args)
        argv.push_back(a.c_str());
    const std::string command = parseApp(argv);
    if (command == "render") {
        std::vector<const char*> renderArgv{"render"};
        bool seen = false;
        for (const std::string& a : args) {
            if (seen)
                renderArgv.push_back(a.c_str());
            seen = seen || a == "render";
        }
        renderSession(renderArgv);
    }
    return 0;
}
