#include "gl/gl_loader.hpp"

#include <stdexcept>
#include <string>

#include <glad/gl.h>

namespace morphogen::gl {

void loadGlFunctions(ProcAddressFn getProcAddress, const char* backendName) {
    const int version = gladLoadGL(reinterpret_cast<GLADloadfunc>(getProcAddress));
    if (version == 0)
        throw std::runtime_error(std::string(backendName) + ": loading GL entry points failed");
    const int major = GLAD_VERSION_MAJOR(version), minor = GLAD_VERSION_MINOR(version);
    if (major < 3 || (major == 3 && minor < 3))
        throw std::runtime_error(std::string(backendName) + ": context is GL " +
                                 std::to_string(major) + "." + std::to_string(minor) +
                                 ", need 3.3 core");
}

} // namespace morphogen::gl
