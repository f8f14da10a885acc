#include "gl/display_choice.hpp"

#include <stdexcept>

#include "core/base/errors.hpp"

namespace morphogen::gl {

bool isSoftwareRendererName(const std::string& renderer) {
    for (const char* name : {"llvmpipe", "softpipe", "swrast"})
        if (renderer.find(name) != std::string::npos)
            return true;
    return false;
}

bool DisplayCandidate::isSoftware() const {
    return softwareDevice || isSoftwareRendererName(renderer);
}

int parseGpuDevice(const std::string& text, const std::string& source) {
    const std::string accepted = " is not a display candidate number (accepted: 0, 1, 2, ...; "
                                 "the backend report and a wrong number list the candidates)";
    if (text.empty() || text.size() > 6 ||
        text.find_first_not_of("0123456789") != std::string::npos)
        throw InputError(source + " '" + text + "'" + accepted);
    return std::stoi(text);
}

std::string describeCandidates(const std::vector<DisplayCandidate>& candidates) {
    std::string out;
    for (std::size_t i = 0; i < candidates.size(); ++i) {
        const DisplayCandidate& c = candidates[i];
        if (i > 0)
            out += "; ";
        out += std::to_string(i) + " " + c.name + ": ";
        if (!c.works())
            out += "failed (" + c.error + ")";
        else
            out += c.renderer + " [" + c.vendor + (c.isSoftware() ? ", software" : "") + "]";
    }
    return out;
}

namespace {

// Failed candidates; `gpusOnly`: only EGL devices that may be GPUs (the
// surfaceless and default displays failing is normal on a headless machine).
std::string failures(const std::vector<DisplayCandidate>& candidates, bool gpusOnly) {
    std::string out;
    for (const DisplayCandidate& c : candidates)
        if (!c.works() && !(gpusOnly && (!c.device || c.softwareDevice)))
            out += (out.empty() ? "" : "; ") + c.name + ": " + c.error;
    return out;
}

} // namespace

DisplayChoice chooseDisplay(const std::vector<DisplayCandidate>& candidates,
                            const std::optional<DeviceRequest>& request) {
    if (request) {
        const std::string what = request->source + " " + std::to_string(request->index);
        if (candidates.empty())
            throw InputError(what + ": no EGL display candidate was found");
        if (request->index < 0 || std::size_t(request->index) >= candidates.size())
            throw InputError(what + " is out of range (accepted: 0.." +
                             std::to_string(candidates.size() - 1) +
                             "; candidates: " + describeCandidates(candidates) + ")");
        const DisplayCandidate& c = candidates[std::size_t(request->index)];
        if (!c.works())
            throw InputError(what + " (" + c.name + ") gives no OpenGL 3.3 core context: " +
                             c.error + " (candidates: " + describeCandidates(candidates) + ")");
        return {std::size_t(request->index), ""};
    }
    for (std::size_t i = 0; i < candidates.size(); ++i)
        if (candidates[i].works() && !candidates[i].isSoftware())
            return {i, ""};
    for (std::size_t i = 0; i < candidates.size(); ++i)
        if (candidates[i].works()) {
            // A failed device that was not known to be software may have been
            // the GPU: say why it was passed over.
            const std::string failed = failures(candidates, true);
            return {i, failed.empty() ? "" : "no hardware renderer; failed: " + failed};
        }
    if (candidates.empty())
        throw std::runtime_error("no EGL display found");
    throw std::runtime_error("no EGL display gives an OpenGL 3.3 core context: " +
                             failures(candidates, false));
}

} // namespace morphogen::gl
