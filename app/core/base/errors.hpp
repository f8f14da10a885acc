#pragma once

#include <stdexcept>
#include <string>

namespace morphogen {

// Input the user can fix: a preset, a flag, a file. The CLI turns it into one
// line on stderr and exit code 2. The message names the file/field/value and
// says what would be accepted.
class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The simulation left the model's sane range (NaN, Inf, or runaway values).
class BlowUpError : public std::runtime_error {
public:
    BlowUpError(const std::string& what, int step, float suggestedDt)
        : std::runtime_error(what), m_step(step), m_suggestedDt(suggestedDt) {}
    int step() const { return m_step; }
    float suggestedDt() const { return m_suggestedDt; }

private:
    int m_step;
    float m_suggestedDt;
};

} // namespace morphogen
