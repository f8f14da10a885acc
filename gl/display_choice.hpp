#pragma once

// Which EGL display the headless context uses. The EGL code tries every
// candidate and describes each here; the choice itself is a pure function of
// those descriptions (no EGL or GL calls), so it is tested with faked
// candidates. On a GPU server with glvnd, Mesa's llvmpipe and the vendor's
// driver are both candidates and either may be listed first: a hardware
// renderer wins wherever it is listed.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace morphogen::gl {

// One EGL display tried for a 3.3 core context.
struct DisplayCandidate {
    std::string name;            // "device 1 /dev/dri/renderD128", "surfaceless", "default display"
    std::string renderer;        // GL_RENDERER, empty when no context could be made
    std::string vendor;          // GL_VENDOR
    bool device = false;         // an EGL device (one piece of hardware or Mesa's software one)
    bool softwareDevice = false; // the EGL device says so (EGL_MESA_device_software)
    std::string error;           // why it failed; empty when it works

    bool works() const { return error.empty(); }
    bool isSoftware() const;
};

// llvmpipe, softpipe, swrast: renderers on which the GPU path is slower than
// the CPU backend.
bool isSoftwareRendererName(const std::string& renderer);

// The environment variable that picks a candidate when no flag does.
constexpr const char* kGpuDeviceEnvVar = "MORPHOGEN_GPU_DEVICE";

// Reads a candidate number (a non-negative integer); `source` names where it
// came from ("--gpu-device", "MORPHOGEN_GPU_DEVICE"). Throws InputError.
int parseGpuDevice(const std::string& text, const std::string& source);

// What the user asked for: a candidate number and where it came from.
struct DeviceRequest {
    int index = 0;
    std::string source; // "--gpu-device" or the environment variable's name
};

struct DisplayChoice {
    std::size_t index = 0;
    // For the backend report: software was chosen while EGL devices not
    // known to be software failed (a GPU whose driver refused), naming them.
    // Empty otherwise.
    std::string note;
};

// The requested candidate if any (InputError when the number is out of range
// or that candidate failed, listing every candidate); else the first working
// hardware renderer, else the first working software one. Throws
// std::runtime_error listing every failure when none works.
DisplayChoice chooseDisplay(const std::vector<DisplayCandidate>& candidates,
                            const std::optional<DeviceRequest>& request);

// "0 device 0 /dev/dri/renderD128: NVIDIA H200 [NVIDIA Corporation]; 1 surfaceless: failed (...)"
std::string describeCandidates(const std::vector<DisplayCandidate>& candidates);

} // namespace morphogen::gl
