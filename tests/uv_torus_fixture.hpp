#pragma once

#include "core/mesh/mesh_io.hpp"
#include "core/surface/surface_tiles.hpp"

namespace morphogen::test {

// The exporter's torus (UV seams copied) with its UVs squeezed into
// [0.1, 0.6] x [0.2, 0.7], one island with empty texture round it, and the
// surface tiles of its welded mesh (600 tiles of 4 x 4): a model whose own
// UV layout and tiled surface are both known, for the bakes' tests.
struct UvTorus {
    UvMesh mesh;
    SurfaceTiles tiles;
};
UvTorus uvTorus();

} // namespace morphogen::test
