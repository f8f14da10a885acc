#include "core/mesh/mesh_report.hpp"

#include <cstdarg>
#include <cstdio>

namespace morphogen {

namespace {

constexpr std::size_t kComponentLines = 20;

std::string format(const char* fmt, ...) {
    char buffer[512];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(buffer, sizeof buffer, fmt, args);
    va_end(args);
    return buffer;
}

std::string point(const Eigen::Vector3f& p) {
    return format("(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
}

std::string plural(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string topology(const MeshComponent& c) {
    if (!c.manifold)
        return "genus undefined (not manifold)";
    if (!c.orientable)
        return format("non-orientable, Euler characteristic %ld", c.eulerCharacteristic);
    return format("genus %d", c.genus);
}

nlohmann::json vec(const Eigen::Vector3f& p) {
    return {p.x(), p.y(), p.z()};
}

nlohmann::json defect(const MeshDefect& d) {
    nlohmann::json j = {{"count", d.count}};
    if (d.count > 0)
        j["first"] = vec(d.first);
    return j;
}

struct Problem {
    const char* name;
    const char* key;
    const MeshDefect* defect;
    const char* consequence;
};

std::vector<Problem> problemsOf(const MeshReport& r) {
    return {
        {"non-manifold edges (more than two triangles)", "non_manifold_edges", &r.nonManifoldEdges,
         "refused"},
        {"non-manifold vertices (several fans of triangles)", "non_manifold_vertices",
         &r.nonManifoldVertices, "refused"},
        {"zero-area triangles (height below 1e-6 of the longest edge)", "zero_area_triangles",
         &r.zeroAreaTriangles, "kept"},
        {"duplicate triangles (same three vertices)", "duplicate_triangles", &r.duplicateTriangles,
         "kept"},
        {"triangles wound against their neighbours", "inconsistent_winding", &r.inconsistentWinding,
         "kept"},
        {"open-boundary vertices within 1e-5 of the box diagonal of another (an unwelded seam?)",
         "near_seam_vertices", &r.nearSeamVertices, "kept"},
    };
}

} // namespace

std::string repairSummary(const RepairStats& m) {
    std::string done;
    const auto add = [&](std::size_t n, const char* one, const char* many) {
        if (n > 0)
            done += (done.empty() ? "" : ", ") + plural(n, one, many);
    };
    add(m.mergedVertices, "open-boundary vertex merged by distance",
        "open-boundary vertices merged by distance");
    add(m.collapsedTriangles, "triangle collapsed by the merge removed",
        "triangles collapsed by the merge removed");
    add(m.duplicateTriangles, "duplicate triangle removed", "duplicate triangles removed");
    if (m.specks > 0)
        done += (done.empty() ? "" : ", ") + plural(m.specks, "speck", "specks") + " (" +
                plural(m.speckTriangles, "triangle", "triangles") + ") removed";
    add(m.splitVertices, "vertex copied to cut sheets apart where they met",
        "vertices copied to cut sheets apart where they met");
    return done.empty() ? "nothing" : done;
}

std::string meshReportText(const LoadedMesh& loaded, const MeshReport& r) {
    const MeshFileInfo& f = loaded.file;
    const WeldStats& w = loaded.weld;
    std::string out;
    out += "file: " + f.path + " (" + f.format + ")\n";
    out += "read: " + plural(f.vertices, "vertex", "vertices") + ", " +
           plural(f.triangles, "triangle", "triangles") + " in " + plural(f.parts, "part", "parts");
    if (f.skippedParts > 0)
        out += " (" + plural(f.skippedParts, "part", "parts") + " of points or lines skipped)";
    out += "\n";
    out += format("welded: %zu -> %zu vertices (equal positions merged)", w.verticesBefore,
                  w.verticesAfter);
    if (w.unreferencedDropped > 0)
        out +=
            ", " + plural(w.unreferencedDropped, "unused vertex", "unused vertices") + " dropped";
    if (w.collapsedRemoved > 0)
        out += ", " + plural(w.collapsedRemoved, "collapsed triangle", "collapsed triangles") +
               " removed";
    if (loaded.reoriented > 0)
        out += ", " + plural(loaded.reoriented, "triangle", "triangles") +
               " turned to agree with their neighbours";
    out += "\n";
    const WrapStats& wrap = loaded.wrap;
    if (wrap.wrapped)
        out += "wrapped: " + plural(wrap.componentsBefore, "piece", "pieces") +
               " replaced by their alpha wrap (CGAL), a closed surface of " +
               plural(wrap.triangles, "triangle", "triangles") +
               format(" %.3g outside the model, gaps under %.3g closed over\n", wrap.offset,
                      wrap.alpha);
    if (!wrap.failed.empty())
        out += "wrap: not made (" + wrap.failed + "); the pieces are kept\n";
    const RepairStats& m = loaded.repair;
    if (m.nonManifoldEdges > 0 || m.nonManifoldVertices > 0)
        out += "found: " + plural(m.nonManifoldEdges, "non-manifold edge", "non-manifold edges") +
               " (more than two triangles), " +
               plural(m.nonManifoldVertices, "non-manifold vertex", "non-manifold vertices") +
               " (several fans of triangles)\n";
    if (m.changed())
        out += "repaired: " + repairSummary(m) + "\n";
    out += "surface (what tiles are built on): " + plural(r.vertices, "vertex", "vertices") + ", " +
           plural(r.edges, "edge", "edges") + ", " + plural(r.triangles, "triangle", "triangles") +
           "\n";
    out += "bounding box: " + point(r.bounds.min) + " to " + point(r.bounds.max) +
           format(", diagonal %.6g\n", r.bounds.diagonal());
    out += format("surface area: %.6g\n", r.area);
    if (r.boundaryEdges == 0)
        out += "boundary: none (closed)\n";
    else
        out += "boundary: " + plural(r.boundaryLoops, "loop", "loops") + " of " +
               plural(r.boundaryEdges, "edge", "edges") +
               " (allowed: patterns stop at an open edge)\n";
    out += "components: " + std::to_string(r.components.size()) + "\n";
    for (std::size_t i = 0; i < r.components.size() && i < kComponentLines; ++i) {
        const MeshComponent& c = r.components[i];
        out += format("  %zu: ", i + 1) + topology(c) + ", " +
               plural(c.boundaryLoops, "boundary loop", "boundary loops") + ", " +
               plural(c.vertices, "vertex", "vertices") + ", " +
               plural(c.triangles, "triangle", "triangles") + format(", area %.6g\n", c.area);
    }
    if (r.components.size() > kComponentLines)
        out +=
            format("  ... and %zu more (all in --json)\n", r.components.size() - kComponentLines);
    std::string problems;
    for (const Problem& p : problemsOf(r))
        if (p.defect->count > 0)
            problems += format("  %s: %zu, the first at ", p.name, p.defect->count) +
                        point(p.defect->first) + " (" + p.consequence + ")\n";
    out += problems.empty() ? "problems: none\n" : "problems:\n" + problems;
    out += r.usableForTiles() ? "usable for surface tiles: yes\n"
                              : "usable for surface tiles: no (" + whyNotUsableForTiles(r) + ")\n";
    return out;
}

nlohmann::json meshReportJson(const LoadedMesh& loaded, const MeshReport& r) {
    const MeshFileInfo& f = loaded.file;
    nlohmann::json components = nlohmann::json::array();
    for (const MeshComponent& c : r.components) {
        components.push_back(
            {{"vertices", c.vertices},
             {"edges", c.edges},
             {"triangles", c.triangles},
             {"boundary_loops", c.boundaryLoops},
             {"euler_characteristic", c.eulerCharacteristic},
             {"manifold", c.manifold},
             {"orientable", c.orientable},
             {"genus", c.genus >= 0 ? nlohmann::json(c.genus) : nullptr},
             {"area", c.area},
             {"bounds", {{"min", vec(c.bounds.min)}, {"max", vec(c.bounds.max)}}}});
    }
    nlohmann::json problems = nlohmann::json::object();
    for (const Problem& p : problemsOf(r))
        problems[p.key] = defect(*p.defect);
    return {
        {"file", f.path},
        {"format", f.format},
        {"read",
         {{"vertices", f.vertices},
          {"triangles", f.triangles},
          {"parts", f.parts},
          {"skipped_parts", f.skippedParts}}},
        {"weld",
         {{"vertices_before", loaded.weld.verticesBefore},
          {"vertices_after", loaded.weld.verticesAfter},
          {"unused_vertices_dropped", loaded.weld.unreferencedDropped},
          {"collapsed_triangles_removed", loaded.weld.collapsedRemoved},
          {"triangles_reoriented", loaded.reoriented}}},
        {"wrap",
         {{"wrapped", loaded.wrap.wrapped},
          {"pieces_before", loaded.wrap.componentsBefore},
          {"triangles", loaded.wrap.triangles},
          {"alpha", loaded.wrap.alpha},
          {"offset", loaded.wrap.offset},
          {"failed", loaded.wrap.failed}}},
        {"repair",
         {{"non_manifold_edges_found", loaded.repair.nonManifoldEdges},
          {"non_manifold_vertices_found", loaded.repair.nonManifoldVertices},
          {"vertices_merged_by_distance", loaded.repair.mergedVertices},
          {"collapsed_triangles_removed", loaded.repair.collapsedTriangles},
          {"duplicate_triangles_removed", loaded.repair.duplicateTriangles},
          {"specks_removed", loaded.repair.specks},
          {"speck_triangles_removed", loaded.repair.speckTriangles},
          {"vertices_split", loaded.repair.splitVertices}}},
        {"vertices", r.vertices},
        {"edges", r.edges},
        {"triangles", r.triangles},
        {"bounds",
         {{"min", vec(r.bounds.min)},
          {"max", vec(r.bounds.max)},
          {"diagonal", r.bounds.diagonal()}}},
        {"area", r.area},
        {"boundary", {{"edges", r.boundaryEdges}, {"loops", r.boundaryLoops}}},
        {"components", components},
        {"problems", problems},
        {"usable", r.usableForTiles()},
    };
}

} // namespace morphogen
