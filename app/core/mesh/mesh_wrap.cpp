#include "core/mesh/mesh_wrap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <CGAL/alpha_wrap_3.h>

#include "core/mesh/cgal_surface_mesh.hpp"

namespace morphogen {

namespace {

constexpr std::array<const char*, 3> kNames = {"auto", "always", "never"};

// Triangles per connected piece (joined through shared vertices).
std::vector<std::size_t> pieceSizes(const TriangleMesh& mesh) {
    std::vector<std::size_t> sizes;
    for (const std::vector<std::uint32_t>& piece : componentTriangles(mesh))
        sizes.push_back(piece.size());
    return sizes;
}

} // namespace

std::optional<WrapMode> parseWrapMode(std::string_view text) {
    for (std::size_t i = 0; i < kNames.size(); ++i)
        if (text == kNames[i])
            return WrapMode(i);
    return std::nullopt;
}

std::string toString(WrapMode mode) {
    return kNames[std::size_t(mode)];
}

std::string wrapModeNames() {
    return std::string(kNames[0]) + ", " + kNames[1] + ", " + kNames[2];
}

std::size_t meshPieces(const TriangleMesh& mesh) {
    return pieceSizes(mesh).size();
}

bool looksLikeSoup(const TriangleMesh& mesh) {
    const std::vector<std::size_t> sizes = pieceSizes(mesh);
    if (sizes.size() < kSoupComponents)
        return false;
    const auto fragments = std::count_if(sizes.begin(), sizes.end(),
                                         [](std::size_t n) { return n <= kSoupFragmentTriangles; });
    return std::size_t(fragments) * 2 > sizes.size();
}

TriangleMesh alphaWrap(const TriangleMesh& mesh, double alphaFraction, double offsetFraction,
                       WrapStats* stats) {
    const double diagonal = boundsOf(mesh.positions).diagonal();
    if (!(diagonal > 0) || !std::isfinite(diagonal))
        throw std::runtime_error("the mesh's extent is not a finite size");
    const cgal::Soup soup = cgal::soupOf(mesh);
    const double alpha = alphaFraction * diagonal, offset = offsetFraction * diagonal;
    cgal::SurfaceMesh wrap;
    CGAL::alpha_wrap_3(soup.points, soup.faces, alpha, offset, wrap);
    if (wrap.number_of_faces() == 0)
        throw std::runtime_error("the wrap came out empty");
    TriangleMesh out = cgal::triangleMeshOf(wrap);
    if (stats) {
        stats->wrapped = true;
        stats->componentsBefore = meshPieces(mesh);
        stats->triangles = out.triangles.size();
        stats->alpha = alpha;
        stats->offset = offset;
    }
    return out;
}

} // namespace morphogen
