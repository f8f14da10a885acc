#include "core/surface/mesh_simplify.hpp"

#include <cstdint>
#include <vector>

#include <meshoptimizer.h>

#include "core/mesh/mesh_check.hpp"

namespace morphogen {

namespace {

struct Topology {
    std::size_t components = 0;
    std::size_t boundaryLoops = 0;
    long euler = 0;
    bool sound = false; // manifold, no duplicate triangles

    bool operator==(const Topology& o) const {
        return components == o.components && boundaryLoops == o.boundaryLoops && euler == o.euler &&
               sound == o.sound;
    }
};

Topology topologyOf(const TriangleMesh& mesh) {
    const MeshReport r = checkMesh(mesh);
    Topology t;
    t.components = r.components.size();
    t.boundaryLoops = r.boundaryLoops;
    for (const MeshComponent& c : r.components)
        t.euler += c.eulerCharacteristic;
    t.sound = r.manifold() && r.duplicateTriangles.count == 0;
    return t;
}

TriangleMesh compacted(const TriangleMesh& mesh, const std::vector<std::uint32_t>& indices) {
    TriangleMesh out;
    std::vector<std::uint32_t> remap(mesh.positions.size(), UINT32_MAX);
    for (std::uint32_t v : indices)
        remap[v] = 0;
    for (std::size_t v = 0; v < remap.size(); ++v)
        if (remap[v] == 0) {
            remap[v] = std::uint32_t(out.positions.size());
            out.positions.push_back(mesh.positions[v]);
        }
    out.triangles.reserve(indices.size() / 3);
    for (std::size_t i = 0; i + 2 < indices.size(); i += 3)
        out.triangles.push_back({remap[indices[i]], remap[indices[i + 1]], remap[indices[i + 2]]});
    return out;
}

} // namespace

TriangleMesh simplifyForTiles(const TriangleMesh& mesh, std::size_t targetTriangles,
                              SimplifyStats* stats) {
    SimplifyStats local;
    SimplifyStats& s = stats ? *stats : local;
    s = SimplifyStats{};
    s.trianglesBefore = s.trianglesAfter = mesh.triangles.size();
    if (mesh.triangles.size() <= targetTriangles)
        return mesh;

    const Topology before = topologyOf(mesh);
    std::vector<std::uint32_t> indices;
    indices.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles)
        indices.insert(indices.end(), t.begin(), t.end());
    std::vector<std::uint32_t> out(indices.size());

    double target = double(targetTriangles);
    for (int attempt = 1; attempt <= 6 && target < double(mesh.triangles.size());
         ++attempt, target *= 1.5) {
        s.attempts = attempt;
        // target_error is relative to the mesh's extent: 1 means "no bound", the
        // triangle budget alone decides where to stop.
        const std::size_t count =
            meshopt_simplify(out.data(), indices.data(), indices.size(), mesh.positions[0].data(),
                             mesh.positions.size(), sizeof(Eigen::Vector3f),
                             3 * std::size_t(target), 1.0f, meshopt_SimplifyLockBorder, nullptr);
        TriangleMesh result =
            compacted(mesh, std::vector<std::uint32_t>(out.begin(), out.begin() + count));
        if (!result.triangles.empty() && topologyOf(result) == before) {
            s.trianglesAfter = result.triangles.size();
            s.simplified = true;
            return result;
        }
    }
    return mesh;
}

} // namespace morphogen
