#include "geometry/loop_subdivision.h"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <cmath>
#include <memory>
#include <string>

namespace caustica {

namespace {

using namespace OpenSubdiv;

// A position as OpenSubdiv's primvar interpolation wants it.
struct Point {
    float x = 0, y = 0, z = 0;
    void Clear() { x = y = z = 0; }
    void AddWithWeight(const Point &s, float w) {
        x += w * s.x;
        y += w * s.y;
        z += w * s.z;
    }
    Vec3f vec() const { return {x, y, z}; }
};

// A refined mesh larger than this is refused rather than exhausting memory.
constexpr double MaxRefinedTriangles = 64e6;

} // namespace

MeshData loop_subdivide(std::vector<int> indices, const std::vector<Vec3f> &p, int levels,
                        const SourceLocation &loc) {
    if (indices.size() % 3 != 0)
        throw InputError(loc, "loopsubdiv: " + std::to_string(indices.size()) +
                                  " vertex indices are not a multiple of 3");
    if (levels < 0 || levels > 8)
        throw InputError(loc, "loopsubdiv: \"levels\" must lie in [0, 8], not " + std::to_string(levels));
    for (int i : indices)
        if (i < 0 || size_t(i) >= p.size())
            throw InputError(loc, "loopsubdiv: vertex index " + std::to_string(i) +
                                      " is out of range (there are " + std::to_string(p.size()) +
                                      " vertices)");
    for (const Vec3f &v : p)
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            throw InputError(loc, "loopsubdiv: a vertex position is not finite");
    std::vector<int> kept;
    kept.reserve(indices.size());
    size_t dropped = 0;
    for (size_t f = 0; f < indices.size(); f += 3) {
        int a = indices[f], b = indices[f + 1], c = indices[f + 2];
        if (a == b || b == c || a == c) {
            ++dropped;
            continue;
        }
        kept.insert(kept.end(), {a, b, c});
    }
    if (dropped > 0)
        warning(loc, "loopsubdiv: dropped " + std::to_string(dropped) +
                         " triangles that repeat a vertex");
    if (kept.empty()) throw InputError(loc, "loopsubdiv: no triangles");
    if (double(kept.size() / 3) * std::pow(4.0, levels) > MaxRefinedTriangles)
        throw InputError(loc, "loopsubdiv: " + std::to_string(levels) + " levels would make more than " +
                                  std::to_string(int64_t(MaxRefinedTriangles)) + " triangles");

    const int faces = int(kept.size() / 3);
    std::vector<int> corners_per_face(size_t(faces), 3);
    Far::TopologyDescriptor topology;
    topology.numVertices = int(p.size());
    topology.numFaces = faces;
    topology.numVertsPerFace = corners_per_face.data();
    topology.vertIndicesPerFace = kept.data();
    Sdc::Options rules;
    rules.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    std::unique_ptr<Far::TopologyRefiner> refiner(
        Factory::Create(topology, Factory::Options(Sdc::SCHEME_LOOP, rules)));
    if (!refiner) throw InputError(loc, "loopsubdiv: OpenSubdiv cannot build the mesh's topology");
    Far::TopologyRefiner::UniformOptions uniform(levels);
    uniform.fullTopologyInLastLevel = true; // the limit evaluation needs it
    refiner->RefineUniform(uniform);

    // Interpolate the positions level by level, then move the last level's to the limit.
    std::vector<Point> level_points(p.size());
    for (size_t i = 0; i < p.size(); ++i) level_points[i] = {p[i].x, p[i].y, p[i].z};
    Far::PrimvarRefiner primvars(*refiner);
    for (int level = 1; level <= levels; ++level) {
        std::vector<Point> finer(size_t(refiner->GetLevel(level).GetNumVertices()));
        primvars.Interpolate(level, level_points, finer);
        level_points = std::move(finer);
    }
    std::vector<Point> limit(level_points.size()), du(level_points.size()), dv(level_points.size());
    primvars.Limit(level_points, limit, du, dv);

    MeshData mesh;
    mesh.p.reserve(limit.size());
    mesh.n.reserve(limit.size());
    bool normals = true;
    for (size_t i = 0; i < limit.size(); ++i) {
        mesh.p.push_back(limit[i].vec());
        Vec3f n = cross(du[i].vec(), dv[i].vec());
        float len = length(n);
        normals = normals && len > 0 && std::isfinite(len);
        mesh.n.push_back(len > 0 ? n / len : n);
    }
    // A degenerate limit tangent (a collapsed region) leaves the mesh without shading normals
    // rather than with a zero one.
    if (!normals) mesh.n.clear();
    const Far::TopologyLevel &last = refiner->GetLevel(levels);
    mesh.indices.reserve(size_t(last.GetNumFaces()) * 3);
    for (int f = 0; f < last.GetNumFaces(); ++f) {
        Far::ConstIndexArray v = last.GetFaceVertices(f);
        for (int k = 0; k < v.size(); ++k) mesh.indices.push_back(v[k]);
    }
    return mesh;
}

} // namespace caustica
