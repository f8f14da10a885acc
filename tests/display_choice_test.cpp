// The EGL display choice over faked candidates: no EGL or GL here.

#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "gl/display_choice.hpp"

using namespace morphogen;
using gl::DeviceRequest;
using gl::DisplayCandidate;

namespace {

DisplayCandidate working(const std::string& name, const std::string& renderer,
                         const std::string& vendor, bool softwareDevice = false) {
    DisplayCandidate c;
    c.name = name;
    c.device = name.rfind("device", 0) == 0;
    c.renderer = renderer;
    c.vendor = vendor;
    c.softwareDevice = softwareDevice;
    return c;
}

DisplayCandidate failed(const std::string& name, const std::string& error,
                        bool softwareDevice = false) {
    DisplayCandidate c;
    c.name = name;
    c.device = name.rfind("device", 0) == 0;
    c.softwareDevice = softwareDevice;
    c.error = error;
    return c;
}

const DisplayCandidate kLlvmpipe =
    working("surfaceless", "llvmpipe (LLVM 15.0.6, 256 bits)", "Mesa");
const DisplayCandidate kNvidia =
    working("device 1 /dev/dri/renderD128", "NVIDIA H200/PCIe/SSE2", "NVIDIA Corporation");

// The message of the exception `f` throws, or a failure if it throws none of type E.
template <class E, class F> std::string messageOf(F f) {
    try {
        f();
    } catch (const E& e) {
        return e.what();
    }
    ADD_FAILURE() << "no exception of the expected type";
    return "";
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

TEST(DisplayChoice, SoftwareRenderersAreRecognisedByNameOrDevice) {
    EXPECT_TRUE(gl::isSoftwareRendererName("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_TRUE(gl::isSoftwareRendererName("softpipe"));
    EXPECT_TRUE(gl::isSoftwareRendererName("Mesa X11 swrast"));
    EXPECT_FALSE(gl::isSoftwareRendererName("NVIDIA H200/PCIe/SSE2"));
    EXPECT_FALSE(gl::isSoftwareRendererName("AMD Radeon RX 7900 (radeonsi, navi31)"));
    EXPECT_TRUE(kLlvmpipe.isSoftware());
    EXPECT_FALSE(kNvidia.isSoftware());
    // Mesa marks its software device even where the renderer string would not say so.
    EXPECT_TRUE(working("device 0", "some renderer", "Mesa", true).isSoftware());
}

TEST(DisplayChoice, HardwareListedAfterSoftwareIsStillChosen) {
    const auto choice = gl::chooseDisplay(
        {working("device 0", "llvmpipe (LLVM 15.0.6, 256 bits)", "Mesa", true), kNvidia, kLlvmpipe},
        std::nullopt);
    EXPECT_EQ(choice.index, 1u);
    EXPECT_EQ(choice.note, "");
}

TEST(DisplayChoice, TheFirstWorkingHardwareRendererWins) {
    const auto second =
        working("device 2 /dev/dri/renderD129", "NVIDIA H200/PCIe/SSE2", "NVIDIA Corporation");
    EXPECT_EQ(gl::chooseDisplay({kLlvmpipe, kNvidia, second}, std::nullopt).index, 1u);
    EXPECT_EQ(
        gl::chooseDisplay({kLlvmpipe, failed("device 0", "EGL_BAD_ALLOC"), second}, std::nullopt)
            .index,
        2u);
}

TEST(DisplayChoice, AllSoftwareGivesTheFirstWorkingSoftware) {
    const auto first = working("device 0", "llvmpipe (LLVM 15.0.6, 256 bits)", "Mesa", true);
    EXPECT_EQ(gl::chooseDisplay({first, kLlvmpipe}, std::nullopt).index, 0u);
    EXPECT_EQ(gl::chooseDisplay({failed("device 0", "eglInitialize: EGL_NOT_INITIALIZED", true),
                                 kLlvmpipe, first},
                                std::nullopt)
                  .index,
              1u);
}

TEST(DisplayChoice, SoftwareAfterAFailedPossibleGpuSaysWhy) {
    const auto choice = gl::chooseDisplay(
        {failed("device 0 /dev/dri/renderD128", "eglCreateContext(3.3 core): EGL_BAD_MATCH"),
         failed("device 1", "eglInitialize: EGL_NOT_INITIALIZED", true), kLlvmpipe,
         failed("default display", "eglInitialize: EGL_NOT_INITIALIZED")},
        std::nullopt);
    EXPECT_EQ(choice.index, 2u);
    EXPECT_TRUE(contains(choice.note, "device 0 /dev/dri/renderD128: eglCreateContext"))
        << choice.note;
    // A failed device that says it is software was never a GPU, and the
    // default display failing is normal without a window system: not worth naming.
    EXPECT_FALSE(contains(choice.note, "device 1")) << choice.note;
    EXPECT_FALSE(contains(choice.note, "default display")) << choice.note;
    // Without a failed possible GPU there is nothing to explain.
    EXPECT_EQ(
        gl::chooseDisplay({failed("default display", "EGL_BAD_ALLOC"), kLlvmpipe}, std::nullopt)
            .note,
        "");
}

TEST(DisplayChoice, FailuresAreSkipped) {
    const auto choice =
        gl::chooseDisplay({failed("device 0", "EGL_BAD_ALLOC"),
                           failed("surfaceless", "no desktop OpenGL API"), kLlvmpipe},
                          std::nullopt);
    EXPECT_EQ(choice.index, 2u);
}

TEST(DisplayChoice, AnExplicitIndexIsHonouredEvenForSoftware) {
    const std::vector<DisplayCandidate> candidates{kNvidia, kLlvmpipe};
    EXPECT_EQ(gl::chooseDisplay(candidates, DeviceRequest{1, "--gpu-device"}).index, 1u);
    EXPECT_EQ(gl::chooseDisplay(candidates, DeviceRequest{0, "--gpu-device"}).index, 0u);
}

TEST(DisplayChoice, AnIndexOutOfRangeListsTheCandidates) {
    const std::vector<DisplayCandidate> candidates{
        kNvidia, kLlvmpipe, failed("default display", "eglInitialize: EGL_NOT_INITIALIZED")};
    const std::string message = messageOf<InputError>([&] {
        gl::chooseDisplay(candidates, DeviceRequest{3, "MORPHOGEN_GPU_DEVICE"});
    });
    EXPECT_TRUE(contains(message, "MORPHOGEN_GPU_DEVICE 3 is out of range (accepted: 0..2"))
        << message;
    EXPECT_TRUE(contains(message, "0 device 1 /dev/dri/renderD128: NVIDIA H200/PCIe/SSE2"))
        << message;
    EXPECT_TRUE(contains(message, "1 surfaceless: llvmpipe")) << message;
    EXPECT_TRUE(contains(message, "2 default display: failed (eglInitialize")) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "an input error is one line";
}

TEST(DisplayChoice, AnExplicitFailedCandidateIsAnError) {
    const std::string message = messageOf<InputError>([] {
        gl::chooseDisplay({kLlvmpipe, failed("device 1", "EGL_BAD_ALLOC")},
                          DeviceRequest{1, "--gpu-device"});
    });
    EXPECT_TRUE(contains(message, "--gpu-device 1 (device 1) gives no OpenGL 3.3 core context: "
                                  "EGL_BAD_ALLOC"))
        << message;
    EXPECT_TRUE(contains(message, "0 surfaceless: llvmpipe")) << message;
}

TEST(DisplayChoice, NothingWorkingListsEveryFailure) {
    const std::string message = messageOf<std::runtime_error>([] {
        gl::chooseDisplay({failed("device 0", "EGL_BAD_ALLOC", true),
                           failed("surfaceless", "no desktop OpenGL API"),
                           failed("default display", "eglInitialize: EGL_NOT_INITIALIZED")},
                          std::nullopt);
    });
    EXPECT_TRUE(contains(message, "device 0: EGL_BAD_ALLOC")) << message;
    EXPECT_TRUE(contains(message, "surfaceless: no desktop OpenGL API")) << message;
    EXPECT_TRUE(contains(message, "default display: eglInitialize")) << message;
    EXPECT_EQ(messageOf<std::runtime_error>([] { gl::chooseDisplay({}, std::nullopt); }),
              "no EGL display found");
}

TEST(DisplayChoice, DeviceNumbersAreParsedStrictly) {
    EXPECT_EQ(gl::parseGpuDevice("0", "--gpu-device"), 0);
    EXPECT_EQ(gl::parseGpuDevice("12", "--gpu-device"), 12);
    for (const char* bad : {"", "-1", "1.5", "one", " 1", "99999999999"}) {
        const std::string message =
            messageOf<InputError>([&] { gl::parseGpuDevice(bad, "MORPHOGEN_GPU_DEVICE"); });
        EXPECT_TRUE(contains(message, std::string("MORPHOGEN_GPU_DEVICE '") + bad + "'"))
            << message;
    }
}
