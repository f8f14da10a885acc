#include "fuzz_support.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace morphogen::fuzz {

namespace fs = std::filesystem;

namespace {

struct ScratchDir {
    std::string path;
    ScratchDir() {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/morphogen-fuzz-XXXXXX";
        if (!mkdtemp(pattern.data())) {
            std::perror("morphogen fuzz: mkdtemp");
            std::abort();
        }
        path = pattern;
    }
    ~ScratchDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

} // namespace

const std::string& scratchDir() {
    static const ScratchDir dir;
    return dir.path;
}

std::string writeInput(const std::uint8_t* data, std::size_t size, const std::string& name) {
    const std::string path = scratchDir() + "/" + name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    out.close();
    if (!out)
        fail("cannot write the input to " + path);
    return path;
}

std::string writeInput(const std::string& text, const std::string& name) {
    return writeInput(reinterpret_cast<const std::uint8_t*>(text.data()), text.size(), name);
}

void fail(const std::string& what) {
    std::fprintf(stderr, "morphogen fuzz: FAILED: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

} // namespace morphogen::fuzz
