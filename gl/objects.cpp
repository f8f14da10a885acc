#include "gl/objects.hpp"

#include <algorithm>
#include <cassert>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <stdexcept>

#include "core/base/embedded_files.hpp"
#include "core/base/errors.hpp"

namespace morphogen::gl {

Texture2D::Texture2D(int width, int height, GLenum internalFormat)
    : m_width(width), m_height(height), m_internalFormat(internalFormat) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (width > maxSize || height > maxSize)
        throw InputError("size " + std::to_string(width) + "x" + std::to_string(height) +
                         " exceeds this GPU's largest texture (" + std::to_string(maxSize) +
                         " per side)");
    while (glGetError() != GL_NO_ERROR) {
    }
    GLuint id = 0;
    glGenTextures(1, &id);
    m_name = UniqueName<TextureTraits>(id);
    glBindTexture(GL_TEXTURE_2D, id);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    // Integer formats need an integer transfer format even with no data.
    const bool integer = internalFormat == GL_RGBA32UI;
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(internalFormat), width, height, 0,
                 integer ? GL_RGBA_INTEGER : GL_RGBA, integer ? GL_UNSIGNED_INT : GL_FLOAT,
                 nullptr);
    const GLenum error = glGetError();
    if (error == GL_OUT_OF_MEMORY)
        throw InputError("size " + std::to_string(width) + "x" + std::to_string(height) +
                         ": the GPU cannot allocate the state textures (out of memory)");
    if (error != GL_NO_ERROR)
        throw std::runtime_error("glTexImage2D failed with GL error " + std::to_string(error));
}

void Texture2D::setWrap(GLenum wrap) {
    glBindTexture(GL_TEXTURE_2D, id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GLint(wrap));
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GLint(wrap));
}

void Texture2D::bind(int unit) const {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, id());
}

void Texture2D::uploadRgba(const std::vector<float>& rgba) {
    glBindTexture(GL_TEXTURE_2D, id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, m_width, m_height, GL_RGBA, GL_FLOAT, rgba.data());
}

void Texture2D::uploadRgbaRect(int x, int y, int width, int height,
                               const std::vector<float>& rgba) {
    assert(x >= 0 && y >= 0 && x + width <= m_width && y + height <= m_height);
    assert(rgba.size() == std::size_t(width) * std::size_t(height) * 4);
    glBindTexture(GL_TEXTURE_2D, id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, x, y, width, height, GL_RGBA, GL_FLOAT, rgba.data());
}

void Texture2D::uploadBytesRect(int x, int y, int width, int height, const std::uint8_t* bytes) {
    assert(m_internalFormat == GL_R8);
    assert(x >= 0 && y >= 0 && x + width <= m_width && y + height <= m_height);
    glBindTexture(GL_TEXTURE_2D, id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, x, y, width, height, GL_RED, GL_UNSIGNED_BYTE, bytes);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

void Texture2D::uploadRgbaUint(const std::vector<std::uint32_t>& rgba) {
    assert(m_internalFormat == GL_RGBA32UI && rgba.size() == std::size_t(m_width) * m_height * 4);
    glBindTexture(GL_TEXTURE_2D, id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, m_width, m_height, GL_RGBA_INTEGER, GL_UNSIGNED_INT,
                    rgba.data());
}

std::vector<float> Texture2D::downloadRgba() const {
    std::vector<float> rgba(std::size_t(m_width) * m_height * 4);
    glBindTexture(GL_TEXTURE_2D, id());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, rgba.data());
    return rgba;
}

int Texture2D::components() const {
    switch (m_internalFormat) {
    case GL_R32F:
        return 1;
    case GL_RG32F:
        return 2;
    default:
        assert(m_internalFormat == GL_RGBA32F);
        return 4;
    }
}

namespace {

GLenum transferFormat(int components) {
    return components == 1 ? GL_RED : components == 2 ? GL_RG : GL_RGBA;
}

} // namespace

void Texture2D::uploadRows(int y, int rows, const float* data) {
    assert(y >= 0 && rows >= 0 && y + rows <= m_height);
    glBindTexture(GL_TEXTURE_2D, id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, y, m_width, rows, transferFormat(components()), GL_FLOAT,
                    data);
}

void Texture2D::downloadRows(int y, int rows, float* data) const {
    assert(y >= 0 && rows >= 0 && y + rows <= m_height);
    GLint previous = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
    GLuint fbo = 0;
    glGenFramebuffers(1, &fbo);
    const UniqueName<FramebufferTraits> owner(fbo);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, id(), 0);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    // Float buffers are not clamped (GL_CLAMP_READ_COLOR is GL_FIXED_ONLY):
    // the bits glGetTexImage would give.
    glReadPixels(0, y, m_width, rows, transferFormat(components()), GL_FLOAT, data);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(previous));
}

