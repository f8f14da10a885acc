#pragma once

#include <array>
#include <string>

#include "core/numerics/kernel.hpp"
#include "core/numerics/savitzky_golay.hpp"

namespace morphogen {

// One unique component of a symmetric 2-D tensor of rank 2, 3 or 4 (eq. 14-16):
// identified by how many x and y indices it has, order notwithstanding.
struct TensorComponent {
    const char* name; // "xxy"
    int rank;
    int nx, ny;
    int multiplicity; // rank! / (nx! ny!), eq. 16
};

constexpr int kTensorComponentCount = 12;

// xx, xy, yy; xxx, xxy, xyy, yyy; xxxx, xxxy, xxyy, xyyy, yyyy (eq. 20-21 order).
const std::array<TensorComponent, kTensorComponentCount>& tensorComponents();

// "xx, xy, yy, xxx, ..., yyyy": for messages.
std::string tensorComponentNames();

// The tensors D^(2), D^(3), D^(4) of McGraw's generalized diffusion by their
// 12 unique components, in tensorComponents() order.
struct TensorSequence {
    std::array<double, kTensorComponentCount> values{};

    // By component name in canonical order ("xxy"); -1 index when unknown.
    static int indexOf(const std::string& canonicalName);
    double get(const std::string& name) const { return values[std::size_t(indexOf(name))]; }
    void set(const std::string& name, double v) { values[std::size_t(indexOf(name))] = v; }

    // D^(2) is what makes the propagator a Gaussian; the rest reshapes it.
    bool hasRank(int rank) const;
};

// Table 2, column (a)..(f). Throws InputError for any other letter.
TensorSequence tableTwoSet(char letter);

// "a".."f" (a Table 2 set), or comma-separated component=value pairs such as
// "xx=1,yy=1,xxxx=-1". Components not named are 0. A name may list its
// indices in any order ("yx" is xy) since the tensors are symmetric. Throws
// InputError naming the bad token and the accepted component names.
TensorSequence parseTensorSequence(const std::string& text);

// "xx=1,yy=2,xxxx=-1,xxyy=1,yyyy=-1": the non-zero components, parseable.
std::string toString(const TensorSequence& sequence);

struct GeneralizedOperatorOptions {
    SgOptions sg;
    // McGraw's stability remedy (sec. 5.1): second derivatives from central
    // differences (3-point, and the 4-corner stencil / 4 for xy) rather than
    // the fitted kernels, whose smoothing leaves the high-frequency modes
    // barely damped.
    bool centralSecondDerivatives = true;
};

// The generalized diffusion term (eq. 21 / eq. 37) as one kernel: every
// component times its multiplicity times the kernel of its derivative, all
// with a plus sign as in eq. 19-21 and eq. 36. Throws InputError when the SG
// basis cannot give a derivative the sequence needs.
Kernel5 generalizedDiffusionKernel(const TensorSequence& sequence,
                                   const GeneralizedOperatorOptions& options = {});

} // namespace morphogen
