#pragma once
// Move-only owners of GL object names. Copy is deleted; a move leaves the
// source owning name 0, whose destructor does nothing. Destructors never
// throw and need the owning context current.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glad/gl.h>

namespace morphogen::gl {

template <typename Traits> class UniqueName {
public:
    UniqueName() = default;
    explicit UniqueName(GLuint id) : m_id(id) {}
    ~UniqueName() {
        if (m_id)
            Traits::destroy(m_id);
    }
    UniqueName(const UniqueName&) = delete;
    UniqueName& operator=(const UniqueName&) = delete;
    UniqueName(UniqueName&& other) noexcept : m_id(std::exchange(other.m_id, 0)) {}
    UniqueName& operator=(UniqueName&& other) noexcept {
        if (this != &other) {
            if (m_id)
                Traits::destroy(m_id);
            m_id = std::exchange(other.m_id, 0);
        }
        return *this;
    }
    GLuint id() const { return m_id; }

private:
    GLuint m_id = 0;
};

struct TextureTraits {
    static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct FramebufferTraits {
    static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct BufferTraits {
    static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct VertexArrayTraits {
    static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct ProgramTraits {
    static void destroy(GLuint id) { glDeleteProgram(id); }
};

// A 2D texture with nearest filtering. Throws std::runtime_error (or
// morphogen::InputError for a size the GPU cannot hold) on failure.
class Texture2D {
public:
    Texture2D() = default;
    Texture2D(int width, int height, GLenum internalFormat);

    GLuint id() const { return m_name.id(); }
    int width() const { return m_width; }
    int height() const { return m_height; }
    GLenum internalFormat() const { return m_internalFormat; }

    void setWrap(GLenum wrap); // GL_REPEAT or GL_CLAMP_TO_EDGE
    void bind(int unit) const;
    // Whole-texture upload/download of RGBA floats.
    void uploadRgba(const std::vector<float>& rgba);
    // RGBA floats (width * height * 4) into the rectangle at (x, y).
    void uploadRgbaRect(int x, int y, int width, int height, const std::vector<float>& rgba);
    // One byte per texel (0..255 read as 0..1) into the rectangle at (x, y)
    // of a GL_R8 texture.
    void uploadBytesRect(int x, int y, int width, int height, const std::uint8_t* bytes);
    // Whole-texture upload of an integer (GL_RGBA32UI) texture.
    void uploadRgbaUint(const std::vector<std::uint32_t>& rgba);
    std::vector<float> downloadRgba() const;
    // Rows y .. y + rows - 1 of a float texture in its own layout,
    // components() floats per texel: with no format conversion the driver
    // makes no whole-texture staging copy either, so a big state moves
    // through a band of rows of memory (the read goes through a framebuffer:
    // glGetTexImage has no rectangle in GL 3.3).
    void uploadRows(int y, int rows, const float* data);
    void downloadRows(int y, int rows, float* data) const;
    // Floats per texel of a float texture: 1 (R32F), 2 (RG32F) or 4 (RGBA32F).
    int components() const;

private:
    UniqueName<TextureTraits> m_name;
    int m_width = 0;
    int m_height = 0;
    GLenum m_internalFormat = 0;
};

// A framebuffer drawing into one or more same-size colour textures (fragment
// output i goes to colours[i]); completeness is checked.
class Framebuffer {
public:
    Framebuffer() = default;
    explicit Framebuffer(const Texture2D& colour) : Framebuffer(std::vector{&colour}) {}
    explicit Framebuffer(const std::vector<const Texture2D*>& colours);
    GLuint id() const { return m_name.id(); }
    void bind() const;

private:
    UniqueName<FramebufferTraits> m_name;
    int m_width = 0;
    int m_height = 0;
};

class Buffer {
public:
    Buffer();
    GLuint id() const { return m_name.id(); }

private:
    UniqueName<BufferTraits> m_name;
};

class VertexArray {
public:
    VertexArray();
    GLuint id() const { return m_name.id(); }
    void bind() const { glBindVertexArray(m_name.id()); }

private:
    UniqueName<VertexArrayTraits> m_name;
};

// One GLSL source file (or generated piece) going into a shader stage.
struct ShaderPiece {
    std::string name; // a path like glsl/step.frag, or "<defines>"
    std::string text;
};

// A linked vertex + fragment program. Each stage is assembled from
// "#version 330 core", the given #defines, then the pieces, passed as
// separate source strings so the driver's "0:12" log prefixes map back to
// files; errors carry the file names and the info log. Non-empty logs are
// printed to stderr even on success.
class Program {
public:
    Program() = default;
    Program(const std::vector<ShaderPiece>& vertex, const std::vector<ShaderPiece>& fragment,
            const std::vector<std::string>& defines);
    GLuint id() const { return m_name.id(); }
    void use() const { glUseProgram(m_name.id()); }
    GLint uniform(const char* name) const { return glGetUniformLocation(m_name.id(), name); }

private:
    UniqueName<ProgramTraits> m_name;
};

// The text of an embedded file under glsl/; throws std::runtime_error if missing.
ShaderPiece embeddedShader(const std::string& path);

} // namespace morphogen::gl
