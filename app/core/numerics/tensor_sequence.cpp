#include "core/numerics/tensor_sequence.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/base/names.hpp"

namespace morphogen {

namespace {

std::string trim(const std::string& s) {
    std::size_t b = 0, e = s.size();
    while (b < e && std::isspace(static_cast<unsigned char>(s[b])))
        ++b;
    while (e > b && std::isspace(static_cast<unsigned char>(s[e - 1])))
        --e;
    return s.substr(b, e - b);
}

// "yxy" -> "xyy"; empty when the name is not 2-4 letters from {x, y}.
std::string canonicalName(const std::string& name) {
    if (name.size() < 2 || name.size() > 4)
        return {};
    int nx = 0;
    for (char ch : name) {
        const char c = char(std::tolower(static_cast<unsigned char>(ch)));
        if (c == 'x')
            ++nx;
        else if (c != 'y')
            return {};
    }
    return std::string(std::size_t(nx), 'x') + std::string(name.size() - std::size_t(nx), 'y');
}

// The 3-point second differences and the 4-corner mixed difference / 4.
Kernel5 centralSecondDerivative(int nx, int ny) {
    Kernel5 k;
    if (nx == 2) {
        k.at(-1, 0) = 1;
        k.at(0, 0) = -2;
        k.at(1, 0) = 1;
    } else if (ny == 2) {
        k.at(0, -1) = 1;
        k.at(0, 0) = -2;
        k.at(0, 1) = 1;
    } else {
        k.at(1, 1) = k.at(-1, -1) = 0.25;
        k.at(1, -1) = k.at(-1, 1) = -0.25;
    }
    return k;
}

} // namespace

const std::array<TensorComponent, kTensorComponentCount>& tensorComponents() {
    static const std::array<TensorComponent, kTensorComponentCount> components = {{
        {"xx", 2, 2, 0, 1},
        {"xy", 2, 1, 1, 2},
        {"yy", 2, 0, 2, 1},
        {"xxx", 3, 3, 0, 1},
        {"xxy", 3, 2, 1, 3},
        {"xyy", 3, 1, 2, 3},
        {"yyy", 3, 0, 3, 1},
        {"xxxx", 4, 4, 0, 1},
        {"xxxy", 4, 3, 1, 4},
        {"xxyy", 4, 2, 2, 6},
        {"xyyy", 4, 1, 3, 4},
        {"yyyy", 4, 0, 4, 1},
    }};
    return components;
}

std::string tensorComponentNames() {
    std::string names;
    for (const TensorComponent& c : tensorComponents())
        names += (names.empty() ? "" : ", ") + std::string(c.name);
    return names;
}

int TensorSequence::indexOf(const std::string& canonical) {
    const auto& components = tensorComponents();
    for (std::size_t i = 0; i < components.size(); ++i)
        if (canonical == components[i].name)
            return int(i);
    return -1;
}

bool TensorSequence::hasRank(int rank) const {
    const auto& components = tensorComponents();
    for (std::size_t i = 0; i < components.size(); ++i)
        if (components[i].rank == rank && values[i] != 0.0)
            return true;
    return false;
}

TensorSequence tableTwoSet(char letter) {
    TensorSequence s;
    const char l = char(std::tolower(static_cast<unsigned char>(letter)));
    if (l < 'a' || l > 'f')
        throw InputError(std::string("tensor set '") + letter +
                         "': Table 2 has sets a, b, c, d, e, f");
    s.set("xx", 1);
    s.set("yy", (l == 'b' || l == 'f') ? 2 : 1);
    if (l == 'c') {
        s.set("xxx", 1);
        s.set("xxy", -1);
        s.set("xyy", -1);
        s.set("yyy", 1);
    } else if (l == 'd' || l == 'e' || l == 'f') {
        const double sign = l == 'd' ? 1.0 : -1.0;
        s.set("xxxx", sign);
        s.set("xxyy", -sign);
        s.set("yyyy", sign);
    }
    return s;
}

TensorSequence parseTensorSequence(const std::string& text) {
    const std::string whole = trim(text);
    if (whole.size() == 1 && std::isalpha(static_cast<unsigned char>(whole[0])))
        return tableTwoSet(whole[0]);
    const std::string accepted = "accepted are a Table 2 set (a..f) or component=value pairs, "
                                 "comma-separated, with components " +
                                 tensorComponentNames();
    if (whole.empty())
        throw InputError("tensor sequence is empty; " + accepted);

    TensorSequence s;
    std::array<bool, kTensorComponentCount> seen{};
    std::stringstream in(whole);
    std::string token;
    while (std::getline(in, token, ',')) {
        const std::string item = trim(token);
        const std::size_t eq = item.find('=');
        if (eq == std::string::npos)
            throw InputError("tensor sequence '" + text + "': '" + item +
                             "' is not component=value; " + accepted);
        const std::string name = trim(item.substr(0, eq));
        const std::string value = trim(item.substr(eq + 1));
        const int index = TensorSequence::indexOf(canonicalName(name));
        if (index < 0)
            throw InputError("tensor sequence '" + text + "': unknown component '" + name + "'; " +
                             accepted + didYouMean(name, splitNameList(tensorComponentNames())));
        char* end = nullptr;
        const double v = std::strtod(value.c_str(), &end);
        if (value.empty() || *end != '\0' || !std::isfinite(v))
            throw InputError("tensor sequence '" + text + "': '" + value + "' in '" + item +
                             "' is not a finite number");
        // Larger components only shrink the stable time step below any usable dt.
        if (std::fabs(v) > kMaxTensorComponent)
            throw InputError("tensor sequence '" + text + "': component '" + name + "' is " +
                             value + "; accepted are values in [-" +
                             std::to_string(int(kMaxTensorComponent)) + ", " +
                             std::to_string(int(kMaxTensorComponent)) + "]");
        if (seen[std::size_t(index)])
            throw InputError("tensor sequence '" + text + "': component '" +
                             tensorComponents()[std::size_t(index)].name + "' given twice");
        seen[std::size_t(index)] = true;
        s.values[std::size_t(index)] = v;
    }
    return s;
}

std::string toString(const TensorSequence& sequence) {
    std::ostringstream os;
    const auto& components = tensorComponents();
    for (std::size_t i = 0; i < components.size(); ++i)
        if (sequence.values[i] != 0.0)
            os << (os.tellp() > 0 ? "," : "") << components[i].name << "=" << sequence.values[i];
    return os.str();
}

Kernel5 generalizedDiffusionKernel(const TensorSequence& sequence,
                                   const GeneralizedOperatorOptions& options) {
    const SavitzkyGolay sg(options.sg);
    Kernel5 total;
    const auto& components = tensorComponents();
    for (std::size_t i = 0; i < components.size(); ++i) {
        const TensorComponent& c = components[i];
        const double coefficient = c.multiplicity * sequence.values[i];
        if (coefficient == 0.0)
            continue;
        const Kernel5 k = (c.rank == 2 && options.centralSecondDerivatives)
                              ? centralSecondDerivative(c.nx, c.ny)
                              : sg.derivative(c.nx, c.ny);
        total = total + k.scaled(coefficient);
    }
    return total;
}

} // namespace morphogen
