#include "uv_torus_fixture.hpp"

#include "core/mesh/mesh_samples.hpp"
#include "core/surface/tile_builder.hpp"

namespace morphogen::test {

UvTorus uvTorus() {
    UvTorus torus;
    MeshAttributes attributes;
    const TriangleMesh seams = torusWithSeams(24, attributes);
    torus.mesh.positions = seams.positions;
    torus.mesh.triangles = seams.triangles;
    for (const Eigen::Vector2f& uv : attributes.texcoords)
        torus.mesh.uvs.emplace_back(0.1f + 0.5f * uv.x(), 0.2f + 0.5f * uv.y());
    TriangleMesh welded = seams;
    weldVertices(welded);
    TileOptions options;
    options.tileSize = 4;
    options.tiles = 600;
    torus.tiles = buildSurfaceTiles(welded, options);
    return torus;
}

} // namespace morphogen::test
