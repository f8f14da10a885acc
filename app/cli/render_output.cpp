#include "cli/render_output.hpp"

#include <algorithm>
#include <cstdio>

#include "core/output/colormap.hpp"
#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/sim/runner.hpp"
#include "core/sim/stability_check.hpp"

namespace morphogen::cli {

void checkStability(Session& session, bool verbose) {
    const StabilityReport report = checkSessionStability(session, verbose);
    for (const StabilityNote& note : report.notes)
        std::fprintf(stderr, "morphogen: %s%s\n", note.warning ? "warning: " : "",
                     note.text.c_str());
    if (report.refused)
        throw InputError(*report.refused);
}

int runChunk(const Session& session) {
    return std::max(50, std::min(500, int(4e7 / double(session.width * session.height))));
}

void writeRenderOutput(const RunResult& result, const std::string& imagePath,
                       const std::string& sessionPath, int bitDepth) {
    const Session& session = result.completed;
    const ReactionModel& model = session.outputModel(); // the final state's
    if (imageFormatForPath(imagePath) == ImageFormat::Exr) {
        std::vector<std::string> names;
        for (const ChemicalSpec& c : model.chemicals())
            names.push_back(c.name);
        writeRawImage(imagePath, result.state, names);
    } else {
        const int chemical = colormapChemical(session.colormap, model);
        writeRgbImage(imagePath, applyColormap(result.state, chemical, session.colormap),
                      session.width, session.height, bitDepth);
    }
    saveSessionFile(session, sessionPath);
}

} // namespace morphogen::cli
