// morphogen: reaction-diffusion texture designer, command line.

#include <cstdio>
#include <exception>
#include <new>
#include <string>

#include "bench/bench_command.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/base/memory_budget.hpp"

int main(int argc, char** argv) {
    morphogen::cli::tuneOpenMpForTheDesigner(argc, argv);
    morphogen::cli::installSignalHandlers(); // an interrupted write leaves no temporaries
    CLI::App app{"Morphogen: reaction-diffusion textures (Turing, Gray-Scott) on the GPU or CPU",
                 "morphogen"};
    // CLI11 answers --version before it asks for a subcommand.
    app.set_version_flag("--version", std::string("morphogen ") + MORPHOGEN_VERSION);
    app.require_subcommand(1);
    using namespace morphogen;
    app.footer("Limits: grid side " + std::to_string(kMaxGridSide) + ", " +
               std::to_string(kMaxSteps) + " steps per run, " + std::to_string(kMaxStages) +
               " stages, " + std::to_string(kMaxScheduleLevels) + " schedule levels, " +
               std::to_string(kMaxSweepTiles) + " sweep tiles, images up to " +
               std::to_string(kMaxImageSide) + " pixels per side, JSON files up to 16 MiB and " +
               std::to_string(kMaxJsonDepth) + " levels deep (README.md, Limits).");
    morphogen::cli::addRenderCommand(app);
    morphogen::cli::addPresetsCommand(app);
    morphogen::bench::addBenchCommand(app);
    morphogen::cli::addPropagatorCommand(app);
    morphogen::cli::addGalleryCommand(app);
    morphogen::cli::addMapCommand(app);
    morphogen::cli::addSweepCommand(app);
    morphogen::cli::addColourCommand(app);
    morphogen::cli::addMeshCommands(app);
    morphogen::cli::addTileStatsCommand(app);
    morphogen::cli::addDesignCommand(app);
    morphogen::cli::addCompletionCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // Unknown flags, missing values and the like are bad input.
        app.exit(e);
        return 2;
    } catch (const morphogen::InputError& e) {
        std::fprintf(stderr, "morphogen: error: %s\n", e.what());
        return 2;
    } catch (const std::bad_alloc&) {
        // The estimate up front (memory_budget.hpp) counts only the state;
        // what else a run allocates can still fail: say what was running.
        const std::string what = morphogen::currentWorkload();
        const std::string left = [] {
            const auto bytes = morphogen::allocatableBytes();
            return bytes ? morphogen::formatBytes(*bytes) : std::string("unknown");
        }();
        std::fprintf(stderr,
                     "morphogen: error: out of memory%s (this process may still allocate %s: "
                     "see ulimit -v and the memory available); use a smaller size\n",
                     what.empty() ? "" : (" running " + what).c_str(), left.c_str());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "morphogen: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
