#pragma once

#include <Eigen/Core>

namespace morphogen {

// Where the three quads of a triangle (a, b, c) meet, as barycentric
// coordinates (sum 1): the quads are (a, m_ab, p, m_ca), (b, m_bc, p, m_ab),
// (c, m_ca, p, m_bc) with m the edge midpoints (fixed: both triangles of an
// edge must agree on it). The centroid is right for a well-shaped triangle
// and is what this returns for an equilateral one, but in an obtuse or skinny
// triangle it lies close to the long edge's midpoint: two of the quads get a
// side a fraction of the others, their texels near it are thin slivers, and
// since a texel's weight sum grows as 1 / (its shorter side)^2 they set the
// explicit step's limit for the whole surface (issue #11). So p is the point
// of the medial triangle (every quad convex) that makes the largest estimated
// weight sum of the three quads' texels smallest: the texels of a bilinear
// n x n grid on each planar quad, each costing 2 (1 / |Ju|^2 + 1 / |Jv|^2)
// (the 5-point sum, surface_weights.hpp) over the sine of the angle between
// Ju and Jv (the cross term's growth on a sheared texel, and the anisotropy
// left where it is capped). A grid search refined twice; deterministic.
Eigen::Vector3f quadSplitPoint(const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                               const Eigen::Vector3f& c);

// The cost quadSplitPoint minimises, for the split point with barycentric
// coordinates `bary` (in units of 1 / length^2 of the triangle's own units);
// infinity if a quad folds.
double quadSplitCost(const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c,
                     const Eigen::Vector3f& bary);

} // namespace morphogen