Framebuffer::Framebuffer(const std::vector<const Texture2D*>& colours) {
    assert(!colours.empty());
    m_width = colours.front()->width();
    m_height = colours.front()->height();
    GLint maxBuffers = 0;
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &maxBuffers);
    if (GLint(colours.size()) > maxBuffers)
        throw std::runtime_error("a framebuffer needs " + std::to_string(colours.size()) +
                                 " colour attachments; this GL allows " +
                                 std::to_string(maxBuffers));
    GLuint id = 0;
    glGenFramebuffers(1, &id);
    m_name = UniqueName<FramebufferTraits>(id);
    glBindFramebuffer(GL_FRAMEBUFFER, id);
    std::vector<GLenum> buffers;
    for (std::size_t i = 0; i < colours.size(); ++i) {
        assert(colours[i]->width() == m_width && colours[i]->height() == m_height);
        const GLenum attachment = GL_COLOR_ATTACHMENT0 + GLenum(i);
        glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, colours[i]->id(), 0);
        buffers.push_back(attachment);
    }
    glDrawBuffers(GLsizei(buffers.size()), buffers.data());
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        char code[16];
        std::snprintf(code, sizeof code, "%x", status);
        throw std::runtime_error("framebuffer with " + std::to_string(colours.size()) + " " +
                                 std::to_string(m_width) + "x" + std::to_string(m_height) +
                                 " texture(s) is incomplete (status 0x" + code + ")");
    }
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, id());
    glViewport(0, 0, m_width, m_height);
}

Buffer::Buffer() {
    GLuint id = 0;
    glGenBuffers(1, &id);
    m_name = UniqueName<BufferTraits>(id);
}

VertexArray::VertexArray() {
    GLuint id = 0;
    glGenVertexArrays(1, &id);
    m_name = UniqueName<VertexArrayTraits>(id);
}

namespace {

std::string legend(const std::vector<ShaderPiece>& pieces) {
    std::string text;
    for (std::size_t i = 0; i < pieces.size(); ++i)
        text += "  source " + std::to_string(i) + " = " + pieces[i].name + "\n";
    return text;
}

GLuint compileStage(GLenum stage, const std::vector<ShaderPiece>& pieces,
                    const std::vector<std::string>& defines) {
    std::vector<ShaderPiece> all;
    std::string prelude = "#version 330 core\n";
    for (const std::string& d : defines)
        prelude += "#define " + d + "\n";
    all.push_back({"<version and defines>", prelude});
    all.insert(all.end(), pieces.begin(), pieces.end());
    std::vector<const char*> strings;
    for (const ShaderPiece& p : all)
        strings.push_back(p.text.c_str());

    const GLuint shader = glCreateShader(stage);
    glShaderSource(shader, GLsizei(strings.size()), strings.data(), nullptr);
    glCompileShader(shader);
    GLint ok = 0, logLength = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &logLength);
    std::string log(std::size_t(std::max(logLength, 1)), '\0');
    glGetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    const std::string mainFile = pieces.empty() ? "?" : pieces.back().name;
    if (!ok) {
        glDeleteShader(shader);
        throw std::runtime_error("compiling " + mainFile + " failed:\n" + log +
                                 "(log prefixes N:line refer to\n" + legend(all) + ")");
    }
    if (!log.empty())
        std::cerr << "shader log for " << mainFile << ":\n" << log << legend(all);
    return shader;
}

} // namespace

Program::Program(const std::vector<ShaderPiece>& vertex, const std::vector<ShaderPiece>& fragment,
                 const std::vector<std::string>& defines) {
    const GLuint vs = compileStage(GL_VERTEX_SHADER, vertex, defines);
    GLuint fs = 0;
    try {
        fs = compileStage(GL_FRAGMENT_SHADER, fragment, defines);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    const GLuint program = glCreateProgram();
    m_name = UniqueName<ProgramTraits>(program);
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDetachShader(program, vs);
    glDetachShader(program, fs);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0, logLength = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &logLength);
    std::string log(std::size_t(std::max(logLength, 1)), '\0');
    glGetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    const std::string names = vertex.back().name + " + " + fragment.back().name;
    if (!ok)
        throw std::runtime_error("linking " + names + " failed:\n" + log);
    if (!log.empty())
        std::cerr << "link log for " << names << ":\n" << log;
}

ShaderPiece embeddedShader(const std::string& path) {
    auto text = embeddedFile(path);
    if (!text)
        throw std::runtime_error("shader " + path + " is not embedded in this build");
    return {path, std::string(*text)};
}

} // namespace morphogen::gl
