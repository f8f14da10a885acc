// morphogen propagator: McGraw's Gram-Charlier diffusion propagator (eq. 23)
// for a tensor sequence, as a polar plot, with its peak directions (the
// orientations the texture will prefer) on stdout and the operator's explicit
// stability on stderr.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include "cli/commands.hpp"
#include "core/base/errors.hpp"
#include "core/io/image_io.hpp"
#include "core/numerics/kernel_symbol.hpp"
#include "core/numerics/propagator.hpp"
#include "core/numerics/tensor_sequence.hpp"

namespace morphogen::cli {

namespace {

struct PropagatorFlags {
    std::string tensor;
    std::string out;
    double tau = 0.1;
    double radius = 1.0;
    int size = 512;
};

std::string formatPeaks(const std::vector<double>& peaks) {
    if (peaks.empty())
        return "peaks (degrees): none (isotropic)"; // angularShape said so
    std::ostringstream os;
    os << "peaks (degrees):";
    for (double p : peaks) {
        double rounded = std::round(p * 10) / 10;
        if (rounded >= 360)
            rounded -= 360;
        os << " " << rounded;
    }
    return os.str();
}

void propagator(const PropagatorFlags& f) {
    const TensorSequence sequence = parseTensorSequence(f.tensor);
    if (!(f.radius > 0) || !std::isfinite(f.radius))
        throw InputError("--radius " + std::to_string(f.radius) + ": must be positive");
    if (f.size < 64 || f.size > 4096)
        throw InputError("--size " + std::to_string(f.size) + ": accepted are 64..4096");
    if (imageFormatForPath(f.out) == ImageFormat::Exr)
        throw InputError("--out " + f.out + ": the plot is an RGB image; use .png, .tif or .tiff");
    checkWritable(f.out);

    const Propagator p(sequence, f.tau);
    const std::vector<double> samples = sampleAngular(p, f.radius);
    if (angularShape(samples) == AngularShape::Empty) {
        std::ostringstream os;
        os << "--radius " << f.radius << " at --tau " << f.tau
           << ": the propagator has no positive value on that circle (it is "
           << (std::all_of(samples.begin(), samples.end(),
                           [](double v) { return std::isfinite(v); })
                   ? "below double precision or negative"
                   : "not finite")
           << " there), so the plot would be empty and show no direction; accepted: a radius "
              "of about 1 to 3 times the Gaussian's width, here "
           << p.width() << " (e.g. --radius " << 2 * p.width() << ")";
        throw InputError(os.str());
    }
    writeRgbImage(f.out, renderPolarPlot(samples, f.size), f.size, f.size, 8);
    std::printf("%s\n", formatPeaks(findAngularPeaks(samples)).c_str());

    // What an explicit run of this operator will face (d = 1).
    const Kernel5 kernel = generalizedDiffusionKernel(sequence);
    const ExplicitStepReport report = analyzeExplicitStep(kernel, 0.1);
    // Rounding leaves +-1e-15 on exactly neutral modes; do not print it as growth.
    auto shown = [](double re) { return std::abs(re) < 1e-12 ? 0.0 : re; };
    if (report.maxStableDt) {
        std::fprintf(stderr,
                     "propagator: %s: max Re(lambda) %.3g, largest stable explicit dt %.4g\n",
                     toString(sequence).c_str(), shown(report.maxRealPart), *report.maxStableDt);
    } else {
        const StabilizedKernel s = stabilizeKernel(kernel);
        const ExplicitStepReport after = analyzeExplicitStep(s.kernel, 0.1);
        std::fprintf(stderr,
                     "propagator: %s: max Re(lambda) %.3g > 0, unstable for every explicit dt; "
                     "with -%.4g * Laplacian^2 damping: max Re %.3g, largest stable dt %.4g\n",
                     toString(sequence).c_str(), report.maxRealPart, s.eta,
                     shown(after.maxRealPart), after.maxStableDt.value_or(0.0));
    }
}

} // namespace

void addPropagatorCommand(CLI::App& app) {
    auto flags = std::make_shared<PropagatorFlags>();
    CLI::App* cmd = app.add_subcommand(
        "propagator",
        "Plot McGraw's generalized diffusion propagator and print its peak directions");
    cmd->add_option("--tensor", flags->tensor,
                    "Table 2 set a..f, or component=value pairs, e.g. \"xx=1,yy=1,xxxx=-1\"")
        ->required();
    cmd->add_option("--out", flags->out, "polar plot image (.png, .tif)")->required();
    cmd->add_option("--tau", flags->tau, "diffusion time tau (default 0.1)");
    cmd->add_option("--radius", flags->radius, "displacement |r| the plot is taken at (default 1)");
    cmd->add_option("--size", flags->size, "image side in pixels (default 512)");
    cmd->callback([flags] { propagator(*flags); });
}

} // namespace morphogen::cli
