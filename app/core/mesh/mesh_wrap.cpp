#include "core/mesh/mesh_wrap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>

namespace morphogen {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

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
    return "auto, always, never";
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
    std::vector<Point> points;
    points.reserve(mesh.positions.size());
    for (const Eigen::Vector3f& p : mesh.positions)
        points.emplace_back(p.x(), p.y(), p.z());
    std::vector<std::array<std::size_t, 3>> faces;
    faces.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        faces.push_back({t[0], t[1], t[2]});
    const double alpha = alphaFraction * diagonal, offset = offsetFraction * diagonal;
    CGAL::Surface_mesh<Point> wrap;
    CGAL::alpha_wrap_3(points, faces, alpha, offset, wrap);
    if (wrap.number_of_faces() == 0)
        throw std::runtime_error("the wrap came out empty");

    TriangleMesh out;
    std::vector<std::uint32_t> index(wrap.number_of_vertices() + wrap.number_of_removed_vertices());
    for (const auto v : wrap.vertices()) {
        const Point& p = wrap.point(v);
        index[std::size_t(v)] = std::uint32_t(out.positions.size());
        out.positions.emplace_back(float(p.x()), float(p.y()), float(p.z()));
    }
    for (const auto f : wrap.faces()) {
        std::array<std::uint32_t, 3> tri{};
        int k = 0;
        for (const auto v : CGAL::vertices_around_face(wrap.halfedge(f), wrap))
            if (k < 3)
                tri[std::size_t(k++)] = index[std::size_t(v)];
        if (k == 3)
            out.triangles.push_back(tri);
    }
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
